// The local fits the joint detector places its figures with: exact on exact readings, a crossing
// found where the curve crosses and nowhere else, and an uncertainty that grows with the scatter.
#include "model/joints/jointfit.h"
#include "testmain.h"

#include <QTest>
#include <cmath>

namespace tst_jointfit {

using namespace tipscope::model;

class TestJointFit : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aLineAndAParabolaThroughExactReadingsAreFoundExactly();
    void tooFewReadingsOrOneInstantGiveNoFit();
    void aCrossingIsOnlyFoundWithinItsInterval();
    void scatteredReadingsAreLessSure();
    void aFirstOrderReturnThroughExactReadingsIsFoundExactly();
    void aFirstOrderReturnIsPlacedThroughWholeDegreesAndAWobble();
    void aFallOrTooFewReadingsGiveNoReturn();
};

void TestJointFit::aLineAndAParabolaThroughExactReadingsAreFoundExactly() {
    std::vector<Reading> line, parabola;
    for (qint64 t = 1000; t <= 1400; t += 100) {
        const double x = double(t - 1000) / 1000;
        line.push_back({t, 300 + 50 * x});
        parabola.push_back({t, 300 + 50 * x - 20 * x * x});
    }
    const auto l = fitPolynomial(line, 1);
    QVERIFY(l);
    QVERIFY(std::abs(l->at(1250) - 312.5) < 1e-9);
    QVERIFY(std::abs(l->slopePerMs(1100) - 0.05) < 1e-12);
    const auto p = fitPolynomial(parabola, 2);
    QVERIFY(p);
    QVERIFY(std::abs(p->at(1250) - (300 + 12.5 - 20 * 0.0625)) < 1e-9);
    // No scatter: what rounding alone leaves is the floor.
    QCOMPARE(p->sigma, kRoundingSigmaK);
}

void TestJointFit::tooFewReadingsOrOneInstantGiveNoFit() {
    QVERIFY(!fitPolynomial({{0, 1}, {100, 2}}, 2));
    QVERIFY(!fitPolynomial({{100, 1}, {100, 2}, {100, 3}}, 1));
    QVERIFY(!fitPolynomial({{0, 1}, {100, 2}, {200, 3}}, 3));
}

void TestJointFit::aCrossingIsOnlyFoundWithinItsInterval() {
    const auto l = fitPolynomial({{0, 300}, {100, 310}, {200, 320}}, 1);
    QVERIFY(l);
    const auto t = crossingTime(*l, 315, 0, 200, 100);
    QVERIFY(t && std::abs(*t - 150) < 1e-6);
    QVERIFY(!crossingTime(*l, 315, 0, 120, 100));
    QVERIFY(!crossingTime(*l, 340, 0, 200, 100));
}

void TestJointFit::scatteredReadingsAreLessSure() {
    std::vector<Reading> clean, wobbly;
    for (qint64 t = 0; t <= 600; t += 100) {
        clean.push_back({t, 300 + 0.05 * double(t)});
        wobbly.push_back({t, 300 + 0.05 * double(t) + ((t / 100) % 2 ? 2.0 : -2.0)});
    }
    const auto c = fitPolynomial(clean, 1);
    const auto w = fitPolynomial(wobbly, 1);
    QVERIFY(c && w);
    QVERIFY(w->sigma > 1.5);
    QVERIFY(crossingUncertaintyMs(*w, 300) > 3 * crossingUncertaintyMs(*c, 300));
}

// y = 350 − 60·e^(−t/800 ms) from t = 0: it passes 344.5 (5.5 K below) at 800·ln(60/5.5).
namespace {
constexpr double kAsymptote = 350, kLevel = 344.5, kDeficit = 60, kTauMs = 800;
double returnAt(qint64 t) {
    return kAsymptote - kDeficit * std::exp(-double(t) / kTauMs);
}
const double kCrossingMs = kTauMs * std::log(kDeficit / (kAsymptote - kLevel));
} // namespace

void TestJointFit::aFirstOrderReturnThroughExactReadingsIsFoundExactly() {
    std::vector<Reading> readings;
    for (qint64 t = 0; t <= 2500; t += 90)
        readings.push_back({t, returnAt(t)});
    const auto a = fitApproach(readings, kAsymptote, kLevel);
    QVERIFY(a);
    QVERIFY2(std::abs(a->crossingMs - kCrossingMs) < 0.5,
             qPrintable(QString::number(a->crossingMs)));
    QVERIFY(std::abs(a->tauMs - kTauMs) < 0.5);
    QVERIFY(std::abs(a->at(kCrossingMs) - kLevel) < 1e-6);
    QVERIFY(std::abs(a->slopePerMs(kCrossingMs) - (kAsymptote - kLevel) / kTauMs) < 1e-9);
    QCOMPARE(a->sigma, kRoundingSigmaK);
}

// Whole degrees on a tip that wobbles ±1.5 K in a 1.5 s swing: near 344.5 the return climbs
// 7 K/s, so the swing alone moves the readings there by 200 ms; the whole climb places it within
// a quarter of that, and says how sure it is.
void TestJointFit::aFirstOrderReturnIsPlacedThroughWholeDegreesAndAWobble() {
    for (const double phase : {0.0, 1.0, 2.0, 3.0, 4.0, 5.0}) {
        std::vector<Reading> readings;
        for (qint64 t = 0; t <= 2500; t += 70 + (t / 70) % 4 * 15) {
            const double wobble = 1.5 * std::sin(double(t) / 1500 * 2 * M_PI + phase);
            readings.push_back({t, std::round(returnAt(t) + wobble)});
        }
        const auto a = fitApproach(readings, kAsymptote, kLevel);
        QVERIFY(a);
        const double error = std::abs(a->crossingMs - kCrossingMs);
        QVERIFY2(error < 50, qPrintable(QStringLiteral("phase %1: %2 ms").arg(phase).arg(error)));
        QVERIFY(a->sigma > 0.8);
        QVERIFY(a->crossingSigmaMs > 1);
    }
}

void TestJointFit::aFallOrTooFewReadingsGiveNoReturn() {
    QVERIFY(!fitApproach({{0, 300}, {100, 320}}, kAsymptote, kLevel));
    QVERIFY(!fitApproach({{0, 340}, {100, 330}, {200, 320}, {300, 310}}, kAsymptote, kLevel));
    QVERIFY(!fitApproach({{0, 300}, {100, 320}, {200, 330}}, kLevel, kLevel));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestJointFit)

} // namespace tst_jointfit
#include "tst_jointfit.moc"
