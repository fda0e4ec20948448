// The Joints page on real widgets: history read from a real journal file (written by
// journal::Journal), the demo station's live joints listed once even when the journal has them
// too, the filters narrowing the table and its charts, the verdict in words, icon and tint, the
// CSV export, and a joint opened on the Charts page at its moment.
#include "charts/chartspage.h"
#include "pages/jointcharts.h"
#include "pages/jointspage.h"
#include "testmain.h"

#include "i18n/translations.h"
#include "journal/journal.h"
#include "sim/demoactivity.h"

#include "demosession.h"

#include <QApplication>
#include <QDialog>
#include <QFile>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>

namespace tst_jointspage {

using namespace tipscope;
using namespace tipscope::model;
using gui::JointsPage;

namespace {
constexpr qint64 kHourMs = 3600'000;
constexpr qint64 kDayMs = 24 * kHourMs;
constexpr int kFirstJointMs =
    sim::DemoActivity::kJointOffsetMs + sim::DemoActivity::kJointEveryMs + 15'000;
const DeviceIdentity kDeviceA{QStringLiteral("/dev/ttyUSB0"), 0, QStringLiteral("DME-2C"),
                              QStringLiteral("9996780")};
const DeviceIdentity kDeviceB{QStringLiteral("/dev/ttyUSB1"), 0, QStringLiteral("DDE-2C"),
                              QStringLiteral("9997010")};

struct Planned {
    DeviceIdentity device;
    int port;
    QString tool;
    JointVerdict verdict;
    QString workOrder;
    qint64 agoMs;
};

// Six joints over forty days, on two devices, two tools, every verdict and two work orders.
const QList<Planned> kPlanned = {
    {kDeviceA, 1, "C245", JointVerdict::Ok, "WO-1", kHourMs / 2},
    {kDeviceA, 2, "C245", JointVerdict::SlowRecovery, "WO-1", 3 * kHourMs},
    {kDeviceA, 1, "T210", JointVerdict::TooDeep, "WO-2", 2 * kDayMs},
    {kDeviceB, 1, "C245", JointVerdict::Ok, "WO-2", 26 * kHourMs},
    {kDeviceB, 1, "C245", JointVerdict::Incomplete, "", 10 * kDayMs},
    {kDeviceA, 1, "C245", JointVerdict::Ok, "WO-1", 40 * kDayMs},
};

JointRecord jointOf(const Planned &p, qint64 nowMs) {
    JointRecord j;
    j.device = p.device;
    j.port = p.port;
    j.tool = p.tool;
    j.startMs = nowMs - p.agoMs;
    j.endMs = j.startMs + 2000;
    j.setpoint = 350;
    j.lowestTip = 320;
    j.dipDepth = 30;
    if (p.verdict != JointVerdict::Incomplete)
        j.recoveryMs = p.verdict == JointVerdict::SlowRecovery ? 4500 : 1200;
    j.durationMs = 2000;
    j.powerPeak = 80;
    j.powerIntegral = 60;
    j.verdict = p.verdict;
    return j;
}

// A real journal file holding `joints`, each under its work order.
bool writeJournal(const QString &path, const QList<QPair<JointRecord, QString>> &joints) {
    journal::Journal journal(path);
    for (const auto &[joint, workOrder] : joints) {
        journal.setContext(WorkContext{workOrder, {}, {}});
        journal.append(joint);
    }
    return journal.flush();
}

bool writePlanned(const QString &path) {
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    QList<QPair<JointRecord, QString>> joints;
    for (const Planned &p : kPlanned)
        joints.append({jointOf(p, now), p.workOrder});
    return writeJournal(path, joints);
}

int rowsWithKey(const JointsPage &page, const QString &key) {
    int n = 0;
    for (const JointRow &r : page.table().rows())
        n += jointKey(r.joint) == key ? 1 : 0;
    return n;
}
} // namespace

class TestJointsPage : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void historyIsReadFromTheJournalNewestFirstWithItsWorkOrder();
    void aMissingJournalIsNoHistoryAndNoError();
    void anUnreadableJournalSaysWhyOnThePage();
    void aJournalBeyondTheLimitListsTheNewestAndSaysSo();
    void filtersNarrowTheTableAndItsCharts_data();
    void filtersNarrowTheTableAndItsCharts();
    void theVerdictShowsInWordsIconAndTint();
    void temperaturesFollowTheSessionsUnit();
    void theExportHoldsTheListedJoints();
    void aFailedExportSaysWhyOnThePage();
    void aJointWithoutReadingsSaysSoInsteadOfAnEmptyChart();
    void liveJointsAreListedOnceAndOpenTheChartsAtTheirMoment();

private:
    QTemporaryDir m_dir;
};

