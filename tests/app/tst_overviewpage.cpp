// OverviewPage on a real Session in demo mode (a simulated 19200 Bd wire): a port in error is
// unmistakable on its card; while the line is down the cards are greyed with the time of their
// last reading, the controls are off and the page says why; after the reconnect a control that
// failed for the lost line is no error any more; the cards share the page's height, and their
// sparklines draw the last minute; a setpoint out of range is refused, not clamped.
#include "devicetree.h"
#include "mainwindow.h"
#include "pages/overviewpage.h"
#include "pages/portcard.h"
#include "testmain.h"
#include "widgets/sparkline.h"

#include "link/simtransport.h"
#include "model/joints/jointrecord.h"
#include "sim/demoactivity.h"
#include "sim/simline.h"

#include "demosession.h"
#include "support/typing.h"

#include <QDoubleSpinBox>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTest>

namespace tst_overviewpage {

using namespace tipscope;
using namespace tipscope::model;
using tipscope::gui::DeviceTree;
using tipscope::gui::MainWindow;
using tipscope::gui::OverviewPage;
using tipscope::gui::PortCard;
using tipscope::gui::Sparkline;

namespace {
constexpr int kConnectMs = 60000;
}

class TestOverviewPage : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void init();
    void cleanup();
    void aPortInErrorIsUnmistakableOnItsCard();
    void whileTheLineIsDownTheCardsAreGreyedWithTheTimeAndTheControlsOff();
    void aControlTheLostLineRefusedIsNoErrorAfterTheReconnect();
    void theCardsShareTheHeightAndTheirSparklinesDrawTheLastMinute();
    void fourPortsFitWithoutScrollingAt1280x720();
    void thePowerIsWrittenBesideItsBarNotOnTheFill();
    void aBusyPortIsShownAtMostFiveTimesASecondAndKeptCurrent();
    void aSetpointOutOfRangeIsRefusedNotClamped();
    void theTransformerTemperatureFollowsTheTemperatureUnit();
    void eachCardShowsItsPortsLastJointAndStillFits();
    void aLineWithoutAStationSaysWhatItIsDoing();
    void noSideScrollingAtTheWindowsDefaultSizeWithAJointAndAnError_data();
    void noSideScrollingAtTheWindowsDefaultSizeWithAJointAndAnError();

private:
    void connectDemo();
    [[nodiscard]] link::SimTransport &transport() const {
        return *qobject_cast<link::SimTransport *>(&m_session->line()->transport());
    }

    std::unique_ptr<Session> m_session;
    std::unique_ptr<OverviewPage> m_page;
};

// The transformer's temperature converts with the unit as the tips' do, even when no new value
// comes: here the line is down, so nothing is read after the change.
void TestOverviewPage::theTransformerTemperatureFollowsTheTemperatureUnit() {
    connectDemo();
    QTRY_VERIFY_WITH_TIMEOUT(m_page->stationText().contains(QStringLiteral("°C")), kConnectMs);
    transport().setPlugged(false);
    QTRY_VERIFY_WITH_TIMEOUT(!m_session->station()->isLineUp(), kConnectMs);
    m_session->setTemperatureUnit(TemperatureUnit::Fahrenheit);
    QVERIFY2(m_page->stationText().contains(QStringLiteral("°F")) &&
                 !m_page->stationText().contains(QStringLiteral("°C")),
             qPrintable(m_page->stationText()));
    QVERIFY(m_page->card(1)->tipText().contains(QStringLiteral("°F")));
}

