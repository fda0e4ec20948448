// ErrorsPage on a real Session in demo mode: the simulated DME at 01 and SFR at 10, with errors
// and alarms injected into the simulator.
#include "pages/errorspage.h"
#include "testmain.h"

#include "demosession.h"
#include "sim/simline.h"
#include "sim/simstation.h"

#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollBar>
#include <QTableView>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

namespace tst_errorspage {

using namespace tipscope;
using namespace tipscope::model;
using tipscope::gui::ErrorsPage;

namespace {

constexpr int kConnectMs = 60000;
constexpr int kReadMs = 30000;
enum StateColumn { Where, Tool, Severity, Error, Alarm };
enum HistoryColumn { Time, HistorySeverity, Kind, Source, Text };

// The current-state row whose "Where" cell is exactly `where` (the port's tool may follow).
int stateRow(const QTableWidget *table, const QString &where) {
    for (int r = 0; r < table->rowCount(); ++r) {
        const QTableWidgetItem *item = table->item(r, Where);
        if (item && (item->text() == where || item->text().startsWith(where + QLatin1String(" ("))))
            return r;
    }
    return -1;
}

QString stateText(const QTableWidget *table, const QString &where, int column) {
    const int r = stateRow(table, where);
    const QTableWidgetItem *item = r >= 0 ? table->item(r, column) : nullptr;
    return item ? item->text() : QString();
}

// Rows of the history view (after filtering) whose columns contain the given texts.
int historyRows(const QTableView *view, const QString &source, const QString &text) {
    const QAbstractItemModel *m = view->model();
    int n = 0;
    for (int r = 0; r < m->rowCount(); ++r)
        if (m->index(r, Source).data().toString().contains(source) &&
            m->index(r, Text).data().toString().contains(text))
            ++n;
    return n;
}

} // namespace

class TestErrorsPage : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void init();
    void cleanup();

    void injectedPortErrorShowsInCurrentStateAndHistory();
    void latchedAlarmShowsAsWarningOnItsPort();
    void feederErrorShowsAndResetClearsItInTheSimulator();
    void monitorOnlyBlocksTheFeederReset();
    void rowsFollowDevicesAsTheyComeAndGo();
    void historyFiltersByKindSeverityAndText();
    void newestEventComesFirstAndStaysInViewUnlessTheReaderScrolledDown();
    void copyPutsTheSelectedRowsOnTheClipboard();
    void exportTextWritesTheShownRowsTabSeparated();
    void aFloodOfOneWarningIsOneRowWithItsCountAndSpan();
    void aLongSourceIsShownWhole();
    void whatToCheckLeavesTheHistoryItsRows();

private:
    void connectDemo();
    [[nodiscard]] QTableWidget *state() const {
        return m_page->findChild<QTableWidget *>(QStringLiteral("currentState"));
    }
    [[nodiscard]] QTableView *history() const {
        return m_page->findChild<QTableView *>(QStringLiteral("history"));
    }
    [[nodiscard]] QPushButton *resetButton() const {
        return m_page->findChild<QPushButton *>(QStringLiteral("resetFeederError"));
    }
    [[nodiscard]] QString portName(int port) const {
        return QStringLiteral("%1, port %2").arg(m_session->station()->displayName()).arg(port);
    }
    void addEvents(int n, const QString &text);

    std::unique_ptr<Session> m_session;
    std::unique_ptr<ErrorsPage> m_page;
};

void TestErrorsPage::init() {
    m_session = std::make_unique<Session>();
    m_session->scheduler().setInterval(PollClass::Status, 200); // errors show up sooner
    // The page exists before the devices do, as in the application.
    m_page = std::make_unique<ErrorsPage>(*m_session);
    m_page->resize(1100, 800);
    m_page->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_page.get()));
    QVERIFY(state());
    QVERIFY(history());
    QVERIFY(resetButton());
}

void TestErrorsPage::cleanup() {
    m_page.reset();
    m_session.reset();
}

void TestErrorsPage::connectDemo() {
    Session::Settings settings = tipscope::testing::unpacedDemoSettings();
    m_session->connectTo(settings);
    QTRY_VERIFY_WITH_TIMEOUT(m_session->state() == Session::State::Connected &&
                                 m_session->station() && m_session->feeder(),
                             kConnectMs);
}

void TestErrorsPage::addEvents(int n, const QString &text) {
    for (int i = 0; i < n; ++i)
        m_session->eventLog().add(Event::Kind::Write, Event::Severity::Info, QStringLiteral("test"),
                                  text.arg(i));
}

