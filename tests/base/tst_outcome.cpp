// Outcome carries either the value or the reason, never both, whatever the types: a QString
// value beside a QString reason, nothing at all (Outcome<void>), or an error type of its own.
#include "base/outcome.h"
#include "testmain.h"

#include <QTest>

namespace tst_outcome {

using namespace tipscope::base;

namespace {

Outcome<QString> greeting(bool works) {
    if (!works)
        return failure(QStringLiteral("the greeter is out"));
    return QStringLiteral("hello");
}

Outcome<void> act(bool works) {
    if (!works)
        return failure(QStringLiteral("cannot act"));
    return {};
}

struct Why {
    int code = 0;
};

Outcome<int, Why> number(bool works) {
    if (!works)
        return failure(Why{7});
    return 42;
}

} // namespace

class TestOutcome : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aValueIsOkAndHoldsIt();
    void aFailureHoldsItsReasonEvenWhenItsTypeIsTheValues();
    void nothingButSuccessOrTheReason();
    void anErrorTypeOfItsOwnCarriesMoreThanWords();
};

void TestOutcome::aValueIsOkAndHoldsIt() {
    const auto g = greeting(true);
    QVERIFY(g.ok());
    QVERIFY(bool(g));
    QCOMPARE(g.value(), QStringLiteral("hello"));
    QCOMPARE(g->size(), 5);
    QCOMPARE(greeting(true).value(), QStringLiteral("hello")); // taken from a temporary
}

void TestOutcome::aFailureHoldsItsReasonEvenWhenItsTypeIsTheValues() {
    const auto g = greeting(false);
    QVERIFY(!g.ok());
    QVERIFY(!bool(g));
    QCOMPARE(g.error(), QStringLiteral("the greeter is out"));
}

void TestOutcome::nothingButSuccessOrTheReason() {
    QVERIFY(act(true).ok());
    const auto a = act(false);
    QVERIFY(!a.ok());
    QCOMPARE(a.error(), QStringLiteral("cannot act"));
}

void TestOutcome::anErrorTypeOfItsOwnCarriesMoreThanWords() {
    QCOMPARE(number(true).value(), 42);
    const auto n = number(false);
    QVERIFY(!n.ok());
    QCOMPARE(n.error().code, 7);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestOutcome)

} // namespace tst_outcome
#include "tst_outcome.moc"
