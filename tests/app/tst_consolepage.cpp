// The raw frame console page, driven through its real widgets against the demo line (a
// simulated DME at 01 and an SFR feeder at 10). The builder's rules are tested on their own in
// tests/model/tst_framecomposer.cpp.
#include "pages/consolepage.h"
#include "pages/framebuilder.h"
#include "testmain.h"

#include "demosession.h"
#include "link/line.h"
#include "protocol/framedecoder.h"
#include "protocol/hexbytes.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <memory>

namespace tst_consolepage {

using namespace tipscope;
using tipscope::gui::ConsolePage;
using tipscope::model::ConsoleModel;
using tipscope::model::Session;

namespace {
constexpr int kConnectMs = 30000; // the demo line runs at a real 19200 baud
constexpr int kTrafficMs = 20000;
} // namespace

class TestConsolePage : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();

    void builtReadOfModelNameShowsTheAnswerInTheTable();
    void rawHexWithABadDigitShowsTheErrorAndSendsNothing();
    void everyExampleFrameThePageShowsDecodes();
    void theRawHexExampleIsAReadTheDeviceAnswers();
    void pauseHoldsRowsAndResumeShowsThem();
    void aHiddenConsoleTakesRowsInLargerBatchesAndCatchesUpWhenShown();
    void addressFilterHidesOtherDevicesRows();
    void monitorOnlyRefusesWritesAndSaysWhyButReadsGoOut();
    void saveWritesEveryRowToTheFile();
    void saveToAnUnwritablePathReportsTheError();
    void pageFollowsTheNewLineAfterReconnecting();
    void theRowCountSaysHowManyRowsAreKept();

private:
    template <class T> T *child(const char *name) const {
        T *w = m_page->findChild<T *>(QLatin1String(name));
        if (!w)
            qFatal("no child %s", name);
        return w;
    }
    void connectDemo();
    // Stops polling and waits until the line is quiet, so the test's own frames are the only ones.
    void quietLine();
    [[nodiscard]] link::RequestQueue &queue() const { return m_session->line()->queue(); }
    [[nodiscard]] QString cell(int proxyRow, int column) const {
        const QAbstractItemModel *rows = m_page->visibleRows();
        return rows->data(rows->index(proxyRow, column)).toString();
    }
    void selectDevice(const QString &address);

    std::unique_ptr<Session> m_session;
    std::unique_ptr<ConsolePage> m_page;
};

void TestConsolePage::init() {
    m_session = std::make_unique<Session>();
    // The page exists before the connection, as in the application, so it must follow the line.
    m_page = std::make_unique<ConsolePage>(*m_session);
    m_page->resize(1200, 800);
    m_page->show();
    connectDemo();
}

void TestConsolePage::cleanup() {
    m_page.reset();
    m_session.reset();
}

void TestConsolePage::connectDemo() {
    Session::Settings settings = tipscope::testing::unpacedDemoSettings();
    m_session->connectTo(settings);
    QTRY_VERIFY_WITH_TIMEOUT(m_session->state() == Session::State::Connected, kConnectMs);
    QCOMPARE(m_session->devices().size(), 2);
}

void TestConsolePage::quietLine() {
    m_session->scheduler().stop();
    QTRY_COMPARE_WITH_TIMEOUT(queue().pendingCount(), 0, kTrafficMs);
}

void TestConsolePage::selectDevice(const QString &address) {
    auto *device = child<QComboBox>("deviceCombo");
    for (int i = 0; i < device->count(); ++i)
        if (device->itemText(i).startsWith(address))
            device->setCurrentIndex(i);
    QVERIFY2(device->currentText().startsWith(address), qPrintable(device->currentText()));
}

