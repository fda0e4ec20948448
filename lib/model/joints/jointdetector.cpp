#include "model/joints/jointdetector.h"

#include "model/joints/jointfit.h"

#include <algorithm>
#include <cmath>

namespace tipscope::model {

namespace {
// The station reports whole degrees: a reading of setpoint − band is a tip anywhere above
// setpoint − band − 0.5, so that is where the continuous tip crosses the band's edge, and where
// both crossings are placed (see docs/protocol-notes.md).
constexpr double kWholeDegreeHalfStep = 0.5;
// The readings of the climb a recovery is fitted through: this many before the first reading back
// in the band, and after it.
constexpr int kClimbReadingsBefore = 5;
constexpr int kClimbReadingsAfter = 1;
// A straight climb is fitted from where it has come this share of the way from its lowest
// reading to the band's edge (below, the bottom rounds off), through at least this many readings.
constexpr double kStraightFromShare = 0.2;
constexpr size_t kStraightMinReadings = 6;
// A local fit whose readings scatter more than this about it is following a wobble, not rounding
// (whole degrees alone scatter 0.29 K).
constexpr double kWobbleSigmaK = 0.5;
// How many of the settled tip's readings say how much it wobbles: two to three seconds of them.
constexpr size_t kRestingReadings = 24;

// The last two readings before a joint may already be on its fall, within the band still: they
// are left out.
double restingSigma(const std::deque<int> &tips) {
    const size_t n = tips.size() > 2 ? tips.size() - 2 : 0;
    if (n < 4)
        return kRoundingSigmaK;
    double mean = 0;
    for (size_t i = 0; i < n; ++i)
        mean += tips[i];
    mean /= double(n);
    double sum = 0;
    for (size_t i = 0; i < n; ++i)
        sum += (tips[i] - mean) * (tips[i] - mean);
    return std::max(kRoundingSigmaK, std::sqrt(sum / double(n - 1)));
}
// The wide window around a return: this many spacings of the readings around it either side, or
// this share of the climb from the lowest point, whichever is longer.
constexpr double kWideSpacings = 2.5;
constexpr double kWideShare = 0.3;

// When the straight line from (t0, v0) to (t1, v1) crosses `level`.
double straightCrossing(qint64 t0, double v0, qint64 t1, double v1, double level) {
    if (v1 == v0)
        return double(t1);
    const double f = qBound(0.0, (level - v0) / (v1 - v0), 1.0);
    return double(t0) + f * double(t1 - t0);
}

Reading readingOf(const PortReading &r) {
    return {r.timeMs, double(*r.tip)};
}
} // namespace

JointDetector::JointDetector(DeviceIdentity device, int port, JointLimits limits)
    : m_device(std::move(device))
    , m_port(port)
    , m_limits(limits) {}

double JointDetector::bandEdge() const {
    return double(m_joint.setpoint) - m_limits.bandK - kWholeDegreeHalfStep;
}

bool JointDetector::inBand(const PortReading &r) const {
    return *r.tip >= r.setpoint - m_limits.bandK;
}

bool JointDetector::sameConditions(const PortReading &reading) const {
    return m_last && reading.working && m_last->working && reading.setpoint == m_last->setpoint &&
           reading.tool == m_last->tool;
}

std::optional<JointRecord> JointDetector::add(const PortReading &reading) {
    if (!reading.tip)
        return gap(reading.timeMs);
    std::optional<JointRecord> ended;
    if (!sameConditions(reading)) {
        // Stand, sleep, heater off, another tool or setpoint: not a joint, and not one to finish.
        if (m_state == State::InJoint)
            ended = finish(m_tailUntilMs ? End::Recovered : End::Broken, m_last->timeMs);
        m_state = State::Waiting;
        m_justRecovered = false;
        m_restingTips.clear(); // another setpoint or tool wobbles about another mean
    }
    const bool withinBand = std::abs(*reading.tip - reading.setpoint) <= m_limits.bandK;
    if (m_state != State::InJoint && withinBand) {
        m_restingTips.push_back(*reading.tip);
        if (m_restingTips.size() > kRestingReadings)
            m_restingTips.pop_front();
    } else if (m_state == State::Waiting) {
        m_restingTips.clear();
    }
    switch (m_state) {
    case State::Waiting:
        if (withinBand && reading.working) {
            m_state = State::Settled;
            m_settledSinceMs = reading.timeMs;
            m_justRecovered = false;
        }
        break;
    case State::Settled:
        if (!inBand(reading)) {
            const bool settled = m_justRecovered || reading.timeMs - m_settledSinceMs >= kSettleMs;
            if (settled && m_last && m_last->tip)
                startJoint(*m_last, reading);
            else
                m_state = State::Waiting; // left the band before it had settled
        } else if (!withinBand && !m_justRecovered) {
            // Above the band while still settling (a heat-up ringing): settled only once it has
            // stayed within the band for kSettleMs.
            m_settledSinceMs = reading.timeMs;
        }
        // Above the band after a joint, at the same setpoint and tool, is the heater overshooting
        // its return: the next dip is a joint at once (reading the tip often catches more of
        // these overshoots; they must not cost the joint that follows).
        break;
    case State::InJoint:
        if (m_tailUntilMs) {
            // Back for good; the readings after the return are gathered for its fit. One below
            // the band now is the next joint, which begins at once.
            if (!inBand(reading)) {
                ended = finish(End::Recovered, m_last->timeMs);
                settleAfterRecovery(m_last->timeMs);
                startJoint(*m_last, reading);
                break;
            }
            accumulate(reading);
            if (reading.timeMs >= *m_tailUntilMs) {
                ended = finish(End::Recovered, reading.timeMs);
                settleAfterRecovery(reading.timeMs);
            }
            break;
        }
        accumulate(reading);
        m_backInBand = inBand(reading) ? m_backInBand + 1 : 0;
        if (m_backInBand >= kConfirmReadings) {
            m_tailUntilMs = tailUntil();
            if (reading.timeMs >= *m_tailUntilMs) {
                ended = finish(End::Recovered, reading.timeMs);
                settleAfterRecovery(reading.timeMs);
            }
        } else if (reading.timeMs - m_joint.startMs > kGiveUpMs) {
            ended = finish(End::GaveUp, reading.timeMs);
            m_state = State::Waiting;
        }
        break;
    }
    m_last = reading;
    return ended;
}

std::optional<JointRecord> JointDetector::gap(qint64 timeMs) {
    std::optional<JointRecord> ended;
    if (m_state == State::InJoint)
        ended = finish(m_tailUntilMs ? End::Recovered : End::Broken,
                       qMax(timeMs, m_last ? m_last->timeMs : timeMs));
    m_state = State::Waiting;
    m_justRecovered = false;
    m_restingTips.clear();
    m_last.reset();
    return ended;
}

void JointDetector::startJoint(const PortReading &previous, const PortReading &reading) {
    m_state = State::InJoint;
    m_joint = JointRecord{};
    m_joint.device = m_device;
    m_joint.port = m_port;
    m_joint.tool = reading.tool;
    m_joint.setpoint = reading.setpoint;
    m_joint.lowestTip = *previous.tip;
    m_joint.powerPeak = int(std::lround(previous.powerPct));
    m_readings = {previous, reading};
    m_restingPowerPct = previous.powerPct;
    m_restingSigmaK = restingSigma(m_restingTips);
    m_backInBand = 0;
    m_tailUntilMs.reset();
    estimateStart(m_joint); // the give-up clock runs from it; refined at the end
    m_readings.pop_back();
    accumulate(reading);
}

// The readings, the power peak, and the power-time integral by the trapezoid rule.
void JointDetector::accumulate(const PortReading &reading) {
    m_readings.push_back(reading);
    m_joint.lowestTip = qMin(m_joint.lowestTip, double(*reading.tip));
    m_joint.powerPeak = qMax(m_joint.powerPeak, int(std::lround(reading.powerPct)));
    if (m_last) {
        const qint64 from = qMax(m_last->timeMs, m_joint.startMs);
        if (reading.timeMs > from)
            m_joint.powerIntegral +=
                (m_last->powerPct + reading.powerPct) / 2 * double(reading.timeMs - from) / 1000;
    }
}

// The edge's crossing on the way down: a line through the first readings of the fall (while it
// is still steep: before the lowest), extrapolated to the edge, within the interval between the
// last reading in the band and the first below it. With fewer than three readings of the fall, no
// line can show whether the fall was straight (the second may already be past the lowest point):
// the crossing is then no earlier than the middle of that interval, where a departure at an
// unknown moment is expected (a settled tip is flat, and a joint draws heat at once).
//
// How far the truth may lie from it (startUncertaintyMs) reaches the far end of what the readings
// allow, not a fit's own scatter: the crossing lies before the first reading below the band, and
// after where the chord through the first two readings of the fall, traced back, meets the edge
// (a joint draws heat at once, so its fall slows as it goes and lies below every such chord; the
// readings' whole degree and wobble are allowed against it). A fit's scatter said too little: a
// line through a slowing fall crosses early, and the interval held the simulator's truth in 62 to
// 84 % of its joints.
void JointDetector::estimateStart(JointRecord &joint) const {
    const PortReading &before = m_readings.at(0);
    const PortReading &first = m_readings.at(1);
    const double lo = double(before.timeMs);
    const double hi = double(first.timeMs);
    const double edge = bandEdge();
    const double straight =
        straightCrossing(before.timeMs, *before.tip, first.timeMs, *first.tip, edge);
    double start = qMax(straight, (lo + hi) / 2);
    std::vector<Reading> fall;
    for (size_t i = 1; i < m_readings.size() && fall.size() < 4; ++i) {
        const PortReading &r = m_readings.at(i);
        if (!fall.empty() && *r.tip >= fall.back().value)
            break; // the lowest is behind
        fall.push_back(readingOf(r));
    }
    if (fall.size() >= 3) {
        if (const auto line = fitPolynomial(fall, 1)) {
            if (const auto t = crossingTime(*line, edge, lo - (hi - lo), hi, hi))
                start = *t;
        }
    }
    double earliest = lo;
    if (fall.size() >= 2) {
        const double reach = kWholeDegreeHalfStep + wobbleReachK();
        const double deeper = fall[0].value - reach;
        const double drop = deeper - (fall[1].value + reach);
        if (drop > 0) {
            const double slope = drop / double(fall[1].timeMs - fall[0].timeMs);
            earliest = qBound(lo, double(fall[0].timeMs) - (edge - deeper) / slope, hi);
        }
    }
    start = qBound(earliest, start, hi);
    joint.startMs = std::llround(start);
    joint.startUncertaintyMs = std::llround(qMax(start - earliest, hi - start));
}

// The lowest point. The readings rarely catch it: the tip turns between two of them, and a sharp
// bottom read 150 ms apart is passed by several kelvin. How deep it can have gone follows from the
// readings either side of the lowest. On the way down a joint's fall slows (it draws heat at
// once), so the tip lies above every chord of the fall traced forward; on the way up it climbs
// about as its readings do. So between the lowest reading and a neighbour, the tip can have gone
// no deeper than where the fall's last chord, traced forward, meets the climb's first, traced
// back: a V through the readings, exact for straight lines, deeper than the truth for a rounded
// bottom. The lowest point is the vertex of a parabola through the lowest reading and its
// neighbours (never more than a degree and a half below the lowest reading: the neighbours bend
// the parabola, they do not carry the tip further), which lies closer to the truth than the
// middle of that span on the simulator's rounded bottoms (dip error p95 3.4 against 10.0 K on its
// noisy set). It is said to be within the span's far end, plus the whole degree and how far this
// port's wobble may carry a reading (the lowest of a wobbling tip's readings is the one the wobble
// carried lowest, or it hid a lower tip). Before, it was said to be within half a degree, and
// that held the simulator's truth in only 43 to 73 % of its joints.
void JointDetector::estimateLowest(JointRecord &joint) const {
    size_t low = 1;
    for (size_t i = 1; i < m_readings.size(); ++i)
        if (*m_readings.at(i).tip < *m_readings.at(low).tip)
            low = i;
    const auto depthAt = [this](size_t i) {
        return double(m_joint.setpoint) - double(*m_readings.at(i).tip);
    };
    const auto timeAt = [this](size_t i) { return double(m_readings.at(i).timeMs); };
    // The depth per ms from reading i to i + 1 (positive while falling); none past the ends.
    const auto slope = [&](size_t i) -> std::optional<double> {
        if (i + 1 >= m_readings.size() || timeAt(i + 1) <= timeAt(i))
            return std::nullopt;
        return (depthAt(i + 1) - depthAt(i)) / (timeAt(i + 1) - timeAt(i));
    };
    // The V between readings a and a + 1 from the fall's chord before a (traced forward from a)
    // and the climb's chord after a + 1 (traced back from a + 1): how deep it reaches. A side
    // with no chord of its own (the band before the fall, no reading yet after the climb) is
    // bounded by the other's alone, at the far reading.
    const auto deepestBetween = [&](size_t a) {
        const double gap = timeAt(a + 1) - timeAt(a);
        const std::optional<double> down =
            a >= 1 && depthAt(a - 1) < depthAt(a) && m_readings.at(a - 1).timeMs >= joint.startMs
                ? slope(a - 1)
                : std::nullopt;
        const std::optional<double> after = slope(a + 1);
        const std::optional<double> up =
            after && *after < 0 ? std::optional<double>(-*after) : std::nullopt;
        if (down && up) {
            // Depth D where (D − d_a) / down + (D − d_a+1) / up = gap.
            return (gap + depthAt(a) / *down + depthAt(a + 1) / *up) / (1 / *down + 1 / *up);
        }
        if (up)
            return depthAt(a + 1) + *up * gap;
        if (down)
            return depthAt(a) + *down * gap;
        return qMax(depthAt(a), depthAt(a + 1));
    };
    const double lowest = depthAt(low);
    double deepest = lowest;
    if (low >= 1)
        deepest = qMax(deepest, deepestBetween(low - 1));
    if (low + 1 < m_readings.size())
        deepest = qMax(deepest, deepestBetween(low));
    const double depth =
        qBound(lowest - kWholeDegreeHalfStep, vertexDepth(low).value_or(lowest), lowest + 1.5);
    joint.lowestTip = double(m_joint.setpoint) - depth;
    const double reach = kWholeDegreeHalfStep + wobbleReachK();
    joint.dipUncertaintyK = qMax(depth - (lowest - reach), deepest + reach - depth);
}

// The vertex of a parabola through the lowest reading and its neighbours, as a depth, when it
// lies between them.
std::optional<double> JointDetector::vertexDepth(size_t low) const {
    if (low < 1 || low + 1 >= m_readings.size())
        return std::nullopt;
    std::vector<Reading> bottom;
    for (size_t i = low - 1; i <= low + 1; ++i)
        bottom.push_back(readingOf(m_readings.at(i)));
    const auto parabola = fitPolynomial(bottom, 2);
    if (!parabola || parabola->c2 <= 0)
        return std::nullopt;
    const double vertexMs = double(parabola->originMs) - parabola->c1 / (2 * parabola->c2) * 1000;
    if (vertexMs <= double(bottom.front().timeMs) || vertexMs >= double(bottom.back().timeMs))
        return std::nullopt;
    return double(m_joint.setpoint) - parabola->at(vertexMs);
}

void JointDetector::settleAfterRecovery(qint64 timeMs) {
    m_state = State::Settled;
    m_justRecovered = true;
    m_settledSinceMs = timeMs;
    m_tailUntilMs.reset();
}

// Where the tip came back: the last reading below the band and the first of the run back in it,
// the lowest reading before, the straight crossing between the two around the return, and how
// far either side of it the readings for a wide fit reach (a few spacings, or a share of the
// climb when that is longer, never more than kMaxTailMs).
JointDetector::Return JointDetector::returnOf() const {
    Return r;
    for (size_t i = m_readings.size(); i-- > 1;) {
        if (!inBand(m_readings.at(i)))
            break;
        r.back = i;
    }
    if (r.back < 1)
        return r;
    r.low = 1;
    for (size_t i = 1; i < r.back; ++i)
        if (*m_readings.at(i).tip < *m_readings.at(r.low).tip)
            r.low = i;
    const PortReading &below = m_readings.at(r.back - 1);
    const PortReading &in = m_readings.at(r.back);
    r.straightMs = straightCrossing(below.timeMs, *below.tip, in.timeMs, *in.tip, bandEdge());
    const double spacing = double(in.timeMs - below.timeMs);
    const double climb = r.straightMs - double(m_readings.at(r.low).timeMs);
    r.halfWindowMs = qMin(double(kMaxTailMs), qMax(kWideSpacings * spacing, kWideShare * climb));
    return r;
}

qint64 JointDetector::tailUntil() const {
    const Return r = returnOf();
    return r.back < 1 ? m_readings.back().timeMs : std::llround(r.straightMs + r.halfWindowMs);
}

// Two standard deviations of the settled tip's wobble beyond rounding (a fit's own share): how far
// the wobble alone may carry any reading of this port.
double JointDetector::wobbleReachK() const {
    return 2 * std::sqrt(std::max(0.0, m_restingSigmaK * m_restingSigmaK -
                                           kRoundingSigmaK * kRoundingSigmaK));
}

// The readings around the return bracket it, give or take how far the wobble may carry a reading
// across the edge: a curve crossing outside that, at `slopePerMs`, is not this return.
bool JointDetector::nearTheReturn(const Return &r, double crossingMs, double slopePerMs) const {
    const double reach = wobbleReachK() / slopePerMs;
    const double below = double(m_readings.at(r.back - 1).timeMs);
    const double in = double(m_readings.at(r.back).timeMs);
    return crossingMs >= below - reach && crossingMs <= in + reach;
}

// Whether readings scattering `sigma` about a two-parameter fit through `count` of them scatter no
// more than the settled tip's wobble, allowed the spread a variance has by chance over that many.
bool JointDetector::withinWobble(double sigma, int count) const {
    const double freedom = double(count - 2);
    const double allowed = m_restingSigmaK * m_restingSigmaK * (1 + 2 * std::sqrt(2 / freedom));
    return freedom > 0 && sigma * sigma <= allowed;
}

// The first-order return through the whole climb: from the lowest reading to the end of the wide
// window after the return, as the readings past the edge say where the curve levels off. None
// when it places the return far from the readings around it, or when the readings say the return
// was not first order (a heater at full power climbing straight): they scatter about it more than
// about a parabola through the same readings and more than the settled tip's own wobble allows.
// A parabola alone fitting closer proves nothing, as its third coefficient follows a slow wobble.
std::optional<Approach> JointDetector::approachOf(const Return &r) const {
    const double setpoint = double(m_joint.setpoint);
    std::vector<Reading> rise;
    for (size_t i = r.low + 1; i < m_readings.size(); ++i) {
        if (double(m_readings.at(i).timeMs) > r.straightMs + r.halfWindowMs)
            break;
        rise.push_back(readingOf(m_readings.at(i)));
    }
    const auto approach = fitApproach(rise, setpoint, bandEdge());
    if (!approach)
        return std::nullopt;
    if (!nearTheReturn(r, approach->crossingMs, approach->slopePerMs(approach->crossingMs)))
        return std::nullopt;
    const auto parabola = fitPolynomial(rise, 2);
    if (!parabola || approach->sigma <= parabola->sigma)
        return approach;
    return withinWobble(approach->sigma, approach->count) ? approach : std::nullopt;
}

// A heater at full power brings its tip back along a straight line. A line through the whole climb
// (from where it is under way, past the rounded bottom, to the first reading back) averages a slow
// wobble over seconds, where a fit across the few readings around the edge follows it. None when
// the readings scatter about that line more than the settled tip's own wobble allows (a curved
// return), or it crosses the edge away from the readings around the return.
std::optional<JointDetector::Crossing> JointDetector::straightClimbOf(const Return &r) const {
    const double edge = bandEdge();
    const double lowest = *m_readings.at(r.low).tip;
    const double underWay = lowest + kStraightFromShare * (edge - lowest);
    std::vector<Reading> climb;
    for (size_t i = r.low + 1; i < m_readings.size() && i <= r.back + kClimbReadingsAfter; ++i)
        if (!climb.empty() || *m_readings.at(i).tip >= underWay)
            climb.push_back(readingOf(m_readings.at(i)));
    if (climb.size() < kStraightMinReadings)
        return std::nullopt;
    const auto line = fitPolynomial(climb, 1);
    if (!line || line->c1 <= 0)
        return std::nullopt;
    if (!withinWobble(line->sigma, line->count))
        return std::nullopt;
    const double t = double(line->originMs) + (edge - line->c0) / line->c1 * 1000;
    if (!nearTheReturn(r, t, line->slopePerMs(t)))
        return std::nullopt;
    return Crossing{t, crossingUncertaintyMs(*line, t)};
}

// The edge's crossing on the way back. A return the readings show to be first order over its
// whole climb is placed by that curve, a straight one by a line through it: tens of kelvin of
// climb against the same wobble pin it where the few readings around the edge, climbing a few
// kelvin a second on a slow return, would follow a slow wobble by hundreds of milliseconds.
// Otherwise, readings a degree apart on a smooth climb: a local fit through the readings around
// the return (a parabola where there are enough of them, else a line) places it within the two
// readings around it, finer than either. Readings that wobble more than rounding explains would
// make that local fit chase the wobble: then a parabola through the readings of a wider window on
// both sides places it, and its scatter says how sure. Readings further apart than the
// measurement allows only bound it.
void JointDetector::estimateRecovery(JointRecord &joint) const {
    const Return r = returnOf();
    if (r.back < 1)
        return;
    const PortReading &below = m_readings.at(r.back - 1);
    const PortReading &in = m_readings.at(r.back);
    const double edge = bandEdge();
    double crossing = r.straightMs;
    double uncertainty = double(in.timeMs - below.timeMs) / 2;
    std::vector<Reading> climb;
    const size_t from =
        r.back > r.low + kClimbReadingsBefore ? r.back - kClimbReadingsBefore : r.low + 1;
    for (size_t i = from; i < m_readings.size() && i <= r.back + kClimbReadingsAfter; ++i)
        climb.push_back(readingOf(m_readings.at(i)));
    const auto local = fitPolynomial(climb, climb.size() >= 5 ? 2 : 1);
    if (const auto approach = approachOf(r)) {
        crossing = approach->crossingMs;
        uncertainty = qMax(uncertainty, 2 * approach->crossingSigmaMs);
    } else if (const auto line = straightClimbOf(r)) {
        crossing = line->timeMs;
        uncertainty = qMax(uncertainty, line->uncertaintyMs);
    } else if (local && local->sigma > kWobbleSigmaK) {
        std::vector<Reading> wide;
        for (size_t i = r.low + 1; i < m_readings.size(); ++i)
            if (std::abs(double(m_readings.at(i).timeMs) - r.straightMs) <= r.halfWindowMs)
                wide.push_back(readingOf(m_readings.at(i)));
        if (const auto fit = fitPolynomial(wide, wide.size() >= 5 ? 2 : 1)) {
            if (const auto t = crossingTime(*fit, edge, double(wide.front().timeMs),
                                            double(wide.back().timeMs), r.straightMs)) {
                crossing = *t;
                uncertainty = qMax(uncertainty, crossingUncertaintyMs(*fit, *t));
            }
        }
    } else if (local) {
        if (const auto t =
                crossingTime(*local, edge, double(below.timeMs), double(in.timeMs), r.straightMs)) {
            crossing = *t;
            uncertainty = qMin(uncertainty, crossingUncertaintyMs(*local, *t));
        }
    }
    // A fit may place the return beyond the two readings around it (a wobble carried one across
    // the edge), but a wobble can also bend a climb into the shape the fit expects: where they
    // disagree, the truth may lie with either, so the interval reaches across both readings.
    if (crossing > double(in.timeMs))
        uncertainty = std::max(uncertainty, crossing - double(below.timeMs));
    else if (crossing < double(below.timeMs))
        uncertainty = std::max(uncertainty, double(in.timeMs) - crossing);
    // Whatever the fit, a reading may be off by as much as the settled tip wobbled, and a slow
    // wobble looks like the curve itself to a fit across a few readings: over the slope at the
    // return, that is how far the crossing may be off.
    if (const auto fit = fitPolynomial(climb, 1)) {
        // The slope at the return, or the climb's average from its lowest reading if less: a
        // wobble steepens a fit across a few readings, and an exponential return is never
        // flatter than at its end.
        const PortReading &lowest = m_readings.at(r.low);
        const double average = crossing > double(lowest.timeMs)
                                   ? (edge - *lowest.tip) / (crossing - double(lowest.timeMs))
                                   : 1e9;
        const double slope = std::min(std::abs(fit->slopePerMs(crossing)), std::abs(average));
        const double wobble = wobbleReachK();
        if (wobble > 0)
            uncertainty = std::max(uncertainty, slope > 1e-9 ? wobble / slope : 1e9);
    }
    joint.recoveryMs = std::llround(crossing) - joint.startMs;
    joint.recoveryUncertaintyMs = std::llround(uncertainty) + joint.startUncertaintyMs;
    if (uncertainty > kMeasuredWithinMs) {
        // Only bounded: somewhere between the two readings around the return, or within the
        // wobble's reach of the crossing, whichever reaches further.
        const double lo = std::min(double(below.timeMs), crossing - uncertainty);
        const double hi = std::max(double(in.timeMs), crossing + uncertainty);
        joint.recoveryMs = std::llround((lo + hi) / 2) - joint.startMs;
        joint.recoveryUncertaintyMs = std::llround((hi - lo) / 2) + joint.startUncertaintyMs;
        joint.recoveryBounded = true;
    }
}

std::optional<JointRecord> JointDetector::finish(End end, qint64 endMs) {
    // A tip that fell and did not come back while the heater idled was not soldering.
    const bool heaterAnswered = m_joint.powerPeak >= m_restingPowerPct + kPowerRisePct;
    if (end != End::Recovered && !heaterAnswered)
        return std::nullopt;
    // Readings that wobble around the band's edge (a noisy tip settling after a slow return)
    // leave it by a degree or two: no solder joint is that shallow.
    if (double(m_joint.setpoint) - m_joint.lowestTip < m_limits.bandK + kMinExcessK)
        return std::nullopt;
    JointRecord j = m_joint;
    estimateStart(j);
    estimateLowest(j);
    j.dipDepth = double(j.setpoint) - j.lowestTip;
    if (end == End::Recovered) {
        estimateRecovery(j);
    } else if (end == End::Broken) {
        // Not seen to its end: it lasted at least until the last reading below the band.
        j.recoveryBounded = true;
    }
    // A recovered joint ends where the tip is back within the band, not at the readings that
    // confirmed it.
    j.endMs =
        end == End::Recovered && j.recoveryMs ? j.startMs + *j.recoveryMs : qMax(endMs, j.startMs);
    j.durationMs = j.endMs - j.startMs;
    j.verdict = end == End::Broken ? JointVerdict::Incomplete : judge(j, m_limits);
    j.limits = JudgedLimits{m_limits.bandK, m_limits.maxRecoveryMs, m_limits.maxDipK};
    return j;
}

JointVerdict JointDetector::judge(const JointRecord &joint, const JointLimits &limits) {
    if (joint.dipDepth > limits.maxDipK)
        return JointVerdict::TooDeep;
    if (!joint.recoveryMs)
        return JointVerdict::SlowRecovery;
    if (!joint.recoveryBounded)
        return *joint.recoveryMs > limits.maxRecoveryMs ? JointVerdict::SlowRecovery
                                                        : JointVerdict::Ok;
    // Bounded: judged only where the whole interval lies on one side of the limit.
    if (*joint.recoveryMs - joint.recoveryUncertaintyMs > limits.maxRecoveryMs)
        return JointVerdict::SlowRecovery;
    if (*joint.recoveryMs + joint.recoveryUncertaintyMs <= limits.maxRecoveryMs)
        return JointVerdict::Ok;
    return JointVerdict::Incomplete;
}

} // namespace tipscope::model