void TestJointsPage::initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    // English plurals ("4 joints") come from the English translation, as in the application.
    QCOMPARE(i18n::installTranslators(*QCoreApplication::instance(), QStringLiteral("en")),
             QStringLiteral("en"));
    QVERIFY(m_dir.isValid());
    QVERIFY(writePlanned(m_dir.filePath(QStringLiteral("planned.sqlite"))));
}

void TestJointsPage::historyIsReadFromTheJournalNewestFirstWithItsWorkOrder() {
    Session session;
    JointsPage page(session);
    page.setJournalPath(m_dir.filePath(QStringLiteral("planned.sqlite")));
    QCOMPARE(page.table().rowCount(), 4); // the last 7 days
    const auto &rows = page.table().rows();
    for (int i = 1; i < rows.size(); ++i)
        QVERIFY(rows.at(i - 1).joint.startMs > rows.at(i).joint.startMs);
    QCOMPARE(rows.at(0).joint.tool, QStringLiteral("C245"));
    QCOMPARE(page.table().index(0, JointTableModel::WorkOrder).data().toString(),
             QStringLiteral("WO-1"));
    QCOMPARE(page.table().index(2, JointTableModel::WorkOrder).data().toString(),
             QStringLiteral("WO-2"));
    QVERIFY2(page.statusText().startsWith(QStringLiteral("4 joints listed.")),
             qPrintable(page.statusText()));
    QVERIFY(!page.statusText().contains(QStringLiteral("journal")));
}

void TestJointsPage::aMissingJournalIsNoHistoryAndNoError() {
    Session session;
    JointsPage page(session);
    const QString path = m_dir.filePath(QStringLiteral("none-yet.sqlite"));
    page.setJournalPath(path);
    QCOMPARE(page.table().rowCount(), 0);
    QVERIFY2(!page.statusText().contains(QStringLiteral("could not")),
             qPrintable(page.statusText()));
    QVERIFY2(page.statusText().contains(QStringLiteral("No journal yet")),
             qPrintable(page.statusText()));
    QVERIFY(!QFile::exists(path)); // reading never creates the file
}

void TestJointsPage::anUnreadableJournalSaysWhyOnThePage() {
    const QString path = m_dir.filePath(QStringLiteral("damaged.sqlite"));
    QFile damaged(path);
    QVERIFY(damaged.open(QIODevice::WriteOnly));
    damaged.write(QByteArray(8192, 'x'));
    damaged.close();
    Session session;
    JointsPage page(session);
    page.setJournalPath(path);
    QCOMPARE(page.table().rowCount(), 0);
    QVERIFY2(page.statusText().startsWith(QStringLiteral("The journal could not be read (")),
             qPrintable(page.statusText()));
    for (const QWidget *w : QApplication::topLevelWidgets()) // no popup: the page says it
        QVERIFY(!qobject_cast<const QDialog *>(w) || !w->isVisible());
}

void TestJointsPage::aJournalBeyondTheLimitListsTheNewestAndSaysSo() {
    const QString path = m_dir.filePath(QStringLiteral("full.sqlite"));
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    QList<QPair<JointRecord, QString>> joints;
    for (int i = 0; i <= JointsPage::kHistoryLimit; ++i) {
        Planned p = kPlanned.first();
        p.agoMs = kHourMs + i * 1000LL;
        joints.append({jointOf(p, now), p.workOrder});
    }
    QVERIFY(writeJournal(path, joints));
    Session session;
    JointsPage page(session);
    page.setJournalPath(path);
    QCOMPARE(page.table().rowCount(), JointsPage::kHistoryLimit);
    QCOMPARE(page.table().row(0).joint.startMs, now - kHourMs);
    QVERIFY2(page.statusText().contains(QStringLiteral("Only the newest 5000 from the journal")),
             qPrintable(page.statusText()));
    // Narrowed below the limit, the page no longer says it.
    page.setRangeFilter(0);
    QVERIFY(page.table().rowCount() < JointsPage::kHistoryLimit);
    QVERIFY2(!page.statusText().contains(QStringLiteral("Only the newest")),
             qPrintable(page.statusText()));
}