// The demo station makes a joint on port 1: its card says the recovery time and the verdict in
// words, the other cards say nothing, and the four cards still fit without scrolling.
void TestOverviewPage::eachCardShowsItsPortsLastJointAndStillFits() {
    Session::Settings settings = tipscope::testing::unpacedDemoSettings();
    settings.demoActivity = true;
    m_session->connectTo(settings);
    QTRY_VERIFY_WITH_TIMEOUT(m_session->state() == Session::State::Connected, kConnectMs);
    QVERIFY(m_page->card(4));
    QTRY_VERIFY_WITH_TIMEOUT(!m_page->card(1)->jointText().isEmpty(),
                             sim::DemoActivity::kJointOffsetMs + sim::DemoActivity::kJointEveryMs +
                                 15'000);
    const QString text = m_page->card(1)->jointText();
    QVERIFY2(text.startsWith(QStringLiteral("last joint ")) &&
                 text.endsWith(QStringLiteral(", ok")) && text.contains(QStringLiteral(" s")),
             qPrintable(text));
    QVERIFY(m_page->card(2)->jointText().isEmpty());
    auto *scroll = m_page->findChild<QScrollArea *>();
    QVERIFY(scroll);
    QTRY_COMPARE(scroll->verticalScrollBar()->maximum(), 0);
}

// A fleet tile of a line that never came up opens this page: it says what the line is doing, not
// "connect to a line", which the technician already did.
void TestOverviewPage::aLineWithoutAStationSaysWhatItIsDoing() {
    QVERIFY2(m_page->stationText().contains(QStringLiteral("Connect to a line")),
             qPrintable(m_page->stationText()));
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost));
    Session::Settings settings;
    settings.line.kind = link::LineSettings::Kind::Tcp;
    settings.line.tcpHost = QStringLiteral("127.0.0.1");
    settings.line.tcpPort = server.serverPort();
    server.close(); // nobody listens: the connection is refused
    m_session->connectTo(settings);
    QTRY_VERIFY_WITH_TIMEOUT(m_session->state() == Session::State::Retrying, kConnectMs);
    QTRY_VERIFY2_WITH_TIMEOUT(m_page->stationText().startsWith(QStringLiteral(
                                  "<i>No station on this line.</i>Cannot open tcp")) &&
                                  m_page->stationText().endsWith(QStringLiteral("refused")),
                              qPrintable(m_page->stationText()), kConnectMs);
}

void TestOverviewPage::initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("TipScopeTests"));
    QSettings().clear();
}

void TestOverviewPage::noSideScrollingAtTheWindowsDefaultSizeWithAJointAndAnError_data() {
    QTest::addColumn<QSize>("window");
    QTest::newRow("1147x692, the default on a 1280x720 screen") << QSize(1147, 692);
    QTest::newRow("1280x720") << QSize(1280, 720);
}

// Port 2's tool has the longest name; with its last joint beside it and a port in error, no
// side scroll bar hides the setpoint, power and Set button of the right-hand cards.
void TestOverviewPage::noSideScrollingAtTheWindowsDefaultSizeWithAJointAndAnError() {
    QFETCH(QSize, window);
    m_page.reset(); // the window's own page
    MainWindow w;
    w.resize(window);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    AppSettings demo;
    demo.kind = AppSettings::Kind::Demo;
    w.connectWith(demo);
    QTRY_VERIFY_WITH_TIMEOUT(w.session().station(), kConnectMs);
    StationModel *station = w.session().station();
    QVERIFY(w.deviceTree().select(DeviceTree::kBarLine, station));
    auto *page = qobject_cast<OverviewPage *>(w.page(QStringLiteral("Overview")));
    QVERIFY(page);
    w.pages().setCurrentWidget(page);
    QTRY_VERIFY_WITH_TIMEOUT(
        page->card(2) && page->card(2)->tipText().contains(QStringLiteral("°C")), kConnectMs);
    QTRY_VERIFY_WITH_TIMEOUT(page->card(2)->statusText().contains(QStringLiteral("Working")) ||
                                 page->card(2)->statusText().contains(QStringLiteral("Stand")),
                             kConnectMs);
    JointRecord joint;
    joint.device = station->identity();
    joint.port = 2;
    joint.recoveryMs = 1640;
    joint.verdict = JointVerdict::SlowRecovery;
    page->card(2)->showJoint(joint);
    w.session().demoLine()->station()->setPortError(2, 1);
    QTRY_VERIFY_WITH_TIMEOUT(page->card(2)->look() == Level::Error, kConnectMs);
    auto *scroll = page->findChild<QScrollArea *>();
    QVERIFY(scroll);
    QTRY_COMPARE(scroll->horizontalScrollBar()->maximum(), 0);
    // The joint is read at a glance: on one line, the title wrapping if one must.
    auto *jointLine = page->card(2)->findChild<QLabel *>(QStringLiteral("lastJoint"));
    QVERIFY(jointLine);
    QVERIFY2(jointLine->height() < 2 * jointLine->fontMetrics().lineSpacing(),
             qPrintable(QString::number(jointLine->height())));
    for (int port : {2, 4}) {
        PortCard *card = page->card(port);
        const QRect shown(card->mapTo(scroll->viewport(), QPoint(0, 0)), card->size());
        QVERIFY2(scroll->viewport()->rect().contains(shown.topRight()),
                 qPrintable(QStringLiteral("port %1's card ends at %2, the page at %3")
                                .arg(port)
                                .arg(shown.right())
                                .arg(scroll->viewport()->width())));
    }
}

