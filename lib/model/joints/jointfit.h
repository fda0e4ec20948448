// Local least-squares fits of a tip curve, for the joint detector's estimates.
//
// The station reports whole degrees at irregular instants, so no single reading says when the tip
// crossed a level or how low it went: a slow recovery stays at one reading for half a second, and
// a reading can sit a degree off either way. A low-order polynomial fitted through the readings
// around the event uses all of them: where it crosses the level, or where it turns, is finer than
// both the spacing and the resolution, and the scatter of the readings about it says how sure that
// is. Plain computation on values; no Qt objects.
#pragma once

#include <QtGlobal>
#include <optional>
#include <vector>

namespace tipscope::model {

struct Reading {
    qint64 timeMs = 0;
    double value = 0;
};

// y(t) = c0 + c1·x + c2·x², x = (t − originMs) / 1000 (seconds, to keep the sums well scaled).
struct Polynomial {
    double c0 = 0, c1 = 0, c2 = 0;
    qint64 originMs = 0;
    // The readings' scatter about the fit (K), never below what whole-degree rounding alone leaves.
    double sigma = 0;
    int count = 0;

    [[nodiscard]] double at(double timeMs) const;
    [[nodiscard]] double slopePerMs(double timeMs) const;
};

// The scatter whole-degree readings have about any smooth curve: a rounding error is uniform over
// a degree, so its standard deviation is 1/√12 K.
inline constexpr double kRoundingSigmaK = 0.2887;

// A fit of the given order (1: a line, 2: a parabola) through the readings; none when there are
// too few of them (order + 1) or they do not span time.
[[nodiscard]] std::optional<Polynomial> fitPolynomial(const std::vector<Reading> &readings,
                                                      int order);

// When the fit crosses `level` within [fromMs, toMs]; the crossing nearest `nearMs` if it crosses
// twice; none if it does not cross there.
[[nodiscard]] std::optional<double> crossingTime(const Polynomial &fit, double level, double fromMs,
                                                 double toMs, double nearMs);

// How far a crossing time found by the fit may be off: the readings' scatter over the slope there,
// shrunk by how many readings carried it (and never below a millisecond).
[[nodiscard]] double crossingUncertaintyMs(const Polynomial &fit, double timeMs);

// A first-order return towards `asymptote` that passes `level` at crossingMs:
// y(t) = asymptote − (asymptote − level)·e^(−(t − crossingMs)/τ). A heater bringing its tip back
// to the setpoint under its controller is close to first order, so a deep return curves the way
// this does all the way up, where a parabola through the same readings bends too early or too late.
struct Approach {
    double asymptote = 0;
    double level = 0;
    double crossingMs = 0;
    double tauMs = 0;
    // The readings' scatter about the fit (K, never below rounding's) and how far crossingMs may
    // be off for that scatter (one standard error).
    double sigma = 0;
    double crossingSigmaMs = 0;
    int count = 0;

    [[nodiscard]] double at(double timeMs) const;
    [[nodiscard]] double slopePerMs(double timeMs) const;
};

// The first-order return through the readings (least squares on the readings themselves); none
// when fewer than three readings are below the asymptote, they do not climb towards it, or the
// fit does not settle.
[[nodiscard]] std::optional<Approach> fitApproach(const std::vector<Reading> &readings,
                                                  double asymptote, double level);

} // namespace tipscope::model