void TestJointsPage::filtersNarrowTheTableAndItsCharts_data() {
    QTest::addColumn<QString>("device");
    QTest::addColumn<int>("port");
    QTest::addColumn<QString>("tool");
    QTest::addColumn<int>("verdict"); // -1: all
    QTest::addColumn<int>("range");   // index into JointsPage::kRangeHours
    QTest::addColumn<QString>("workOrder");
    QTest::addColumn<int>("rows");
    const int week = JointsPage::kDefaultRange;
    QTest::newRow("last 7 days") << "" << 0 << "" << -1 << week << "" << 4;
    QTest::newRow("last hour") << "" << 0 << "" << -1 << 0 << "" << 1;
    QTest::newRow("last 24 hours") << "" << 0 << "" << -1 << 1 << "" << 2;
    QTest::newRow("last 30 days") << "" << 0 << "" << -1 << 3 << "" << 5;
    QTest::newRow("all times") << "" << 0 << "" << -1 << 4 << "" << 6;
    QTest::newRow("device") << kDeviceB.key() << 0 << "" << -1 << week << "" << 1;
    QTest::newRow("port") << "" << 2 << "" << -1 << week << "" << 1;
    QTest::newRow("tool") << "" << 0 << "T210" << -1 << week << "" << 1;
    QTest::newRow("verdict") << "" << 0 << "" << int(JointVerdict::Ok) << week << "" << 2;
    QTest::newRow("work order") << "" << 0 << "" << -1 << week << "WO-2" << 2;
    QTest::newRow("device, tool, all times") << kDeviceA.key() << 0 << "C245" << -1 << 4 << "" << 3;
}

void TestJointsPage::filtersNarrowTheTableAndItsCharts() {
    QFETCH(QString, device);
    QFETCH(int, port);
    QFETCH(QString, tool);
    QFETCH(int, verdict);
    QFETCH(int, range);
    QFETCH(QString, workOrder);
    QFETCH(int, rows);
    Session session;
    JointsPage page(session);
    page.setJournalPath(m_dir.filePath(QStringLiteral("planned.sqlite")));
    page.setDeviceFilter(device);
    page.setPortFilter(port);
    page.setToolFilter(tool);
    page.setVerdictFilter(verdict < 0 ? std::nullopt
                                      : std::optional<JointVerdict>(JointVerdict(verdict)));
    page.setRangeFilter(range);
    page.setWorkOrderFilter(workOrder);
    QCOMPARE(page.table().rowCount(), rows);
    QCOMPARE(page.view().model()->rowCount(), rows);
    // The histogram counts exactly the listed joints, recovered or not.
    page.flushCharts();
    const RecoveryHistogram &h = page.histogramView().histogram();
    int counted = h.notRecovered;
    for (const int n : h.counts)
        counted += n;
    QCOMPARE(counted, rows);
}

void TestJointsPage::theVerdictShowsInWordsIconAndTint() {
    Session session;
    JointsPage page(session);
    page.setJournalPath(m_dir.filePath(QStringLiteral("planned.sqlite")));
    const QAbstractItemModel &shown = *page.view().model();
    const QModelIndex ok = shown.index(0, JointTableModel::Verdict);
    const QModelIndex slow = shown.index(1, JointTableModel::Verdict);
    QCOMPARE(ok.data().toString(), QStringLiteral("ok"));
    QCOMPARE(slow.data().toString(), QStringLiteral("slow recovery"));
    QVERIFY(!ok.data(Qt::DecorationRole).value<QIcon>().isNull());
    QVERIFY(!slow.data(Qt::DecorationRole).value<QIcon>().isNull());
    QVERIFY(ok.data(Qt::DecorationRole).value<QIcon>().cacheKey() !=
            slow.data(Qt::DecorationRole).value<QIcon>().cacheKey());
    // The broken limit tints the whole row; a good joint stays plain.
    QVERIFY(shown.index(1, JointTableModel::Time).data(Qt::BackgroundRole).isValid());
    QVERIFY(!shown.index(0, JointTableModel::Time).data(Qt::BackgroundRole).isValid());
}

void TestJointsPage::temperaturesFollowTheSessionsUnit() {
    Session session;
    JointsPage page(session);
    page.setJournalPath(m_dir.filePath(QStringLiteral("planned.sqlite")));
    const QModelIndex setpoint = page.view().model()->index(0, JointTableModel::Setpoint);
    QCOMPARE(setpoint.data().toString(), QStringLiteral("350 °C"));
    session.setTemperatureUnit(TemperatureUnit::Fahrenheit);
    QCOMPARE(setpoint.data().toString(), QStringLiteral("662 °F"));
}

