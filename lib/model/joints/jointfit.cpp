#include "model/joints/jointfit.h"

#include <array>
#include <cmath>

namespace tipscope::model {

double Polynomial::at(double timeMs) const {
    const double x = (timeMs - double(originMs)) / 1000;
    return c0 + c1 * x + c2 * x * x;
}

double Polynomial::slopePerMs(double timeMs) const {
    const double x = (timeMs - double(originMs)) / 1000;
    return (c1 + 2 * c2 * x) / 1000;
}

namespace {

// Solves the n×n system (n ≤ 3) by Gaussian elimination with partial pivoting; false when it is
// singular (the readings do not span time).
bool solve(std::array<std::array<double, 4>, 3> &m, int n, std::array<double, 3> &out) {
    for (int col = 0; col < n; ++col) {
        int pivot = col;
        for (int row = col + 1; row < n; ++row)
            if (std::abs(m[row][col]) > std::abs(m[pivot][col]))
                pivot = row;
        if (std::abs(m[pivot][col]) < 1e-12)
            return false;
        std::swap(m[col], m[pivot]);
        for (int row = col + 1; row < n; ++row) {
            const double f = m[row][col] / m[col][col];
            for (int k = col; k <= n; ++k)
                m[row][k] -= f * m[col][k];
        }
    }
    for (int row = n - 1; row >= 0; --row) {
        double sum = m[row][n];
        for (int k = row + 1; k < n; ++k)
            sum -= m[row][k] * out[k];
        out[row] = sum / m[row][row];
    }
    return true;
}

} // namespace

std::optional<Polynomial> fitPolynomial(const std::vector<Reading> &readings, int order) {
    const int n = order + 1;
    if (order < 1 || order > 2 || int(readings.size()) < n)
        return std::nullopt;
    Polynomial p;
    qint64 sumT = 0;
    for (const Reading &r : readings)
        sumT += r.timeMs;
    p.originMs = sumT / qint64(readings.size());
    // The normal equations: Σ xʲ⁺ᵏ · c = Σ xʲ · y.
    std::array<double, 5> powers{};
    std::array<double, 3> moments{};
    for (const Reading &r : readings) {
        const double x = double(r.timeMs - p.originMs) / 1000;
        double xp = 1;
        for (int k = 0; k <= 2 * order; ++k) {
            powers[size_t(k)] += xp;
            if (k <= order)
                moments[size_t(k)] += xp * r.value;
            xp *= x;
        }
    }
    std::array<std::array<double, 4>, 3> m{};
    for (int row = 0; row < n; ++row) {
        for (int col = 0; col < n; ++col)
            m[size_t(row)][size_t(col)] = powers[size_t(row + col)];
        m[size_t(row)][size_t(n)] = moments[size_t(row)];
    }
    std::array<double, 3> c{};
    if (!solve(m, n, c))
        return std::nullopt;
    p.c0 = c[0];
    p.c1 = c[1];
    p.c2 = order == 2 ? c[2] : 0;
    p.count = int(readings.size());
    double squares = 0;
    for (const Reading &r : readings) {
        const double e = r.value - p.at(double(r.timeMs));
        squares += e * e;
    }
    const int freedom = p.count - n;
    p.sigma =
        std::max(kRoundingSigmaK, freedom > 0 ? std::sqrt(squares / freedom) : kRoundingSigmaK);
    return p;
}

std::optional<double> crossingTime(const Polynomial &fit, double level, double fromMs, double toMs,
                                   double nearMs) {
    // In seconds from the fit's origin: c2·x² + c1·x + (c0 − level) = 0.
    const double origin = double(fit.originMs);
    const double c = fit.c0 - level;
    std::vector<double> roots;
    if (std::abs(fit.c2) < 1e-9) {
        if (std::abs(fit.c1) > 1e-12)
            roots.push_back(-c / fit.c1);
    } else {
        const double disc = fit.c1 * fit.c1 - 4 * fit.c2 * c;
        if (disc >= 0) {
            const double s = std::sqrt(disc);
            roots.push_back((-fit.c1 + s) / (2 * fit.c2));
            roots.push_back((-fit.c1 - s) / (2 * fit.c2));
        }
    }
    std::optional<double> best;
    for (const double x : roots) {
        const double t = origin + x * 1000;
        if (t < fromMs || t > toMs)
            continue;
        if (!best || std::abs(t - nearMs) < std::abs(*best - nearMs))
            best = t;
    }
    return best;
}

double crossingUncertaintyMs(const Polynomial &fit, double timeMs) {
    const double slope = std::abs(fit.slopePerMs(timeMs));
    if (slope < 1e-9)
        return 1e9;
    return std::max(1.0, fit.sigma / slope / std::sqrt(std::max(1, fit.count - 1)) * 2);
}

} // namespace tipscope::model
