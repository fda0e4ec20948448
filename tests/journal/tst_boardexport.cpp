// The board record as JSON, CSV and text: the same joint and event fields as the joint export,
// the figures of the journal the record was read from, and what the journal does not hold said
// as such, never filled in.
#include "journalfixture.h"
#include "testmain.h"

#include "journal/boardexport.h"
#include "journal/jointexport.h"

#include <QJsonArray>
#include <QTemporaryDir>
#include <QTest>

namespace tst_boardexport {

using namespace tipscope;
using namespace tipscope::testing;

class TestBoardExport : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void jsonCarriesEveryJointEventAndTipOfTheRecord();
    void jsonSaysWhatTheJournalDoesNotHold();
    void csvIsTheJointExportOfTheBoardsJoints();
    void textListsEachJointWithHowSureItIs();
    void wearIsTheRecentMedianAgainstTheBaseline();

private:
    QTemporaryDir m_dir;
    journal::BoardRecord m_record;
};

void TestBoardExport::initTestCase() {
    const auto record = writeAndReadSampleBoard(m_dir.filePath(QStringLiteral("journal.sqlite")));
    QVERIFY2(record, qPrintable(record.error()));
    m_record = record.value();
}

void TestBoardExport::jsonCarriesEveryJointEventAndTipOfTheRecord() {
    const QJsonObject json = journal::boardJson(m_record, QStringLiteral("9.9.9"));
    QCOMPARE(json.value(QStringLiteral("board_serial")).toString(), QStringLiteral("SN-42"));
    QCOMPARE(json.value(QStringLiteral("result")).toString(), QStringLiteral("fail"));
    QCOMPARE(json.value(QStringLiteral("software")).toString(), QStringLiteral("9.9.9"));
    QCOMPARE(json.value(QStringLiteral("first")).toString(),
             journal::utcText(m_record.joints.first().record.startMs));
    const QJsonArray joints = json.value(QStringLiteral("joints")).toArray();
    QCOMPARE(joints.size(), m_record.joints.size());
    for (int i = 0; i < joints.size(); ++i)
        QCOMPARE(joints.at(i).toObject(), journal::jointJson(m_record.joints.at(i)));
    const QJsonArray events = json.value(QStringLiteral("events")).toArray();
    QCOMPARE(events.size(), m_record.events.size());
    QCOMPARE(events.first().toObject().value(QStringLiteral("kind")).toString(),
             QStringLiteral("port error"));
    const QJsonObject verdicts = json.value(QStringLiteral("verdicts")).toObject();
    QCOMPARE(verdicts.value(QStringLiteral("ok")).toInt(), 3);
    QCOMPARE(verdicts.value(QStringLiteral("too deep")).toInt(), 1);
    const QJsonObject tip = json.value(QStringLiteral("tips")).toArray().first().toObject();
    QCOMPARE(tip.value(QStringLiteral("tool")).toString(), QStringLiteral("C245"));
    QCOMPARE(tip.value(QStringLiteral("baseline_recovery_ms")).toInt(), 1000);
    QCOMPARE(tip.value(QStringLiteral("recent_recovery_ms")).toInt(), 1300);
    QCOMPARE(tip.value(QStringLiteral("setpoints_c")).toArray(), QJsonArray{350});
    const QJsonObject other = json.value(QStringLiteral("tips")).toArray().at(1).toObject();
    QVERIFY(other.value(QStringLiteral("baseline_recovery_ms")).isNull());
    QVERIFY(other.value(QStringLiteral("since")).isNull());
    QCOMPARE(json.value(QStringLiteral("profiles_before")).toArray().size(), 1);
}