void TestErrorsPage::injectedPortErrorShowsInCurrentStateAndHistory() {
    connectDemo();
    QTRY_COMPARE_WITH_TIMEOUT(stateText(state(), portName(2), Severity), QStringLiteral("OK"),
                              kReadMs);
    QCOMPARE(historyRows(history(), portName(2), QStringLiteral("Short circuit")), 0);

    m_session->demoLine()->station()->setPortError(2, 1);
    QTRY_COMPARE_WITH_TIMEOUT(stateText(state(), portName(2), Error),
                              QStringLiteral("Short circuit"), kReadMs);
    QCOMPARE(stateText(state(), portName(2), Severity), QStringLiteral("Error"));
    QCOMPARE(stateText(state(), portName(1), Severity), QStringLiteral("OK"));
    // What to check is said in words under the table, not hidden in a tooltip.
    auto *advice = m_page->findChild<QLabel *>(QStringLiteral("errorAdvice"));
    QVERIFY(advice);
    QVERIFY(advice->isVisibleTo(m_page.get()));
    QVERIFY2(advice->text().contains(portName(2)) &&
                 advice->text().contains(QStringLiteral("cartridge is seated")),
             qPrintable(advice->text()));
    QTRY_COMPARE_WITH_TIMEOUT(historyRows(history(), portName(2), QStringLiteral("Short circuit")),
                              1, kReadMs);
    const QAbstractItemModel *m = history()->model();
    int row = -1;
    for (int r = 0; r < m->rowCount(); ++r)
        if (m->index(r, Text).data().toString() == QLatin1String("Short circuit"))
            row = r;
    QVERIFY(row >= 0);
    QCOMPARE(m->index(row, Kind).data().toString(), QStringLiteral("Port error"));
    QCOMPARE(m->index(row, HistorySeverity).data().toString(), QStringLiteral("Error"));
    QVERIFY(m->index(row, Time).data().toString().contains(QLatin1Char(':')));

    // Cleared in the station: the state follows, and the history keeps both facts.
    m_session->demoLine()->station()->setPortError(2, 0);
    QTRY_COMPARE_WITH_TIMEOUT(stateText(state(), portName(2), Severity), QStringLiteral("OK"),
                              kReadMs);
    QTRY_COMPARE_WITH_TIMEOUT(historyRows(history(), portName(2), QStringLiteral("error cleared")),
                              1, kReadMs);
    QVERIFY(!advice->isVisibleTo(m_page.get()));
}

void TestErrorsPage::latchedAlarmShowsAsWarningOnItsPort() {
    connectDemo();
    QTRY_COMPARE_WITH_TIMEOUT(stateText(state(), portName(3), Alarm), QStringLiteral("None"),
                              kReadMs);
    m_session->demoLine()->station()->latchAlarm(3, 1);
    QTRY_VERIFY_WITH_TIMEOUT(
        stateText(state(), portName(3), Alarm).contains(QLatin1String("High temperature")),
        kReadMs);
    QCOMPARE(stateText(state(), portName(3), Severity), QStringLiteral("Warning"));
    // An alarm has what to check in words too, as an error has.
    auto *advice = m_page->findChild<QLabel *>(QStringLiteral("errorAdvice"));
    QVERIFY(advice);
    QTRY_VERIFY(advice->isVisibleTo(m_page.get()));
    QVERIFY2(advice->text().contains(portName(3) + QStringLiteral(", High temperature alarm: ")) &&
                 advice->text().contains(QStringLiteral("high alarm limit")),
             qPrintable(advice->text()));
    // The station row has no alarm column of its own.
    QCOMPARE(stateText(state(), m_session->station()->displayName(), Alarm), QString());
}

void TestErrorsPage::feederErrorShowsAndResetClearsItInTheSimulator() {
    connectDemo();
    const QString feeder = m_session->feeder()->displayName();
    QTRY_COMPARE_WITH_TIMEOUT(stateText(state(), feeder, Severity), QStringLiteral("OK"), kReadMs);
    QTRY_VERIFY(resetButton()->isEnabled());

    m_session->demoLine()->feeder()->setError(3);
    QTRY_VERIFY_WITH_TIMEOUT(
        stateText(state(), feeder, Error).contains(QLatin1String("Feeder error 3")), kReadMs);
    QCOMPARE(stateText(state(), feeder, Severity), QStringLiteral("Error"));

    resetButton()->click();
    QTRY_COMPARE_WITH_TIMEOUT(m_session->demoLine()->feeder()->error(), 0, kReadMs);
    QTRY_COMPARE_WITH_TIMEOUT(stateText(state(), feeder, Severity), QStringLiteral("OK"), kReadMs);
    QTRY_COMPARE_WITH_TIMEOUT(historyRows(history(), feeder, QStringLiteral("Feeder error 3")), 1,
                              kReadMs);
}

