// CountersPage on a real Session in demo mode: the simulated DME at 01 (port 1 starts at 1200
// plugged hours) and the SFR at 10 (partial plugged hours start at 12).
#include "pages/counterspage.h"
#include "testmain.h"

#include "demosession.h"
#include "protocol/frame.h"
#include "sim/simline.h"

#include <QAbstractButton>
#include <QApplication>
#include <QHeaderView>
#include <QMessageBox>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

namespace tst_counterspage {

using namespace tipscope;
using namespace tipscope::model;
using tipscope::gui::CountersPage;

namespace {

constexpr int kConnectMs = 60000;
constexpr int kReadMs = 60000;

// Clicks the button of `role` on the next modal QMessageBox and keeps what the box said; the
// page runs the box with exec(), so this has to poll from inside that event loop.
class MessageBoxAnswerer : public QObject {
public:
    explicit MessageBoxAnswerer(QMessageBox::ButtonRole role)
        : m_role(role) {
        connect(&m_timer, &QTimer::timeout, this, &MessageBoxAnswerer::poll);
        m_timer.start(20);
    }
    [[nodiscard]] bool answered() const { return m_answered; }
    [[nodiscard]] QString text() const { return m_text; }

private:
    void poll() {
        auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
        if (!box)
            return;
        for (QAbstractButton *button : box->buttons()) {
            if (box->buttonRole(button) != m_role)
                continue;
            m_text = box->text() + QLatin1Char('\n') + box->informativeText();
            m_answered = true;
            m_timer.stop();
            button->click();
            return;
        }
    }

    QMessageBox::ButtonRole m_role;
    QTimer m_timer;
    bool m_answered = false;
    QString m_text;
};

int rowNamed(const QTableWidget *table, const QString &name) {
    for (int r = 0; r < table->rowCount(); ++r)
        if (table->verticalHeaderItem(r) && table->verticalHeaderItem(r)->text() == name)
            return r;
    return -1;
}

// A counter as the page shows it: the locale's digit grouping, then the unit.
QString shown(qint64 value, const char *unit) {
    return QLocale().toString(value) + QLatin1Char(' ') + QLatin1String(unit);
}

QString cellText(const QTableWidget *table, const QString &row, int column) {
    const int r = rowNamed(table, row);
    const QTableWidgetItem *item = r >= 0 ? table->item(r, column) : nullptr;
    return item ? item->text() : QString();
}

} // namespace

class TestCountersPage : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();

    void tablesFollowDevicesAsTheyComeAndGo();
    void stationTableShowsTheSimulatorsPluggedHoursPerPort();
    void feederTableShowsTotalsAndPartials();
    void refreshReadsCountersThatAreOtherwiseNotPolled();
    void exportCsvRoundTripsHeaderAndValues();
    void exportCsvToAnUnwritablePathSaysWhy();
    void declinedPartialResetAsksAndChangesNothing();
    void acceptedPartialResetResetsTheSimulatorCounter();
    void monitorOnlyDisablesThePartialResets();

private:
    void connectDemo();
    void readCountersNow();
    [[nodiscard]] QTableWidget *stationTable() const {
        return m_page->findChild<QTableWidget *>(QStringLiteral("stationCounters"));
    }
    [[nodiscard]] QTableWidget *feederTable() const {
        return m_page->findChild<QTableWidget *>(QStringLiteral("feederCounters"));
    }
    [[nodiscard]] QPushButton *resetButton(const char *code) const {
        return m_page->findChild<QPushButton *>(QLatin1String("reset") + QLatin1String(code));
    }
    [[nodiscard]] qint64 simulatorValue(const QByteArray &code) const {
        return m_session->demoLine()
            ->feeder()
            ->handle(protocol::Frame::read(code))
            .data.toLongLong();
    }
    [[nodiscard]] int simulatorWrites(const QByteArray &code) const {
        const QString prefix = QString::fromLatin1(code + '=');
        int n = 0;
        for (const QString &w : m_session->demoLine()->feeder()->acceptedWrites())
            n += w.startsWith(prefix) ? 1 : 0;
        return n;
    }

    std::unique_ptr<Session> m_session;
    std::unique_ptr<CountersPage> m_page;
};

void TestCountersPage::init() {
    m_session = std::make_unique<Session>();
    // The page exists before the devices do, as in the application.
    m_page = std::make_unique<CountersPage>(*m_session);
    m_page->resize(1000, 700);
    m_page->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_page.get()));
}

void TestCountersPage::cleanup() {
    m_page.reset();
    m_session.reset();
}

void TestCountersPage::connectDemo() {
    Session::Settings settings = tipscope::testing::unpacedDemoSettings();
    m_session->connectTo(settings);
    QTRY_VERIFY_WITH_TIMEOUT(m_session->state() == Session::State::Connected &&
                                 m_session->station() && m_session->feeder(),
                             kConnectMs);
}