void TestConsolePage::builtReadOfModelNameShowsTheAnswerInTheTable() {
    quietLine();
    // Discovery already read SMN; only an answer after this clear can come from our send.
    child<QAction>("clearAction")->trigger();
    QCOMPARE(m_page->consoleModel().rowCount(), 0);
    const qint64 sentBefore = queue().stats().sent;

    selectDevice(QStringLiteral("01"));
    child<QComboBox>("headerCombo")->setCurrentIndex(0); // R
    child<QComboBox>("commandCombo")->setEditText(QStringLiteral("SMN"));
    child<QLineEdit>("dataEdit")->clear();
    const QString preview = child<QLabel>("framePreview")->text();
    const QByteArray expected = protocol::Frame::read("SMN").addressed(0, 1).encode();
    QVERIFY2(preview.startsWith(protocol::toHexText(expected)), qPrintable(preview));

    auto *send = child<QPushButton>("sendFrameButton");
    QVERIFY(send->isEnabled());
    QTest::mouseClick(send, Qt::LeftButton);

    auto answerRow = [this] {
        const QAbstractItemModel *rows = m_page->visibleRows();
        for (int r = 0; r < rows->rowCount(); ++r)
            if (cell(r, ConsoleModel::Direction) == QLatin1String("RX") &&
                cell(r, ConsoleModel::Command) == QLatin1String("SMN") &&
                cell(r, ConsoleModel::Data).contains(QLatin1String("DME-2C")))
                return r;
        return -1;
    };
    QTRY_VERIFY_WITH_TIMEOUT(answerRow() >= 0, kTrafficMs);
    QCOMPARE(cell(answerRow(), ConsoleModel::Device), QStringLiteral("01→00"));
    QCOMPARE(cell(answerRow(), ConsoleModel::Bcc), QStringLiteral("ok"));
    QCOMPARE(cell(0, ConsoleModel::Hex), protocol::toHexText(expected)); // what went out, verbatim
    QCOMPARE(queue().stats().sent, sentBefore + 1);                      // once, no retries
    QTRY_VERIFY(child<QLabel>("outcomeLabel")->text().contains(QLatin1String("DME-2C")));
}