void TestBoardExport::jsonSaysWhatTheJournalDoesNotHold() {
    const QJsonObject notHeld = journal::boardJson(m_record, QStringLiteral("9.9.9"))
                                    .value(QStringLiteral("not_in_journal"))
                                    .toObject();
    QCOMPARE(notHeld.keys(), (QStringList{QStringLiteral("curves"), QStringLiteral("limits"),
                                          QStringLiteral("settings")}));
    for (const QJsonValue &why : notHeld)
        QVERIFY(why.toString().contains(QStringLiteral("journal")));
    // Once every joint carries its limits, they are no longer among what the journal lacks.
    journal::BoardRecord judged = m_record;
    for (journal::StoredJoint &joint : judged.joints)
        joint.record.limits = model::JudgedLimits{5, 5000, 80};
    QCOMPARE(journal::boardJson(judged, QStringLiteral("9.9.9"))
                 .value(QStringLiteral("not_in_journal"))
                 .toObject()
                 .keys(),
             (QStringList{QStringLiteral("curves"), QStringLiteral("settings")}));
    QVERIFY(!journal::boardText(judged, QStringLiteral("9.9.9"))
                 .contains(QStringLiteral("  limits: joints")));
}

void TestBoardExport::csvIsTheJointExportOfTheBoardsJoints() {
    const QStringList lines =
        journal::boardCsv(m_record).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), m_record.joints.size() + 1);
    QCOMPARE(lines.first(), journal::jointCsvHeader());
    for (int i = 0; i < m_record.joints.size(); ++i)
        QCOMPARE(lines.at(i + 1), journal::jointCsvRow(m_record.joints.at(i)));
}

void TestBoardExport::textListsEachJointWithHowSureItIs() {
    const QString text = journal::boardText(m_record, QStringLiteral("9.9.9"));
    const QStringList lines = text.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(lines.at(0), QStringLiteral("board SN-42"));
    QCOMPARE(lines.at(1),
             QStringLiteral("result: fail (6 joints: 3 ok, 1 slow recovery, 1 too deep, 1 "
                            "incomplete)"));
    const QStringList jointLines = lines.filter(QStringLiteral("  WO-7  (start ±40 ms"));
    QCOMPARE(jointLines.size(), m_record.joints.size());
    QVERIFY2(jointLines.at(0).endsWith(QStringLiteral("dip ±0.5 K, recovery ±60 ms)  ana")),
             qPrintable(jointLines.at(0)));
    // Only bounded: the interval, and no ± that would look measured.
    QVERIFY2(jointLines.at(4).contains(QStringLiteral("recovery 0.8-1.8 s bounded")),
             qPrintable(jointLines.at(4)));
    // Each with the limits it was judged by, where the journal kept them.
    QVERIFY2(jointLines.at(4).endsWith(
                 QStringLiteral("dip ±0.5 K)  limits: dip 80 K, recovery 5.0 s, band 5 K  ana")),
             qPrintable(jointLines.at(4)));
    QVERIFY(text.contains(QStringLiteral("E-PT1: tip sensor open")));
    QVERIFY(text.contains(QStringLiteral("profile 0123456789ab applied")));
    QVERIFY(text.contains(QStringLiteral("\n  limits: joints without the limits they were judged "
                                         "by (journaled before the journal kept them): 1 of 6")));
    QVERIFY(text.endsWith(QStringLiteral("software: TipScope 9.9.9\n")));
}

void TestBoardExport::wearIsTheRecentMedianAgainstTheBaseline() {
    QCOMPARE(journal::wearShareText(m_record.tips.at(0)), QStringLiteral("+30 %"));
    QCOMPARE(journal::wearShareText(m_record.tips.at(1)), QString());
    const QString text = journal::boardText(m_record, QStringLiteral("9.9.9"));
    QVERIFY2(text.contains(QStringLiteral("C245  5 joints at 350 °C  wear: recovers in 1.30 s "
                                          "(median of the last 10 joints), 1.00 s when plugged "
                                          "in: +30 %")),
             qPrintable(text));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestBoardExport)

} // namespace tst_boardexport
#include "tst_boardexport.moc"