void TestErrorsPage::monitorOnlyBlocksTheFeederReset() {
    connectDemo();
    QTRY_VERIFY(resetButton()->isEnabled());
    m_session->demoLine()->feeder()->setError(3);
    m_session->setMonitorOnly(true);
    QVERIFY(!resetButton()->isEnabled());
    QVERIFY(resetButton()->toolTip().contains(QLatin1String("Monitor-only")));
    // The method behind the button refuses too.
    m_page->resetFeederError();
    QVERIFY(!m_session->feeder()->action("ECV")->isRunning());
    QTest::qWait(500);
    QCOMPARE(m_session->demoLine()->feeder()->error(), 3);

    m_session->setMonitorOnly(false);
    QVERIFY(resetButton()->isEnabled());
}

void TestErrorsPage::rowsFollowDevicesAsTheyComeAndGo() {
    QCOMPARE(stateRow(state(), QStringLiteral("No device is connected.")), 0);
    QVERIFY(!resetButton()->isEnabled());
    connectDemo();
    const int ports = int(m_session->station()->ports().size());
    QCOMPARE(state()->rowCount(), 1 + ports + 1); // station, its ports, feeder
    QVERIFY(stateRow(state(), portName(ports)) >= 0);

    m_session->disconnectFromLine();
    QCOMPARE(state()->rowCount(), 1);
    QCOMPARE(stateRow(state(), QStringLiteral("No device is connected.")), 0);
    QVERIFY(!resetButton()->isEnabled());
    m_page->resetFeederError(); // nothing to reset, nothing dangling
    // The history keeps what happened, including the disconnection.
    QTRY_VERIFY(historyRows(history(), QString(), QStringLiteral("disconnected")) >= 1);

    connectDemo();
    QCOMPARE(state()->rowCount(), 1 + ports + 1);
    QTRY_COMPARE_WITH_TIMEOUT(stateText(state(), portName(1), Severity), QStringLiteral("OK"),
                              kReadMs);
    // The connected tool, by name, next to its port.
    QTRY_VERIFY_WITH_TIMEOUT(m_session->station()->port(1)->tool().has_value(), kReadMs);
    QCOMPARE(stateText(state(), portName(1), Tool), m_session->station()->port(1)->toolName());
    QVERIFY(stateText(state(), portName(1), Tool).startsWith(QLatin1Char('T')));
}

void TestErrorsPage::historyFiltersByKindSeverityAndText() {
    EventLog &log = m_session->eventLog();
    log.add(Event::Kind::Write, Event::Severity::Info, QStringLiteral("DME-2C at 01"),
            QStringLiteral("Max temperature set to 400 °C"));
    log.add(Event::Kind::Communication, Event::Severity::Warning, QStringLiteral("SFR-A at 10"),
            QStringLiteral("reading Feeding speed: timeout"));
    log.add(Event::Kind::PortError, Event::Severity::Error, QStringLiteral("DME-2C at 01, port 2"),
            QStringLiteral("Short circuit"));
    log.add(Event::Kind::Alarm, Event::Severity::Warning, QStringLiteral("DME-2C at 01, port 1"),
            QStringLiteral("High temperature alarm"));
    const QAbstractItemModel *m = history()->model();
    QTRY_COMPARE(m->rowCount(), 4);

    auto *kind = m_page->findChild<QComboBox *>(QStringLiteral("kindFilter"));
    auto *severity = m_page->findChild<QComboBox *>(QStringLiteral("severityFilter"));
    auto *text = m_page->findChild<QLineEdit *>(QStringLiteral("textFilter"));
    QVERIFY(kind && severity && text);

    kind->setCurrentIndex(kind->findText(QStringLiteral("Errors and alarms")));
    QCOMPARE(m->rowCount(), 2);
    severity->setCurrentIndex(severity->findText(QStringLiteral("Errors only")));
    QCOMPARE(m->rowCount(), 1);
    QCOMPARE(m->index(0, Text).data().toString(), QStringLiteral("Short circuit"));

    kind->setCurrentIndex(0);
    severity->setCurrentIndex(severity->findText(QStringLiteral("Warnings and errors")));
    QCOMPARE(m->rowCount(), 3);
    text->setText(QStringLiteral("TIMEOUT")); // any column, any case
    QCOMPARE(m->rowCount(), 1);
    QCOMPARE(m->index(0, Source).data().toString(), QStringLiteral("SFR-A at 10"));
    text->setText(QStringLiteral("port 1"));
    QCOMPARE(m->rowCount(), 1);
    QCOMPARE(m->index(0, Kind).data().toString(), QStringLiteral("Alarm"));
    text->clear();
    severity->setCurrentIndex(0);
    QCOMPARE(m->rowCount(), 4);

    // New events pass through the same filters.
    kind->setCurrentIndex(kind->findText(QStringLiteral("Port errors")));
    log.add(Event::Kind::PortError, Event::Severity::Error, QStringLiteral("DME-2C at 01, port 4"),
            QStringLiteral("Open circuit"));
    log.add(Event::Kind::Write, Event::Severity::Info, QStringLiteral("DME-2C at 01"),
            QStringLiteral("saved"));
    QTRY_COMPARE(m->rowCount(), 2);
}