void TestJointsPage::theExportHoldsTheListedJoints() {
    Session session;
    JointsPage page(session);
    page.setJournalPath(m_dir.filePath(QStringLiteral("planned.sqlite")));
    page.setWorkOrderFilter(QStringLiteral("WO-1"));
    QCOMPARE(page.table().rowCount(), 2);
    const QString path = m_dir.filePath(QStringLiteral("joints.csv"));
    QCOMPARE(page.exportCsv(path), QString());
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(file.readAll()).trimmed().split(QLatin1Char('\n'));
    QCOMPARE(lines.size(), 3);
    QVERIFY(lines.at(0).startsWith(QStringLiteral("time,device,port,tool,setpoint [°C]")));
    QVERIFY2(lines.at(1).contains(kDeviceA.key() + QStringLiteral(",1,C245,350,320.0,30.0,1.200,")),
             qPrintable(lines.at(1)));
    QVERIFY2(lines.at(1).endsWith(QStringLiteral(",ok,WO-1")), qPrintable(lines.at(1)));
    QVERIFY2(lines.at(2).endsWith(QStringLiteral(",slow recovery,WO-1")), qPrintable(lines.at(2)));
    QVERIFY2(page.statusText().contains(QStringLiteral("2 joints written to")),
             qPrintable(page.statusText()));
}

void TestJointsPage::aFailedExportSaysWhyOnThePage() {
    Session session;
    JointsPage page(session);
    page.setJournalPath(m_dir.filePath(QStringLiteral("planned.sqlite")));
    const QString path = m_dir.filePath(QStringLiteral("no such folder/joints.csv"));
    const QString why = page.exportCsv(path);
    QVERIFY(why.startsWith(QStringLiteral("cannot write")));
    QCOMPARE(page.statusText(), why);
    QVERIFY(!QFile::exists(path));
}

void TestJointsPage::aJointWithoutReadingsSaysSoInsteadOfAnEmptyChart() {
    Session session;
    JointsPage page(session);
    gui::ChartsPage charts(session);
    page.setChartsPage(&charts);
    page.setJournalPath(m_dir.filePath(QStringLiteral("planned.sqlite")));
    QSignalSpy shown(&page, &JointsPage::chartsShown);
    QVERIFY(shown.isValid());
    const QString why = page.openJoint(0);
    QVERIFY2(why.startsWith(QStringLiteral("The charts hold no readings of DME-2C")),
             qPrintable(why));
    QCOMPARE(page.statusText(), why);
    QVERIFY(shown.isEmpty());
}

void TestJointsPage::liveJointsAreListedOnceAndOpenTheChartsAtTheirMoment() {
    const QString path = m_dir.filePath(QStringLiteral("live.sqlite"));
    Session session;
    JointsPage page(session);
    gui::ChartsPage charts(session);
    page.setChartsPage(&charts);
    page.setJournalPath(path); // not written: the table fills from the session alone
    page.setWorkOrder(QStringLiteral("WO-9"));
    Session::Settings settings = testing::unpacedDemoSettings();
    settings.demoActivity = true;
    session.connectTo(settings);
    QTRY_VERIFY_WITH_TIMEOUT(page.table().rowCount() > 0, kFirstJointMs);
    const JointRecord live = page.table().row(0).joint;
    QCOMPARE(live.device, session.station()->identity());
    QCOMPARE(page.table().row(0).workOrder, QStringLiteral("WO-9"));
    // The count follows the live joints; the line still says where the history is (none yet).
    QVERIFY2(page.statusText().contains(QStringLiteral("joint")) &&
                 page.statusText().endsWith(
                     QStringLiteral("No journal yet: this session's joints only.")),
             qPrintable(page.statusText()));

    // The journal gets the same joint; read back, it is still one row.
    QVERIFY(writeJournal(path, {{live, QStringLiteral("WO-9")}}));
    page.reload();
    QCOMPARE(rowsWithKey(page, jointKey(live)), 1);
    QVERIFY2(!page.statusText().contains(QStringLiteral("journal")), qPrintable(page.statusText()));

    // Enter on the joint shows the charts around it, paused there.
    QSignalSpy shown(&page, &JointsPage::chartsShown);
    QVERIFY(shown.isValid());
    page.view().setCurrentIndex(page.view().model()->index(0, 0));
    QTest::keyClick(&page.view(), Qt::Key_Return);
    QCOMPARE(shown.size(), 1);
    QCOMPARE(shown.first().first().value<QWidget *>(), &charts);
    QVERIFY(!charts.viewport().isFollowing());
    // What came before the joint is shown too, not the joint at the left edge.
    QVERIFY2(charts.viewport().start() <= live.startMs - 5'000 &&
                 charts.viewport().end() >= live.endMs,
             qPrintable(QStringLiteral("%1..%2 for %3..%4")
                            .arg(charts.viewport().start())
                            .arg(charts.viewport().end())
                            .arg(live.startMs)
                            .arg(live.endMs)));
}

TIPSCOPE_TEST_MAIN(TestJointsPage)

} // namespace tst_jointspage
#include "tst_jointspage.moc"