// At start-up the scheduler reads every setting before the counters; tests about what the page
// does with the values read them at once instead (the page follows the parameters either way).
void TestCountersPage::readCountersNow() {
    for (PortModel *port : m_session->station()->ports())
        for (Parameter *p : port->counters())
            p->refresh();
    for (Parameter *p : m_session->feeder()->counters())
        p->refresh();
}

void TestCountersPage::tablesFollowDevicesAsTheyComeAndGo() {
    QVERIFY(!stationTable());
    QVERIFY(!feederTable());
    connectDemo();
    QVERIFY(stationTable());
    QVERIFY(feederTable());
    QCOMPARE(stationTable()->columnCount(), m_session->station()->ports().size());
    QCOMPARE(stationTable()->rowCount(), 7); // plugged, work, sleep, hibernation, no tool, 2 cycles

    m_session->disconnectFromLine();
    QVERIFY(!stationTable());
    QVERIFY(!feederTable());
    // Nothing on the page still reaches the deleted devices.
    m_page->refresh();
    m_page->resetPartial("CPP");
    QTemporaryDir dir;
    QVERIFY(m_page->exportCsv(dir.filePath(QStringLiteral("empty.csv"))).ok());

    connectDemo();
    QVERIFY(stationTable());
    QTRY_VERIFY_WITH_TIMEOUT(
        cellText(stationTable(), QStringLiteral("Plugged hours"), 0) == shown(1200, "h"), kReadMs);
}

void TestCountersPage::stationTableShowsTheSimulatorsPluggedHoursPerPort() {
    connectDemo();
    QTableWidget *table = stationTable();
    QVERIFY(table);
    QVERIFY(rowNamed(table, QStringLiteral("Plugged hours")) >= 0);
    QCOMPARE(table->horizontalHeaderItem(0)->text(), QStringLiteral("Port 1"));
    // The simulated DME starts port n at 1200 + 37 (n - 1) plugged hours.
    QTRY_COMPARE_WITH_TIMEOUT(cellText(table, QStringLiteral("Plugged hours"), 0), shown(1200, "h"),
                              kReadMs);
    QTRY_COMPARE_WITH_TIMEOUT(cellText(table, QStringLiteral("Plugged hours"), 1), shown(1237, "h"),
                              kReadMs);
}

void TestCountersPage::feederTableShowsTotalsAndPartials() {
    connectDemo();
    QTableWidget *table = feederTable();
    QVERIFY(table);
    QCOMPARE(table->horizontalHeaderItem(0)->text(), QStringLiteral("Total"));
    QCOMPARE(table->horizontalHeaderItem(1)->text(), QStringLiteral("Partial"));
    QTRY_COMPARE_WITH_TIMEOUT(cellText(table, QStringLiteral("Plugged hours"), 0), shown(512, "h"),
                              kReadMs);
    QTRY_COMPARE_WITH_TIMEOUT(cellText(table, QStringLiteral("Plugged hours"), 1), shown(12, "h"),
                              kReadMs);
    QTRY_COMPARE_WITH_TIMEOUT(cellText(table, QStringLiteral("Fed length"), 0), shown(2450, "m"),
                              kReadMs);
}

void TestCountersPage::refreshReadsCountersThatAreOtherwiseNotPolled() {
    m_session->scheduler().setInterval(PollClass::Counter, 0); // once, then only on request
    connectDemo();
    QTRY_COMPARE_WITH_TIMEOUT(cellText(feederTable(), QStringLiteral("Plugged hours"), 1),
                              shown(12, "h"), kReadMs);
    // Behind TipScope's back, as the feeder's own keys would.
    (void)m_session->demoLine()->feeder()->handle(protocol::Frame::write("CPP", "00000"));
    QCOMPARE(simulatorValue("CPP"), 0);
    QTest::qWait(500);
    QCOMPARE(cellText(feederTable(), QStringLiteral("Plugged hours"), 1), shown(12, "h"));

    auto *refresh = m_page->findChild<QPushButton *>(QStringLiteral("refreshCounters"));
    QVERIFY(refresh && refresh->isEnabled());
    refresh->click();
    QTRY_COMPARE_WITH_TIMEOUT(cellText(feederTable(), QStringLiteral("Plugged hours"), 1),
                              shown(0, "h"), kReadMs);
}