void TestConsolePage::rawHexWithABadDigitShowsTheErrorAndSendsNothing() {
    quietLine();
    const qint64 sentBefore = queue().stats().sent;
    auto *raw = child<QLineEdit>("rawHexEdit");
    auto *status = child<QLabel>("rawStatusLabel");
    raw->setText(QStringLiteral("02 30 30 30 31 52 53 4G 4E 03 5E"));
    QTest::mouseClick(child<QPushButton>("sendRawButton"), Qt::LeftButton);
    QVERIFY2(status->text().contains(QLatin1String("'G'")), qPrintable(status->text()));
    QTest::qWait(300); // anything queued would have been written by now
    QCOMPARE(queue().stats().sent, sentBefore);

    // The same field with good bytes does send, so the check above is not vacuous.
    raw->setText(protocol::toHexText(protocol::Frame::read("SMN").addressed(0, 1).encode()));
    QTest::mouseClick(child<QPushButton>("sendRawButton"), Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(queue().stats().sent, sentBefore + 1, kTrafficMs);
}

void TestConsolePage::everyExampleFrameThePageShowsDecodes() {
    // Hex that starts with STX, wherever the page shows it: placeholders, labels, tooltips.
    static const QRegularExpression frameHex(QStringLiteral("\\b02( [0-9A-Fa-f]{2}){4,}\\b"));
    QStringList shown;
    for (const QWidget *w : m_page->findChildren<QWidget *>()) {
        shown << w->toolTip();
        if (const auto *edit = qobject_cast<const QLineEdit *>(w))
            shown << edit->placeholderText() << edit->text();
        if (const auto *label = qobject_cast<const QLabel *>(w))
            shown << label->text();
    }
    int examples = 0;
    for (const QString &text : std::as_const(shown)) {
        for (const QRegularExpressionMatch &m : frameHex.globalMatch(text)) {
            ++examples;
            const auto bytes = protocol::parseHexBytes(m.captured());
            QVERIFY2(bytes, qPrintable(m.captured()));
            const auto frame = protocol::parseFrame(*bytes);
            QVERIFY2(frame, qPrintable(m.captured() + QStringLiteral(": ") + frame.error().why));
        }
    }
    QVERIFY2(examples >= 2, qPrintable(QString::number(examples))); // raw hex and the preview
}

void TestConsolePage::theRawHexExampleIsAReadTheDeviceAnswers() {
    quietLine();
    auto *raw = child<QLineEdit>("rawHexEdit");
    raw->setText(raw->placeholderText());
    QTest::mouseClick(child<QPushButton>("sendRawButton"), Qt::LeftButton);
    auto *outcome = child<QLabel>("outcomeLabel");
    QTRY_VERIFY_WITH_TIMEOUT(!outcome->text().contains(QLatin1String("waiting")), kTrafficMs);
    QVERIFY2(outcome->text().contains(QLatin1String("answered")) &&
                 outcome->text().contains(QLatin1String("DME-2C")),
             qPrintable(outcome->text()));
}

void TestConsolePage::pauseHoldsRowsAndResumeShowsThem() {
    ConsoleModel &console = m_page->consoleModel();
    auto *pause = child<QAction>("pauseAction");
    pause->trigger();
    QVERIFY(console.isPaused());
    const int rowsAtPause = console.rowCount();
    const int shownAtPause = m_page->visibleRows()->rowCount();
    const qint64 sentAtPause = queue().stats().sent;
    QTRY_VERIFY_WITH_TIMEOUT(queue().stats().sent >= sentAtPause + 3,
                             kTrafficMs); // polling goes on
    QCOMPARE(console.rowCount(), rowsAtPause);
    QCOMPARE(m_page->visibleRows()->rowCount(), shownAtPause);
    // The count of held rows is shown as they come, and stays in sight on a narrow page, where
    // the toolbar folds its last items away.
    auto *count = child<QLabel>("rowCountLabel");
    const auto heldShown = [&] {
        return count->text().endsWith(QStringLiteral("paused: %1 held").arg(console.heldCount()));
    };
    quietLine(); // a count that stands still, to compare with
    QVERIFY(console.heldCount() >= 3);
    QTRY_VERIFY2(heldShown(), qPrintable(count->text()));
    const int heldBefore = console.heldCount();
    QObject owner;
    queue().enqueue(link::Request::read(1, "SMN"), &owner);
    QTRY_VERIFY_WITH_TIMEOUT(console.heldCount() > heldBefore && queue().pendingCount() == 0,
                             kTrafficMs);
    QTRY_VERIFY2(heldShown(), qPrintable(count->text()));
    m_page->resize(700, 800);
    QTRY_VERIFY(count->isVisible());
    QVERIFY(m_page->rect().contains(count->geometry()));

    pause->trigger();
    QVERIFY(!console.isPaused());
    QVERIFY(console.rowCount() >= rowsAtPause + 3); // the held rows, at once
}

void TestConsolePage::aHiddenConsoleTakesRowsInLargerBatchesAndCatchesUpWhenShown() {
    ConsoleModel &console = m_page->consoleModel();
    m_page->setActive(false);
    console.flush();
    qint64 sentAtLastBatch = queue().stats().sent;
    QSignalSpy batches(&console, &QAbstractItemModel::rowsInserted);
    connect(&console, &QAbstractItemModel::rowsInserted, this,
            [&] { sentAtLastBatch = queue().stats().sent; });
    const qint64 sentAtHide = queue().stats().sent;
    QTest::qWait(2500);
    QVERIFY(queue().stats().sent >= sentAtHide + 10); // the line stayed busy
    // A shown console takes a batch every 100 ms; hidden, at most one a second (a slow machine
    // only makes them fewer).
    QVERIFY2(batches.count() <= 3, qPrintable(QString::number(batches.count())));
    // A request went out since the last batch, so a row waits; showing the page brings it.
    QTRY_VERIFY_WITH_TIMEOUT(queue().stats().sent > sentAtLastBatch, kTrafficMs);
    // (Counted as inserted rows: a full table drops its oldest as the new ones come.)
    const int batchesBeforeShow = int(batches.count());
    m_page->setActive(true);
    QVERIFY(batches.count() > batchesBeforeShow);
}

void TestConsolePage::addressFilterHidesOtherDevicesRows() {
    // Both devices are polled; wait until each has traffic in the table.
    auto rowsFor = [this](const QString &address) {
        const ConsoleModel &console = m_page->consoleModel();
        int n = 0;
        for (int r = 0; r < console.rowCount(); ++r)
            n += console.data(console.index(r, ConsoleModel::Device), Qt::DisplayRole)
                     .toString()
                     .contains(address);
        return n;
    };
    QTRY_VERIFY_WITH_TIMEOUT(rowsFor(QStringLiteral("10")) > 0 && rowsFor(QStringLiteral("01")) > 0,
                             kTrafficMs);

    auto *address = child<QComboBox>("addressFilter");
    QVERIFY(address->findText(QStringLiteral("10"), Qt::MatchStartsWith) >
            0); // offered from devices
    address->setEditText(QStringLiteral("10"));
    const QAbstractItemModel *shown = m_page->visibleRows();
    QVERIFY(shown->rowCount() > 0);
    for (int r = 0; r < shown->rowCount(); ++r)
        QVERIFY2(cell(r, ConsoleModel::Device).contains(QLatin1String("10")),
                 qPrintable(cell(r, ConsoleModel::Device)));

    // Back to every device, RX chunks included (they are off by default), shows every row.
    address->setEditText(QStringLiteral("All"));
    child<QCheckBox>("showRx")->setChecked(true);
    QCOMPARE(shown->rowCount(), m_page->consoleModel().rowCount());
}

void TestConsolePage::monitorOnlyRefusesWritesAndSaysWhyButReadsGoOut() {
    quietLine();
    selectDevice(QStringLiteral("01"));
    auto *header = child<QComboBox>("headerCombo");
    auto *send = child<QPushButton>("sendFrameButton");
    auto *sendRaw = child<QPushButton>("sendRawButton");
    auto *hint = child<QLabel>("hintLabel");
    auto *rawStatus = child<QLabel>("rawStatusLabel");
    header->setCurrentIndex(1); // W
    child<QComboBox>("commandCombo")->setEditText(QStringLiteral("MAT"));
    child<QLineEdit>("dataEdit")->setText(QStringLiteral("00450"));
    QVERIFY(send->isEnabled());
    QVERIFY(sendRaw->isEnabled());

    m_session->setMonitorOnly(true);
    QVERIFY(!send->isEnabled());
    QVERIFY(send->toolTip().contains(QLatin1String("Monitor-only")));
    QVERIFY(!sendRaw->isEnabled());
    QVERIFY(sendRaw->toolTip().contains(QLatin1String("Monitor-only")));
    // Where the person looks, not only in a tooltip.
    QVERIFY2(hint->text().startsWith(QLatin1String("Monitor-only")), qPrintable(hint->text()));
    QVERIFY2(rawStatus->text().startsWith(QLatin1String("Monitor-only")),
             qPrintable(rawStatus->text()));

    // Return in the fields does not get around the disabled buttons, and says so.
    const qint64 sentBefore = queue().stats().sent;
    QTest::keyClick(child<QLineEdit>("dataEdit"), Qt::Key_Return);
    QVERIFY2(
        child<QLabel>("outcomeLabel")->text().endsWith(QLatin1String("monitor-only mode is on")),
        qPrintable(child<QLabel>("outcomeLabel")->text()));
    auto *raw = child<QLineEdit>("rawHexEdit");
    raw->setText(
        protocol::toHexText(protocol::Frame::write("MAT", "00450").addressed(0, 1).encode()));
    QVERIFY(!sendRaw->isEnabled());
    QTest::keyClick(raw, Qt::Key_Return);
    QTest::qWait(300);
    QCOMPARE(queue().stats().sent, sentBefore);

    // Reads go out, composed or typed.
    raw->setText(protocol::toHexText(protocol::Frame::read("SMN").addressed(0, 1).encode()));
    QVERIFY(sendRaw->isEnabled());
    QTest::mouseClick(sendRaw, Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(queue().stats().sent, sentBefore + 1, kTrafficMs);
    header->setCurrentIndex(0); // R
    child<QComboBox>("commandCombo")->setEditText(QStringLiteral("SMN"));
    child<QLineEdit>("dataEdit")->clear();
    QVERIFY(send->isEnabled());

    m_session->setMonitorOnly(false);
    header->setCurrentIndex(1);
    QVERIFY(send->isEnabled());
    QVERIFY(sendRaw->isEnabled());
}

void TestConsolePage::saveWritesEveryRowToTheFile() {
    ConsoleModel &console = m_page->consoleModel();
    QTRY_VERIFY_WITH_TIMEOUT(console.rowCount() > 5, kTrafficMs);
    child<QAction>("pauseAction")->trigger(); // a fixed set of rows to compare with
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("console.txt"));
    const auto saved = m_page->saveTo(path);
    QVERIFY2(saved.ok(), qPrintable(saved.error()));

    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
    const QStringList lines =
        QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), console.rowCount() + 1); // a header line, then every row
    QVERIFY(lines.first().contains(QLatin1String("Hex")));
    QCOMPARE(lines.last(), console.lineText(console.rowCount() - 1));
    QVERIFY(lines.join(QLatin1Char('\n')).contains(QLatin1String("SMN")));
}