void TestOverviewPage::init() {
    m_session = std::make_unique<Session>();
    m_page = std::make_unique<OverviewPage>(*m_session);
    m_page->resize(1040, 560);
    m_page->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_page.get()));
}

void TestOverviewPage::cleanup() {
    m_page.reset();
    m_session.reset();
}

void TestOverviewPage::connectDemo() {
    Session::Settings settings = tipscope::testing::unpacedDemoSettings();
    m_session->connectTo(settings);
    QTRY_VERIFY_WITH_TIMEOUT(m_session->state() == Session::State::Connected, kConnectMs);
    m_session->scheduler().setVisiblePorts(m_session->station(), m_page->visiblePorts());
    QVERIFY(m_page->card(4));
    QTRY_VERIFY_WITH_TIMEOUT(m_page->card(4)->tipText().contains(QStringLiteral("°C")), kConnectMs);
}

void TestOverviewPage::aPortInErrorIsUnmistakableOnItsCard() {
    connectDemo();
    QTRY_VERIFY_WITH_TIMEOUT(m_session->station()->port(1)->error().has_value(), kConnectMs);
    QCOMPARE(m_page->card(1)->look(), Level::Ok);
    m_session->demoLine()->station()->setPortError(1, 4);
    QTRY_VERIFY_WITH_TIMEOUT(m_session->station()->port(1)->error().value_or(0) != 0, kConnectMs);
    PortCard *card = m_page->card(1);
    const QString error = m_session->station()->port(1)->errorText();
    // The status line is the error in words, in colour, and the card itself changes colour.
    QVERIFY2(card->statusText().contains(QStringLiteral("Error: ") + error) &&
                 card->statusText().contains(QStringLiteral("color:")),
             qPrintable(card->statusText()));
    QVERIFY(!card->statusText().startsWith(QStringLiteral("Working")));
    QVERIFY(card->look() >= Level::Warning);
    QVERIFY2(card->styleSheet().contains(QStringLiteral("border")), qPrintable(card->styleSheet()));
    QVERIFY2(card->problemText().contains(QStringLiteral("Working")),
             qPrintable(card->problemText()));
    QCOMPARE(m_page->card(2)->look(), Level::Ok);
    QVERIFY(m_page->card(2)->styleSheet().isEmpty());
}