void TestErrorsPage::newestEventComesFirstAndStaysInViewUnlessTheReaderScrolledDown() {
    QTableView *view = history();
    addEvents(300, QStringLiteral("event %1"));
    QTRY_COMPARE(view->model()->rowCount(), 300);
    const QAbstractItemModel *m = view->model();
    auto topRowText = [view, m] { return m->index(view->rowAt(0), Text).data().toString(); };
    QVERIFY(view->verticalScrollBar()->maximum() > 0); // there is something to scroll
    QCOMPARE(m->index(0, Text).data().toString(), QStringLiteral("event 299"));
    QTRY_COMPARE(topRowText(), QStringLiteral("event 299"));
    addEvents(5, QStringLiteral("more %1"));
    QTRY_COMPARE(m->rowCount(), 305);
    QCOMPARE(m->index(0, Text).data().toString(), QStringLiteral("more 4"));
    QTRY_COMPARE(topRowText(), QStringLiteral("more 4"));

    // Someone reading back through the history keeps the rows they read in front of them.
    view->verticalScrollBar()->setValue(100);
    const QString reading = topRowText();
    addEvents(5, QStringLiteral("later %1"));
    QTRY_COMPARE(m->rowCount(), 310);
    QCOMPARE(topRowText(), reading);
    QCOMPARE(m->index(0, Text).data().toString(), QStringLiteral("later 4"));
}

void TestErrorsPage::copyPutsTheSelectedRowsOnTheClipboard() {
    addEvents(5, QStringLiteral("event %1"));
    QTableView *view = history();
    QTRY_COMPARE(view->model()->rowCount(), 5);
    auto *copy = m_page->findChild<QPushButton *>(QStringLiteral("copyEvents"));
    QVERIFY(copy);
    QVERIFY(!copy->isEnabled()); // nothing selected yet
    QApplication::clipboard()->clear();

    view->selectionModel()->select(view->model()->index(3, 0),
                                   QItemSelectionModel::Select | QItemSelectionModel::Rows);
    view->selectionModel()->select(view->model()->index(1, 0),
                                   QItemSelectionModel::Select | QItemSelectionModel::Rows);
    QVERIFY(copy->isEnabled());
    copy->click();
    const QStringList lines =
        QApplication::clipboard()->text().split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 2);
    QVERIFY2(lines[0].endsWith(QLatin1String("\tInfo\tWrite\ttest\tevent 1")),
             qPrintable(lines[0]));
    QVERIFY2(lines[1].endsWith(QLatin1String("\tevent 3")), qPrintable(lines[1]));
    // The full date is on the clipboard, not only the time shown in the table.
    QVERIFY(lines[0].startsWith(QDate::currentDate().toString(Qt::ISODate)) ||
            lines[0].startsWith(QDate::currentDate().addDays(-1).toString(Qt::ISODate)));
}