void TestConsolePage::saveToAnUnwritablePathReportsTheError() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("missing/console.txt"));
    const auto saved = m_page->saveTo(path);
    QVERIFY(!saved.ok());
    QVERIFY2(saved.error().startsWith(QStringLiteral("cannot write %1: ").arg(path)),
             qPrintable(saved.error()));
}

void TestConsolePage::pageFollowsTheNewLineAfterReconnecting() {
    ConsoleModel &console = m_page->consoleModel();
    // Nothing runs the event loop between this clear and the reconnection, so every row after
    // it comes from the new line. The old line is deleted before the new one is built, so the
    // new one may even reuse its address; the page must still attach to it.
    child<QAction>("clearAction")->trigger();
    connectDemo();
    auto discoveryRows = [&console] {
        int n = 0;
        for (int r = 0; r < console.rowCount(); ++r)
            n += console.entry(r).direction == model::ConsoleEntry::Direction::Tx &&
                 console.entry(r).frame && console.entry(r).frame->command == "SMN";
        return n;
    };
    QVERIFY(discoveryRows() > 0);
}

// A busy line fills the console in a few minutes; the oldest rows going is said, not found out.
void TestConsolePage::theRowCountSaysHowManyRowsAreKept() {
    auto *count = child<QLabel>("rowCountLabel");
    QTRY_VERIFY(m_page->visibleRows()->rowCount() > 0);
    QTRY_VERIFY2(count->text().endsWith(
                     QStringLiteral("; the newest %1 are kept").arg(QLocale().toString(20000))),
                 qPrintable(count->text()));
    // The layout follows a new text on the event loop.
    QTRY_VERIFY2(
        count->width() >= count->fontMetrics().horizontalAdvance(count->text()),
        qPrintable(QStringLiteral("%1 px for \"%2\"").arg(count->width()).arg(count->text())));
}

TIPSCOPE_TEST_MAIN(TestConsolePage)

} // namespace tst_consolepage
#include "tst_consolepage.moc"
