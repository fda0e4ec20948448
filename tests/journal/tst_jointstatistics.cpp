// The support report's joint statistics: per device and port, the last 24 hours of the journal
// counted by verdict with the median and 95th percentile recovery; older joints left out; a
// journal that cannot be read is said in the report instead of stopping it. The report also
// says where the journal is, whether it writes and what it holds.
#include "journalfixture.h"
#include "testmain.h"

#include "journal/jointstatistics.h"
#include "journal/journalhealth.h"
#include "model/report/supportreport.h"

#include <QDateTime>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QTest>

namespace tst_jointstatistics {

using namespace tipscope;
using namespace tipscope::journal;
using namespace tipscope::testing;

class TestJointStatistics : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void theLastDayIsCountedPerPortByVerdictWithRecoveryPercentiles();
    void anUnreadableJournalIsSaidInTheReport();
    void theReportSaysWhereTheJournalIsWhetherItWritesAndWhatItHolds();
};

void TestJointStatistics::theLastDayIsCountedPerPortByVerdictWithRecoveryPercentiles() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    {
        Journal journal(path, quickOptions());
        // Port 1: nine recovered joints (1.0 s to 1.8 s; the last two judged slow), and one
        // that never recovered.
        for (int i = 0; i < 10; ++i) {
            model::JointRecord j = sampleJoint(i, now - 3600'000 + i * 1000, 1);
            j.recoveryMs = 1000 + i * 100;
            j.verdict = i >= 7 ? model::JointVerdict::SlowRecovery : model::JointVerdict::Ok;
            if (i == 9) {
                j.recoveryMs.reset();
                j.verdict = model::JointVerdict::Incomplete;
            }
            journal.append(j);
        }
        model::JointRecord deep = sampleJoint(20, now - 60'000, 2);
        deep.verdict = model::JointVerdict::TooDeep;
        journal.append(deep);
        model::JointRecord old = sampleJoint(21, now - 2 * 86'400'000, 2); // not in the last day
        journal.append(old);
        QVERIFY(journal.flush());
    }
    const QJsonObject joints = lastDayOfJoints(path);
    QVERIFY2(!joints.contains(QStringLiteral("error")),
             qPrintable(joints.value(QStringLiteral("error")).toString()));
    const QJsonArray ports = joints.value(QStringLiteral("ports")).toArray();
    QCOMPARE(ports.size(), 2);
    const QJsonObject p1 = ports.at(0).toObject();
    QCOMPARE(p1.value(QStringLiteral("port")).toInt(), 1);
    QCOMPARE(p1.value(QStringLiteral("joints")).toInt(), 10);
    QCOMPARE(p1.value(QStringLiteral("ok")).toInt(), 7);
    QCOMPARE(p1.value(QStringLiteral("slow recovery")).toInt(), 2);
    QCOMPARE(p1.value(QStringLiteral("incomplete")).toInt(), 1);
    QCOMPARE(p1.value(QStringLiteral("recoveryMedianMs")).toInt(), 1400);
    QCOMPARE(p1.value(QStringLiteral("recoveryP95Ms")).toInt(), 1800);
    const QJsonObject p2 = ports.at(1).toObject();
    QCOMPARE(p2.value(QStringLiteral("joints")).toInt(), 1);
    QCOMPARE(p2.value(QStringLiteral("too deep")).toInt(), 1);

    const QString text = model::supportReportText({{QStringLiteral("joints"), joints}});
    QVERIFY2(text.contains(QStringLiteral("port 1: 10 joints: 7 ok, 2 slow recovery, 0 too deep, "
                                          "1 incomplete; recovery median 1400 ms, 95th "
                                          "percentile 1800 ms")),
             qPrintable(text));
}

void TestJointStatistics::anUnreadableJournalIsSaidInTheReport() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString missing = dir.filePath(QStringLiteral("none.sqlite"));
    const QJsonObject joints = lastDayOfJoints(missing);
    QVERIFY(joints.contains(QStringLiteral("error")));
    const QString text = model::supportReportText({{QStringLiteral("joints"), joints}});
    QVERIFY2(text.contains(QStringLiteral("Joints of the last 24 hours: not read: ")),
             qPrintable(text));
    QVERIFY2(text.contains(missing), qPrintable(text));
}

void TestJointStatistics::theReportSaysWhereTheJournalIsWhetherItWritesAndWhatItHolds() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
    Journal journal(path, quickOptions());
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    for (int i = 0; i < 3; ++i)
        journal.append(sampleJoint(i, now - 60'000 + i * 1000, 1));
    for (int i = 0; i < 2; ++i)
        journal.append(sampleEvent(i, now - 30'000 + i));
    QVERIFY(journal.flush());
    const QJsonObject health = journalHealth(journal);
    QCOMPARE(health.value(QStringLiteral("state")).toString(), QStringLiteral("ready"));
    QCOMPARE(health.value(QStringLiteral("joints")).toInteger(), 3);
    QCOMPARE(health.value(QStringLiteral("events")).toInteger(), 2);
    QCOMPARE(health.value(QStringLiteral("retentionDays")).toInteger(), 0);
    QVERIFY(health.value(QStringLiteral("bytes")).toInteger() > 0);

    const QString text = model::supportReportText({{QStringLiteral("journal"), health}});
    QVERIFY2(text.contains(QStringLiteral("Journal: ") + path), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("  writing: yes\n")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("3 joints and 2 events, 3 and 2 of them not yet "
                                          "published; 0 waiting in memory")),
             qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("kept without a time limit")), qPrintable(text));
    QVERIFY2(!text.contains(QStringLiteral("lost:")), qPrintable(text));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestJointStatistics)

} // namespace tst_jointstatistics
#include "tst_jointstatistics.moc"