void TestOverviewPage::whileTheLineIsDownTheCardsAreGreyedWithTheTimeAndTheControlsOff() {
    connectDemo();
    m_session->demoLine()->station()->setPortError(4, 4);
    PortCard *noTool = m_page->card(4);
    QTRY_VERIFY_WITH_TIMEOUT(noTool->statusText().contains(QStringLiteral("color:")), kConnectMs);
    PortCard *card = m_page->card(2);
    QVERIFY(card->controlsEnabled());
    QVERIFY(card->staleText().isEmpty());
    QVERIFY(m_page->noticeText().isEmpty());
    transport().setPlugged(false);
    QTRY_VERIFY_WITH_TIMEOUT(!m_session->station()->isLineUp(), kConnectMs);
    const QDateTime last =
        m_session->station()->parameter(protocol::Role::TipTemperature, 2)->lastUpdate();
    const QString time = QLocale().toString(last.time(), QStringLiteral("HH:mm:ss"));
    QCOMPARE(card->staleText(), QStringLiteral("Not connected: last read %1").arg(time));
    QVERIFY(!card->controlsEnabled());
    QCOMPARE(card->look(), Level::Unknown);
    QVERIFY(!card->findChild<Sparkline *>()->isEnabled());
    // An error stays in words but loses its colour: amber would read as current.
    QVERIFY2(noTool->statusText().contains(QStringLiteral("Error: ")) &&
                 !noTool->statusText().contains(QStringLiteral("color:")),
             qPrintable(noTool->statusText()));
    QVERIFY2(m_page->noticeText().contains(QStringLiteral("Not connected")) &&
                 m_page->noticeText().contains(QStringLiteral("robot controls are off")),
             qPrintable(m_page->noticeText()));
    transport().setPlugged(true);
    QTRY_VERIFY_WITH_TIMEOUT(m_session->station()->isLineUp(), kConnectMs);
    QVERIFY(card->controlsEnabled());
    QVERIFY(card->staleText().isEmpty());
    QVERIFY(m_page->noticeText().isEmpty());
    QVERIFY(card->findChild<Sparkline *>()->isEnabled());
    QTRY_VERIFY2(noTool->statusText().contains(QStringLiteral("color:")),
                 qPrintable(noTool->statusText()));
}

// The page is about 1040×560 in the main window at 1280×720: the four cards share it, and no
// port hides below a scroll bar.
void TestOverviewPage::fourPortsFitWithoutScrollingAt1280x720() {
    connectDemo();
    auto *scroll = m_page->findChild<QScrollArea *>();
    QVERIFY(scroll);
    QTRY_VERIFY2(scroll->verticalScrollBar()->maximum() == 0,
                 qPrintable(QStringLiteral("%1 px to scroll, cards %2 px tall")
                                .arg(scroll->verticalScrollBar()->maximum())
                                .arg(m_page->card(1)->height())));
    PortCard *last = m_page->card(4);
    const QPoint bottom = last->mapTo(scroll->viewport(), QPoint(0, last->height()));
    QVERIFY2(bottom.y() <= scroll->viewport()->height(), qPrintable(QString::number(bottom.y())));
}

void TestOverviewPage::aControlTheLostLineRefusedIsNoErrorAfterTheReconnect() {
    connectDemo();
    PortCard *card = m_page->card(4); // the demo leaves port 4 alone, working
    transport().setPlugged(false);
    QTRY_VERIFY_WITH_TIMEOUT(!m_session->station()->isLineUp(), kConnectMs);
    QCOMPARE(card->requestMode(10), QString()); // as a shortcut would, with the buttons off
    QTRY_VERIFY_WITH_TIMEOUT(card->feedbackText().contains(QStringLiteral("not connected")),
                             kConnectMs);
    transport().setPlugged(true);
    QTRY_VERIFY_WITH_TIMEOUT(m_session->station()->isLineUp(), kConnectMs);
    QTRY_VERIFY(card->feedbackText().isEmpty());
}

void TestOverviewPage::theCardsShareTheHeightAndTheirSparklinesDrawTheLastMinute() {
    connectDemo();
    auto *spark = m_page->card(1)->findChild<Sparkline *>();
    QVERIFY(spark);
    QTRY_VERIFY_WITH_TIMEOUT(spark->rangeText().contains(QStringLiteral("°C")), kConnectMs);
    const int small = spark->height();
    // At 1920×1080 the page is about 1690×880: the room goes to the cards, not below them.
    m_page->resize(1690, 880);
    QTRY_VERIFY2(spark->height() > 2 * small, qPrintable(QString::number(spark->height())));
    PortCard *last = m_page->card(4);
    const int bottom = last->mapTo(m_page.get(), QPoint(0, last->height())).y();
    QVERIFY2(bottom > m_page->height() * 8 / 10, qPrintable(QString::number(bottom)));
}

