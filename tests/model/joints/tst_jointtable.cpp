// Joints as a table: each joint listed once wherever it was read from, newest first, the
// temperatures in the chosen unit, the verdict in words with a level to colour it, and the CSV a
// spreadsheet reads; and the recovery statistics over the listed joints.
#include "model/joints/jointstats.h"
#include "model/joints/jointtable.h"
#include "testmain.h"

#include <QSignalSpy>
#include <QTest>

namespace tst_jointtable {

using namespace tipscope::model;

namespace {
const qint64 kT0 = QDateTime(QDate(2026, 3, 2), QTime(10, 0)).toMSecsSinceEpoch();
constexpr qint64 kDayMs = 24 * 3600'000LL;

JointRow joint(qint64 startMs, std::optional<qint64> recoveryMs = 1500, int port = 1,
               const QString &tool = QStringLiteral("C245")) {
    JointRow r;
    r.joint.device = {QStringLiteral("/dev/ttyUSB0"), 0, QStringLiteral("DME-2C"),
                      QStringLiteral("9996780")};
    r.joint.port = port;
    r.joint.tool = tool;
    r.joint.startMs = startMs;
    r.joint.endMs = startMs + 2000;
    r.joint.setpoint = 350;
    r.joint.lowestTip = 310.4;
    r.joint.dipDepth = 39.6;
    r.joint.dipUncertaintyK = 0.5;
    r.joint.recoveryMs = recoveryMs;
    r.joint.recoveryUncertaintyMs = recoveryMs ? 40 : 0;
    r.joint.durationMs = 2000;
    r.joint.powerPeak = 87;
    r.joint.powerIntegral = 95.25;
    r.joint.verdict = recoveryMs ? JointVerdict::Ok : JointVerdict::Incomplete;
    return r;
}

QStringList startsOf(const JointTableModel &m) {
    QStringList out;
    for (const JointRow &r : m.rows())
        out.append(QString::number((r.joint.startMs - kT0) / 1000));
    return out;
}
} // namespace

class TestJointTable : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aJointReadTwiceIsOneRow();
    void rowsAreNewestFirstWhateverOrderTheyCameIn();
    void theDeviceIsShortWithItsDescriptionAsTooltip();
    void temperaturesFollowTheUnit_data();
    void temperaturesFollowTheUnit();
    void theVerdictIsInWordsAndCarriesALevel_data();
    void theVerdictIsInWordsAndCarriesALevel();
    void theCsvHasUnitsOffsetTimesAndStableVerdictNames();
    void aBoundedRecoveryShowsItsIntervalAndSaysSo();
    void histogramBinsAreRoundAndJointsWithoutRecoveryCountApart();
    void theTrendIsEachToolsDailyMedian();
};

void TestJointTable::aJointReadTwiceIsOneRow() {
    JointTableModel m;
    QSignalSpy inserted(&m, &QAbstractItemModel::rowsInserted);
    QVERIFY(inserted.isValid());
    QVERIFY(m.add(joint(kT0)));
    QVERIFY(!m.add(joint(kT0)));         // the journal's copy of the live joint
    QVERIFY(m.add(joint(kT0, 1500, 2))); // another port at the same moment
    QCOMPARE(m.rowCount(), 2);
    QCOMPARE(inserted.size(), 2);
    m.reset({joint(kT0), joint(kT0), joint(kT0 + 1000)});
    QCOMPARE(m.rowCount(), 2);
    QVERIFY(m.contains(joint(kT0).joint));
}

