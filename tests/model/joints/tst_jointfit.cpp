// The local fits the joint detector places its figures with: exact on exact readings, a crossing
// found where the curve crosses and nowhere else, and an uncertainty that grows with the scatter.
#include "model/joints/jointfit.h"

#include <QTest>
#include <cmath>

using namespace tipscope::model;

class TestJointFit : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aLineAndAParabolaThroughExactReadingsAreFoundExactly();
    void tooFewReadingsOrOneInstantGiveNoFit();
    void aCrossingIsOnlyFoundWithinItsInterval();
    void scatteredReadingsAreLessSure();
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

QTEST_GUILESS_MAIN(TestJointFit)
#include "tst_jointfit.moc"