void TestOverviewPage::aSetpointOutOfRangeIsRefusedNotClamped() {
    connectDemo();
    QTRY_VERIFY_WITH_TIMEOUT(
        m_session->station()->parameter(protocol::Role::Setpoint, 1)->value().has_value(),
        kConnectMs);
    PortCard *card = m_page->card(1);
    auto *spin = card->findChild<QDoubleSpinBox *>();
    QVERIFY(spin);
    testing::typeInto(*spin, QStringLiteral("600"), false);
    QCOMPARE(spin->text(), QStringLiteral("600 °C"));
    const qint64 writes = m_session->demoLine()->stats().writeRequests;
    QPushButton *set = nullptr;
    for (QPushButton *b : card->findChildren<QPushButton *>())
        if (b->text() == QStringLiteral("Set"))
            set = b;
    QVERIFY(set);
    set->click();
    QVERIFY2(card->feedbackText().contains(QStringLiteral("600 °C is not allowed")) &&
                 card->feedbackText().contains(QStringLiteral("500 °C")),
             qPrintable(card->feedbackText()));
    QTest::qWait(200);
    QCOMPARE(m_session->demoLine()->stats().writeRequests, writes);
}

// The unpaced demo changes a port's values far more often than a person reads them; each change
// repainted every label of the card and the setpoint box (18 % of a core for the Overview under
// X). The power text, which changes at almost every reading, is painted at most
// PortCard::kMaxRefreshesPerSecond times a second, and still follows the port.
void TestOverviewPage::aBusyPortIsShownAtMostFiveTimesASecondAndKeptCurrent() {
    connectDemo();
    PortCard *card = m_page->card(1);
    auto *text = card->findChild<QLabel *>(QStringLiteral("powerText"));
    QVERIFY(text);
    struct Count : QObject {
        int texts = 0;
        QString last;
        QLabel *label = nullptr;
        bool eventFilter(QObject *, QEvent *e) override {
            if (e->type() == QEvent::Paint && label->text() != last) {
                last = label->text();
                ++texts;
            }
            return false;
        }
    } count;
    count.label = text;
    count.last = text->text();
    text->installEventFilter(&count);
    const int answeredBefore = m_session->line()->queue().stats().answered;
    QTest::qWait(3000);
    text->removeEventFilter(&count);
    // The line answered hundreds of readings meanwhile, tens of them this port's power.
    QVERIFY(m_session->line()->queue().stats().answered - answeredBefore > 100);
    QVERIFY2(count.texts >= 2, qPrintable(QString::number(count.texts)));
    QVERIFY2(count.texts <= 3 * PortCard::kMaxRefreshesPerSecond + 1,
             qPrintable(QString::number(count.texts)));
}

// On the bar the words ran into the fill and were hard to read on its colour.
void TestOverviewPage::thePowerIsWrittenBesideItsBarNotOnTheFill() {
    connectDemo();
    PortCard *card = m_page->card(1);
    QTRY_VERIFY_WITH_TIMEOUT(card->powerText().contains(QStringLiteral("%")), kConnectMs);
    QVERIFY2(card->powerText().startsWith(QStringLiteral("power ")), qPrintable(card->powerText()));
    auto *bar = card->findChild<QProgressBar *>();
    auto *text = card->findChild<QLabel *>(QStringLiteral("powerText"));
    QVERIFY(bar && text);
    QVERIFY(!bar->isTextVisible());
    QTRY_VERIFY(text->isVisible());
    QVERIFY(!bar->geometry().intersects(text->geometry()));
    // (Once the layout has taken the latest value in: it changes several times a second.)
    QTRY_VERIFY(text->width() >= text->fontMetrics().horizontalAdvance(text->text()));
}

TIPSCOPE_TEST_MAIN(TestOverviewPage)

} // namespace tst_overviewpage
#include "tst_overviewpage.moc"