void TestErrorsPage::exportTextWritesTheShownRowsTabSeparated() {
    m_session->eventLog().add(Event::Kind::PortError, Event::Severity::Error,
                              QStringLiteral("DME-2C at 01, port 2"),
                              QStringLiteral("Short circuit"));
    m_session->eventLog().add(Event::Kind::Write, Event::Severity::Info,
                              QStringLiteral("DME-2C at 01"),
                              QStringLiteral("a\ttab and\na line break"));
    QTRY_COMPARE(history()->model()->rowCount(), 2);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("events.txt"));
    const auto saved = m_page->exportText(path);
    QVERIFY2(saved.ok(), qPrintable(saved.error()));

    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QStringList lines =
        QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 3);
    QCOMPARE(lines[0], QStringLiteral("Time\tSeverity\tKind\tSource\tWhat happened"));
    const QStringList fields = lines[1].split(QLatin1Char('\t'));
    QCOMPARE(fields.size(), 5);
    QCOMPARE(fields.mid(1), QStringList({QStringLiteral("Error"), QStringLiteral("Port error"),
                                         QStringLiteral("DME-2C at 01, port 2"),
                                         QStringLiteral("Short circuit")}));
    // A tab or a line break inside a text does not break the one-event-a-line format.
    QCOMPARE(lines[2].split(QLatin1Char('\t')).size(), 5);

    const auto refused = m_page->exportText(QStringLiteral("/nonexistent-dir/events.txt"));
    QVERIFY(!refused.ok());
    QVERIFY2(
        refused.error().startsWith(QStringLiteral("cannot write /nonexistent-dir/events.txt: ")),
        qPrintable(refused.error()));
}

void TestErrorsPage::aFloodOfOneWarningIsOneRowWithItsCountAndSpan() {
    const int before = history()->model()->rowCount();
    for (int i = 0; i < 75; ++i)
        m_session->eventLog().add(Event::Kind::Communication, Event::Severity::Warning,
                                  QStringLiteral("DME-2C at 01"),
                                  QStringLiteral("not sent: the line is not connected"));
    QTRY_COMPARE(history()->model()->rowCount(), before + 1);
    const QString text = history()->model()->index(0, Text).data().toString(); // the newest
    QVERIFY2(
        text.startsWith(QStringLiteral("not sent: the line is not connected (75 times, until ")),
        qPrintable(text));
}

// A device named by its workspace line, in German: "DME-2C, Adresse 01, Port 4" was cut before
// its port in a column sized for the English "DME-2C at 01, port 4".
void TestErrorsPage::aLongSourceIsShownWhole() {
    const QString source = QStringLiteral("Rework station B, Adresse 01, Port 4");
    m_session->eventLog().add(Event::Kind::PortError, Event::Severity::Error, source,
                              QStringLiteral("Short circuit"));
    QTableView *view = history();
    QTRY_COMPARE(view->model()->rowCount(), 1);
    QCOMPARE(view->model()->index(0, Source).data().toString(), source);
    const QRect cell = view->visualRect(view->model()->index(0, Source));
    QVERIFY2(cell.width() > view->fontMetrics().horizontalAdvance(source) + 8,
             qPrintable(QStringLiteral("%1 px for %2 px of text")
                            .arg(cell.width())
                            .arg(view->fontMetrics().horizontalAdvance(source))));
    QVERIFY(cell.right() < view->viewport()->width()); // what happened still has its room
}

// At 1280x720 the page is about 1040x590. Three ports in error and one in alarm have much to
// check; the history still shows five rows, not two or three.
void TestErrorsPage::whatToCheckLeavesTheHistoryItsRows() {
    m_page->resize(1040, 590);
    connectDemo();
    sim::SimStation *station = m_session->demoLine()->station();
    station->setPortError(1, 1);
    station->setPortError(2, 1);
    station->setPortError(4, 1);
    station->latchAlarm(3, 1);
    auto *advice = m_page->findChild<QLabel *>(QStringLiteral("errorAdvice"));
    QVERIFY(advice);
    QTRY_VERIFY_WITH_TIMEOUT(advice->text().count(QStringLiteral("• ")) == 4, kReadMs);
    QTRY_VERIFY(advice->isVisibleTo(m_page.get()));
    QTableView *view = history();
    const int rowHeight = view->verticalHeader()->defaultSectionSize();
    QTRY_VERIFY2(view->viewport()->height() >= 5 * rowHeight,
                 qPrintable(QStringLiteral("%1 rows of history shown")
                                .arg(view->viewport()->height() / rowHeight)));
}

TIPSCOPE_TEST_MAIN(TestErrorsPage)

} // namespace tst_errorspage
#include "tst_errorspage.moc"
