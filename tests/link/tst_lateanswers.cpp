// LateAnswers alone: a timeout holds its command to its device, and nothing else, until its
// deadline or until every answer still expected came; only answers to the robot from the held
// device (or, without addresses, unaddressed answers) are taken for those; deadlines that passed
// are dropped, so the holds stay bounded.
#include "link/lateanswers.h"
#include "testmain.h"

#include <QTest>

namespace tst_lateanswers {

using namespace tipscope::link;
using namespace tipscope::protocol;

namespace {
constexpr int kRobot = 0;

Frame answer(const QByteArray &command, std::optional<int> from, Header header = Header::Answer,
             std::optional<int> to = kRobot) {
    Frame f;
    f.header = header;
    f.command = command;
    if (from) {
        f.source = from;
        f.target = to;
    }
    f.data = header == Header::Nak ? QByteArray("00004") : QByteArray("00350");
    return f;
}
} // namespace

class TestLateAnswers : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aTimeoutHoldsItsCommandToItsDeviceAndNothingElse();
    void eachLateAnswerEndsOneOfThoseExpected();
    void onlyAnswersToTheRobotFromTheHeldDeviceAreTaken_data();
    void onlyAnswersToTheRobotFromTheHeldDeviceAreTaken();
    void withoutAddressesOnlyUnaddressedAnswersAreTaken();
    void holdsEndAtTheirDeadlineAndTheNextOneIsSaid();
};

void TestLateAnswers::aTimeoutHoldsItsCommandToItsDeviceAndNothingElse() {
    LateAnswers late;
    late.expect("ST1", 1, 1000);
    QVERIFY(late.holds("ST1", 1, 999));
    QVERIFY(!late.holds("ST2", 1, 999));
    QVERIFY(!late.holds("ST1", 2, 999));
    QVERIFY(!late.holds("ST1", std::nullopt, 999));
    QVERIFY(!late.holds("ST1", 1, 1000)); // the deadline passed: the answer is taken as lost
}

// Two timeouts of the same read: two answers may still come, and the hold lasts until the later
// deadline or the second of them.
void TestLateAnswers::eachLateAnswerEndsOneOfThoseExpected() {
    LateAnswers late;
    late.expect("ST1", 1, 1000);
    late.expect("ST1", 1, 800);
    QVERIFY(late.absorb(answer("ST1", 1), kRobot));
    QVERIFY(late.holds("ST1", 1, 900));
    QVERIFY(late.absorb(answer("ST1", 1, Header::Nak), kRobot)); // a refusal is an answer too
    QVERIFY(!late.holds("ST1", 1, 900));
    QVERIFY(!late.absorb(answer("ST1", 1), kRobot)); // nothing was expected any more
}

void TestLateAnswers::onlyAnswersToTheRobotFromTheHeldDeviceAreTaken_data() {
    QTest::addColumn<Frame>("stray");
    QTest::newRow("another device") << answer("ST1", 2);
    QTest::newRow("another command") << answer("ST2", 1);
    QTest::newRow("to another robot") << answer("ST1", 1, Header::Answer, 5);
    QTest::newRow("a request, not an answer") << answer("ST1", 1, Header::Read);
    QTest::newRow("without addresses") << answer("ST1", std::nullopt);
}

void TestLateAnswers::onlyAnswersToTheRobotFromTheHeldDeviceAreTaken() {
    QFETCH(Frame, stray);
    LateAnswers late;
    late.expect("ST1", 1, 1000);
    QVERIFY(!late.absorb(stray, kRobot));
    QVERIFY(late.holds("ST1", 1, 500));
}

void TestLateAnswers::withoutAddressesOnlyUnaddressedAnswersAreTaken() {
    LateAnswers late;
    late.expect("ST1", std::nullopt, 1000);
    QVERIFY(!late.absorb(answer("ST1", 1), kRobot));
    QVERIFY(late.holds("ST1", std::nullopt, 500));
    QVERIFY(late.absorb(answer("ST1", std::nullopt), kRobot));
    QVERIFY(!late.holds("ST1", std::nullopt, 500));
}

void TestLateAnswers::holdsEndAtTheirDeadlineAndTheNextOneIsSaid() {
    LateAnswers late;
    QCOMPARE(late.nextDeadline(0), std::nullopt);
    late.expect("ST1", 1, 900);
    late.expect("ST2", 1, 500);
    QCOMPARE(late.nextDeadline(100), std::optional<qint64>(500));
    QCOMPARE(late.nextDeadline(600), std::optional<qint64>(900));
    // The passed hold is gone: its late answer, if it comes now, is a stray like any other.
    QVERIFY(!late.absorb(answer("ST2", 1), kRobot));
    QCOMPARE(late.nextDeadline(900), std::nullopt);
    QVERIFY(!late.absorb(answer("ST1", 1), kRobot));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestLateAnswers)

} // namespace tst_lateanswers
#include "tst_lateanswers.moc"