void TestJointTable::rowsAreNewestFirstWhateverOrderTheyCameIn() {
    JointTableModel m;
    m.reset({joint(kT0 + 20'000), joint(kT0), joint(kT0 + 40'000)});
    QCOMPARE(startsOf(m), (QStringList{"40", "20", "0"}));
    m.add(joint(kT0 + 30'000));
    m.add(joint(kT0 + 60'000));
    QCOMPARE(startsOf(m), (QStringList{"60", "40", "30", "20", "0"}));
}

void TestJointTable::theDeviceIsShortWithItsDescriptionAsTooltip() {
    JointTableModel m;
    m.add(joint(kT0));
    const QModelIndex device = m.index(0, JointTableModel::Device);
    QCOMPARE(device.data().toString(), QStringLiteral("DME-2C (00)"));
    QCOMPARE(device.data(Qt::ToolTipRole).toString(), joint(kT0).joint.device.description());
}

void TestJointTable::temperaturesFollowTheUnit_data() {
    QTest::addColumn<TemperatureUnit>("unit");
    QTest::addColumn<QString>("setpoint");
    QTest::addColumn<QString>("lowest");
    QTest::addColumn<QString>("dip");
    QTest::addColumn<QString>("csvHeader");
    QTest::newRow("celsius") << TemperatureUnit::Celsius << "350 °C"
                             << "310.4 °C"
                             << "39.6 K"
                             << "setpoint [°C],lowest tip [°C],dip [K]";
    // A dip is a difference: 39.6 K is 71.3 °F, not 103.3 °F.
    QTest::newRow("fahrenheit") << TemperatureUnit::Fahrenheit << "662 °F"
                                << "590.7 °F"
                                << "71.3 °F"
                                << "setpoint [°F],lowest tip [°F],dip [°F]";
}

void TestJointTable::temperaturesFollowTheUnit() {
    QFETCH(TemperatureUnit, unit);
    QFETCH(QString, setpoint);
    QFETCH(QString, lowest);
    QFETCH(QString, dip);
    QFETCH(QString, csvHeader);
    JointTableModel m;
    m.add(joint(kT0));
    QSignalSpy changed(&m, &QAbstractItemModel::dataChanged);
    QVERIFY(changed.isValid());
    m.setTemperatureUnit(unit);
    QCOMPARE(changed.isEmpty(), unit == TemperatureUnit::Celsius);
    QCOMPARE(m.index(0, JointTableModel::Setpoint).data().toString(), setpoint);
    QCOMPARE(m.index(0, JointTableModel::Lowest).data().toString(), lowest);
    QCOMPARE(m.index(0, JointTableModel::Dip).data().toString(), dip);
    QVERIFY2(QString::fromUtf8(m.csv()).section(QLatin1Char('\n'), 0, 0).contains(csvHeader),
             m.csv().constData());
}

void TestJointTable::theVerdictIsInWordsAndCarriesALevel_data() {
    QTest::addColumn<JointVerdict>("verdict");
    QTest::addColumn<QString>("words");
    QTest::addColumn<Level>("level");
    QTest::newRow("ok") << JointVerdict::Ok << "ok" << Level::Ok;
    QTest::newRow("slow") << JointVerdict::SlowRecovery << "slow recovery" << Level::Warning;
    QTest::newRow("deep") << JointVerdict::TooDeep << "too deep" << Level::Warning;
    QTest::newRow("incomplete") << JointVerdict::Incomplete << "incomplete" << Level::Info;
}

void TestJointTable::theVerdictIsInWordsAndCarriesALevel() {
    QFETCH(JointVerdict, verdict);
    QFETCH(QString, words);
    QFETCH(Level, level);
    JointRow r = joint(kT0);
    r.joint.verdict = verdict;
    JointTableModel m;
    m.add(r);
    QCOMPARE(m.index(0, JointTableModel::Verdict).data().toString(), words);
    for (int column = 0; column < JointTableModel::ColumnCount; ++column) {
        QCOMPARE(m.index(0, column).data(JointTableModel::LevelRole).toInt(), int(level));
        QCOMPARE(m.index(0, column).data(JointTableModel::VerdictRole).toInt(), int(verdict));
    }
}

void TestJointTable::theCsvHasUnitsOffsetTimesAndStableVerdictNames() {
    JointRow slow = joint(kT0 + 1000, 4200);
    slow.joint.verdict = JointVerdict::SlowRecovery;
    slow.workOrder = QStringLiteral("WO 17, board \"A\"");
    JointTableModel m;
    m.reset({joint(kT0, std::nullopt, 2, QStringLiteral("T210")), slow});
    const QStringList lines = QString::fromUtf8(m.csv()).split(QLatin1Char('\n'));
    QCOMPARE(lines.size(), 4); // header, two joints, the empty rest after the last '\n'
    QCOMPARE(lines.at(0),
             QStringLiteral("time,device,port,tool,setpoint [°C],lowest tip [°C],dip [K],"
                            "recovery [s],recovery uncertainty [s],recovery bounded,duration [s],"
                            "power peak [%],power time [%·s],verdict,"
                            "work order"));
    const QString time = QDateTime::fromMSecsSinceEpoch(kT0 + 1000)
                             .toOffsetFromUtc(QDateTime::fromMSecsSinceEpoch(kT0).offsetFromUtc())
                             .toString(Qt::ISODateWithMs);
    QCOMPARE(lines.at(1), time + QStringLiteral(",/dev/ttyUSB0|00|DME-2C|9996780,1,C245,350,310.4,"
                                                "39.6,4.200,0.040,false,2.000,87,95.25,"
                                                "slow recovery,"
                                                "\"WO 17, board \"\"A\"\"\""));
    // No recovery: an empty cell, never 0.
    QVERIFY2(lines.at(2).contains(
                 QStringLiteral(",2,T210,350,310.4,39.6,,,false,2.000,87,95.25,incomplete,")),
             qPrintable(lines.at(2)));
    QVERIFY(lines.at(3).isEmpty());
}

// A recovery known only between two readings is shown as that interval, flagged in the CSV, and
// its tooltip says why; a measured one says how sure it is.
void TestJointTable::aBoundedRecoveryShowsItsIntervalAndSaysSo() {
    JointRow bounded = joint(kT0, 2500);
    bounded.joint.recoveryBounded = true;
    bounded.joint.recoveryUncertaintyMs = 500;
    JointTableModel m;
    m.reset({bounded, joint(kT0 + 1000, 1480)});
    const QModelIndex measured = m.index(0, JointTableModel::Recovery);
    QCOMPARE(measured.data().toString(), QStringLiteral("1.5 s"));
    QVERIFY2(measured.data(Qt::ToolTipRole).toString().contains(QStringLiteral("± 40 ms")),
             qPrintable(measured.data(Qt::ToolTipRole).toString()));
    const QModelIndex range = m.index(1, JointTableModel::Recovery);
    QCOMPARE(range.data().toString(), QStringLiteral("2.0–3.0 s"));
    QVERIFY(range.data(Qt::ToolTipRole).toString().contains(QStringLiteral("Only bounded")));
    const QStringList lines = QString::fromUtf8(m.csv()).split(QLatin1Char('\n'));
    QVERIFY2(lines.at(2).contains(QStringLiteral(",2.500,0.500,true,")), qPrintable(lines.at(2)));
    QVERIFY2(lines.at(1).contains(QStringLiteral(",1.480,0.040,false,")), qPrintable(lines.at(1)));
}

void TestJointTable::histogramBinsAreRoundAndJointsWithoutRecoveryCountApart() {
    QList<JointRow> rows;
    for (const qint64 ms : {100, 900, 950, 1999, 4100})
        rows.append(joint(kT0 + ms, ms));
    rows.append(joint(kT0 + 5000, std::nullopt));
    const RecoveryHistogram h = recoveryHistogram(rows, 10);
    QCOMPARE(h.binMs, 500); // 4.1 s in at most 10 bins
    QCOMPARE(h.counts, (QList<int>{1, 2, 0, 1, 0, 0, 0, 0, 1}));
    QCOMPARE(h.notRecovered, 1);
    QCOMPARE(h.maxCount(), 2);
    QCOMPARE(recoveryHistogram(rows, 100).binMs, 100);
    QVERIFY(recoveryHistogram({joint(kT0, std::nullopt)}).counts.isEmpty());
}

void TestJointTable::theTrendIsEachToolsDailyMedian() {
    QList<JointRow> rows;
    for (const qint64 ms : {1000, 3000, 2000})
        rows.append(joint(kT0 + ms, ms));
    rows.append(joint(kT0 + kDayMs, 2500));
    rows.append(joint(kT0 + kDayMs + 1, std::nullopt));
    rows.append(joint(kT0 + 2 * kDayMs, 800, 2, QStringLiteral("T210")));
    const QList<ToolTrend> trends = dailyRecoveryByTool(rows);
    QCOMPARE(trends.size(), 2);
    QCOMPARE(trends.at(0).tool, QStringLiteral("C245"));
    QCOMPARE(trends.at(0).days.size(), 2);
    QCOMPARE(trends.at(0).days.at(0).day, QDate(2026, 3, 2));
    QCOMPARE(trends.at(0).days.at(0).medianMs, 2000);
    QCOMPARE(trends.at(0).days.at(0).joints, 3);
    QCOMPARE(trends.at(0).days.at(1).medianMs, 2500);
    QCOMPARE(trends.at(0).days.at(1).joints, 1); // the one that never recovered is not a zero
    QCOMPARE(trends.at(1).tool, QStringLiteral("T210"));
    QCOMPARE(trends.at(1).days.at(0).day, QDate(2026, 3, 4));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestJointTable)

} // namespace tst_jointtable
#include "tst_jointtable.moc"
