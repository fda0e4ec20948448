// TipWear: a tip whose recent recoveries are slower than its first ones by more than the share
// gets one notice; a new tool starts afresh; joints that never recovered do not count.
#include "model/joints/tipwear.h"
#include "testmain.h"

#include <QTest>

namespace tst_tipwear {

using namespace tipscope::model;

namespace {
const DeviceIdentity kDme{QStringLiteral("demo"), 1, QStringLiteral("DME-2C"),
                          QStringLiteral("9996780")};

JointRecord joint(qint64 recoveryMs, const QString &tool = QStringLiteral("C245"), int port = 1) {
    JointRecord j;
    j.device = kDme;
    j.port = port;
    j.tool = tool;
    j.recoveryMs = recoveryMs;
    j.verdict = JointVerdict::Ok;
    return j;
}

// Feeds `count` joints of `recoveryMs`; the notices they gave.
QList<TipWear::Notice> feed(TipWear &wear, int count, qint64 recoveryMs,
                            const QString &tool = QStringLiteral("C245")) {
    QList<TipWear::Notice> notices;
    for (int i = 0; i < count; ++i)
        if (const auto n = wear.add(joint(recoveryMs, tool), 0.3))
            notices.append(*n);
    return notices;
}
} // namespace

class TestTipWear : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aTipThatSlowsBeyondTheShareIsNoticedOnce();
    void aTipThatSlowsLessIsNotNoticed();
    void aNewToolStartsAfresh();
    void jointsThatNeverRecoveredDoNotCount();
    void portsAreKeptApart();
    void theRecentMedianIsWhatTheBaselineIsComparedWith();
};

void TestTipWear::aTipThatSlowsBeyondTheShareIsNoticedOnce() {
    TipWear wear;
    QVERIFY(feed(wear, TipWear::kWindow, 1000).isEmpty());
    QCOMPARE(wear.baselineMs(kDme, 1), 1000);
    // Half the window slow is not yet a slower median of the window.
    QVERIFY(feed(wear, TipWear::kWindow / 2, 1500).isEmpty());
    const auto notices = feed(wear, TipWear::kWindow, 1500);
    QCOMPARE(notices.size(), 1);
    QCOMPARE(notices.first().baselineMs, 1000);
    QCOMPARE(notices.first().recentMs, 1500);
    QCOMPARE(notices.first().tool, QStringLiteral("C245"));
    QVERIFY(TipWear::noticeText(notices.first()).startsWith(QStringLiteral("tip wearing: C245")));
    QVERIFY(feed(wear, TipWear::kWindow, 2000).isEmpty());
}

void TestTipWear::aTipThatSlowsLessIsNotNoticed() {
    TipWear wear;
    feed(wear, TipWear::kWindow, 1000);
    QVERIFY(feed(wear, 3 * TipWear::kWindow, 1290).isEmpty());
}

void TestTipWear::aNewToolStartsAfresh() {
    TipWear wear;
    feed(wear, TipWear::kWindow, 1000);
    wear.toolChanged(kDme, 1);
    QVERIFY(!wear.baselineMs(kDme, 1));
    // The new tip's first joints are its own baseline, however slow.
    QVERIFY(feed(wear, 2 * TipWear::kWindow, 1500).isEmpty());
    QCOMPARE(wear.baselineMs(kDme, 1), 1500);
    // A joint made with another tool also starts afresh.
    QVERIFY(feed(wear, 2 * TipWear::kWindow, 3000, QStringLiteral("C470")).isEmpty());
    QCOMPARE(wear.baselineMs(kDme, 1), 3000);
}

void TestTipWear::jointsThatNeverRecoveredDoNotCount() {
    TipWear wear;
    feed(wear, TipWear::kWindow, 1000);
    JointRecord never = joint(0);
    never.recoveryMs.reset();
    never.verdict = JointVerdict::SlowRecovery;
    JointRecord incomplete = joint(9000);
    incomplete.verdict = JointVerdict::Incomplete;
    for (int i = 0; i < 3 * TipWear::kWindow; ++i) {
        QVERIFY(!wear.add(never, 0.3));
        QVERIFY(!wear.add(incomplete, 0.3));
    }
}

void TestTipWear::portsAreKeptApart() {
    TipWear wear;
    feed(wear, TipWear::kWindow, 1000);
    for (int i = 0; i < TipWear::kWindow; ++i)
        QVERIFY(!wear.add(joint(5000, QStringLiteral("C245"), 2), 0.3));
    QCOMPARE(wear.baselineMs(kDme, 2), 5000);
    QCOMPARE(wear.baselineMs(kDme, 1), 1000);
}

void TestTipWear::theRecentMedianIsWhatTheBaselineIsComparedWith() {
    TipWear wear;
    feed(wear, TipWear::kWindow, 1000);
    QVERIFY(!wear.recentMs(kDme, 1));
    feed(wear, 3, 1200);
    QCOMPARE(wear.recentMs(kDme, 1), 1200);
    // Only the last kWindow count.
    feed(wear, TipWear::kWindow, 1400);
    QCOMPARE(wear.recentMs(kDme, 1), 1400);
    QVERIFY(!wear.recentMs(kDme, 2));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestTipWear)

} // namespace tst_tipwear
#include "tst_tipwear.moc"