void TestCountersPage::exportCsvRoundTripsHeaderAndValues() {
    connectDemo();
    readCountersNow();
    QTRY_COMPARE_WITH_TIMEOUT(cellText(stationTable(), QStringLiteral("Plugged hours"), 0),
                              shown(1200, "h"), kReadMs);
    QTRY_COMPARE_WITH_TIMEOUT(cellText(feederTable(), QStringLiteral("Plugged hours"), 1),
                              shown(12, "h"), kReadMs);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("counters.csv"));
    const auto saved = m_page->exportCsv(path);
    QVERIFY2(saved.ok(), qPrintable(saved.error()));

    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QStringList lines =
        QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QVERIFY(!lines.isEmpty());
    QCOMPARE(lines.first(), QStringLiteral("device,port,counter,value,unit"));
    const QString station = m_session->station()->displayName();
    const QString feeder = m_session->feeder()->displayName();
    QVERIFY2(lines.contains(station + QStringLiteral(",1,Plugged hours,1200,h")),
             qPrintable(lines.join(QLatin1Char('\n'))));
    QVERIFY(lines.contains(feeder + QStringLiteral(",,Plugged hours (partial),12,h")));
    // Every counter of every port and of the feeder, one a line.
    const int ports = int(m_session->station()->ports().size());
    QCOMPARE(lines.size(), 1 + ports * 7 + 6);
}

void TestCountersPage::exportCsvToAnUnwritablePathSaysWhy() {
    connectDemo();
    const auto saved = m_page->exportCsv(QStringLiteral("/nonexistent-dir/counters.csv"));
    QVERIFY(!saved.ok());
    QVERIFY2(
        saved.error().startsWith(QStringLiteral("cannot write /nonexistent-dir/counters.csv: ")),
        qPrintable(saved.error()));
}

void TestCountersPage::declinedPartialResetAsksAndChangesNothing() {
    connectDemo();
    readCountersNow();
    QTRY_COMPARE_WITH_TIMEOUT(cellText(feederTable(), QStringLiteral("Plugged hours"), 1),
                              shown(12, "h"), kReadMs);
    QPushButton *reset = resetButton("CPP");
    QVERIFY(reset);
    QTRY_VERIFY(reset->isEnabled());
    Action *action = m_session->feeder()->action("CPP");
    QVERIFY(action);

    MessageBoxAnswerer cancel(QMessageBox::RejectRole);
    reset->click();
    QVERIFY(cancel.answered());
    // The question says what will happen.
    QVERIFY2(cancel.text().contains(action->danger()), qPrintable(cancel.text()));
    QVERIFY(cancel.text().contains(shown(12, "h")));
    // Nothing was started (an Action is running from the moment it queues its write) ...
    QVERIFY(!action->isRunning());
    QCOMPARE(simulatorWrites("CPP"), 0);
    // ... and nothing arrives later either.
    QTest::qWait(1000);
    QCOMPARE(simulatorWrites("CPP"), 0);
    QCOMPARE(simulatorValue("CPP"), 12);
    QCOMPARE(cellText(feederTable(), QStringLiteral("Plugged hours"), 1), shown(12, "h"));
}

void TestCountersPage::acceptedPartialResetResetsTheSimulatorCounter() {
    connectDemo();
    readCountersNow();
    QTRY_COMPARE_WITH_TIMEOUT(cellText(feederTable(), QStringLiteral("Feeding hours"), 1),
                              shown(3, "h"), kReadMs);
    QPushButton *reset = resetButton("CFP");
    QVERIFY(reset);
    QTRY_VERIFY(reset->isEnabled());

    MessageBoxAnswerer accept(QMessageBox::DestructiveRole);
    reset->click();
    QVERIFY(accept.answered());
    QTRY_COMPARE_WITH_TIMEOUT(simulatorValue("CFP"), 0, kReadMs);
    QCOMPARE(simulatorWrites("CFP"), 1);
    // Only the partial counter it named.
    QCOMPARE(simulatorValue("CPP"), 12);
    QCOMPARE(simulatorValue("CFT"), 140);
    // The page reads the counter back rather than waiting a minute for the next poll.
    QTRY_COMPARE_WITH_TIMEOUT(cellText(feederTable(), QStringLiteral("Feeding hours"), 1),
                              shown(0, "h"), kReadMs);
}

void TestCountersPage::monitorOnlyDisablesThePartialResets() {
    connectDemo();
    const char *codes[] = {"CPP", "CFP", "CTP"};
    for (const char *code : codes) {
        QVERIFY(resetButton(code));
        QVERIFY(resetButton(code)->isEnabled());
    }
    m_session->setMonitorOnly(true);
    for (const char *code : codes) {
        QVERIFY(!resetButton(code)->isEnabled());
        QVERIFY(resetButton(code)->toolTip().contains(QLatin1String("Monitor-only")));
    }
    // The method behind the buttons refuses too, without asking.
    MessageBoxAnswerer accept(QMessageBox::DestructiveRole);
    m_page->resetPartial("CPP");
    QVERIFY(!accept.answered());
    QVERIFY(!m_session->feeder()->action("CPP")->isRunning());
    QCOMPARE(simulatorWrites("CPP"), 0);

    m_session->setMonitorOnly(false);
    for (const char *code : codes)
        QVERIFY(resetButton(code)->isEnabled());
}

TIPSCOPE_TEST_MAIN(TestCountersPage)

} // namespace tst_counterspage
#include "tst_counterspage.moc"
