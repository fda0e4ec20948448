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

double Approach::at(double timeMs) const {
    return asymptote - (asymptote - level) * std::exp(-(timeMs - crossingMs) / tauMs);
}

double Approach::slopePerMs(double timeMs) const {
    return (asymptote - level) / tauMs * std::exp(-(timeMs - crossingMs) / tauMs);
}

namespace {

// A start for the fit: the deficit below the asymptote falls exponentially, so its logarithm is a
// line in time, fitted with each reading weighted by its deficit squared (a reading's error in
// the logarithm is its error in kelvin over the deficit). Readings within a degree of the
// asymptote say nothing about the slope in the logarithm.
std::optional<Approach> logDeficitStart(const std::vector<Reading> &readings, double asymptote,
                                        double level) {
    double sw = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    int used = 0;
    const double origin = double(readings.front().timeMs);
    for (const Reading &r : readings) {
        const double deficit = asymptote - r.value;
        if (deficit < 1)
            continue;
        const double w = deficit * deficit;
        const double x = (double(r.timeMs) - origin) / 1000;
        const double y = std::log(deficit);
        sw += w;
        sx += w * x;
        sy += w * y;
        sxx += w * x * x;
        sxy += w * x * y;
        ++used;
    }
    const double det = sw * sxx - sx * sx;
    if (used < 3 || std::abs(det) < 1e-12)
        return std::nullopt;
    const double slope = (sw * sxy - sx * sy) / det; // per second, negative on a return
    const double intercept = (sy - slope * sx) / sw;
    if (slope >= 0)
        return std::nullopt;
    Approach a;
    a.asymptote = asymptote;
    a.level = level;
    a.tauMs = -1000 / slope;
    a.crossingMs = origin + (std::log(asymptote - level) - intercept) / slope * 1000;
    return a;
}

} // namespace

std::optional<Approach> fitApproach(const std::vector<Reading> &readings, double asymptote,
                                    double level) {
    if (readings.size() < 3 || asymptote <= level)
        return std::nullopt;
    std::optional<Approach> a = logDeficitStart(readings, asymptote, level);
    if (!a)
        return std::nullopt;
    // Gauss-Newton on the readings themselves, in (crossing, rate): the start above weighs the
    // readings by a logarithm's error, not by their own.
    const double span = double(readings.back().timeMs - readings.front().timeMs);
    std::array<std::array<double, 2>, 2> normal{};
    for (int iteration = 0; iteration < 30; ++iteration) {
        normal = {};
        std::array<double, 2> gradient{};
        const double rate = 1000 / a->tauMs; // per second
        for (const Reading &r : readings) {
            const double x = (double(r.timeMs) - a->crossingMs) / 1000;
            const double deficit = (asymptote - level) * std::exp(-rate * x);
            const double e = r.value - (asymptote - deficit);
            // ∂y/∂crossing (per ms) and ∂y/∂rate.
            const std::array<double, 2> j{-deficit * rate / 1000, deficit * x};
            for (size_t p = 0; p < 2; ++p) {
                gradient[p] += j[p] * e;
                for (size_t q = 0; q < 2; ++q)
                    normal[p][q] += j[p] * j[q];
            }
        }
        const double det = normal[0][0] * normal[1][1] - normal[0][1] * normal[1][0];
        if (std::abs(det) < 1e-18)
            return std::nullopt;
        const double dCrossing = (gradient[0] * normal[1][1] - gradient[1] * normal[0][1]) / det;
        const double dRate = (normal[0][0] * gradient[1] - normal[1][0] * gradient[0]) / det;
        const double newRate = rate + dRate;
        if (!std::isfinite(dCrossing) || !std::isfinite(newRate) || newRate <= 0)
            return std::nullopt;
        a->crossingMs += dCrossing;
        a->tauMs = 1000 / newRate;
        if (std::abs(dCrossing) < 0.01 && std::abs(dRate) < 1e-6 * newRate)
            break;
    }
    // A fit that settled far outside its readings followed nothing they show.
    if (a->crossingMs < double(readings.front().timeMs) - span ||
        a->crossingMs > double(readings.back().timeMs) + span)
        return std::nullopt;
    double squares = 0;
    for (const Reading &r : readings) {
        const double e = r.value - a->at(double(r.timeMs));
        squares += e * e;
    }
    a->count = int(readings.size());
    const int freedom = a->count - 2;
    a->sigma =
        std::max(kRoundingSigmaK, freedom > 0 ? std::sqrt(squares / freedom) : kRoundingSigmaK);
    const double det = normal[0][0] * normal[1][1] - normal[0][1] * normal[1][0];
    a->crossingSigmaMs = a->sigma * std::sqrt(std::max(0.0, normal[1][1] / det));
    return a;
}

} // namespace tipscope::model
