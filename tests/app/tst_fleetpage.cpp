// FleetPage on a workspace of in-process demo lines (each a DME and an SFR): a tile per device
// with the names the workspace gives them; sorted by name, line or state (a port in error first);
// filtered to those that need attention; a click opens the device it shows; a line taken down
// greys its tiles and says since when; the tiles go from one column to several as the page
// widens; a tile repaints only when what it shows changed, and says how late it was.
#include "pages/fleet/fleetpage.h"
#include "pages/fleet/fleettilewidget.h"
#include "testmain.h"

#include "model/workspace/workspace.h"

#include "link/simtransport.h"
#include "sim/simline.h"
#include "sim/simstation.h"

#include "demoworkspace.h"
#include "fullbacklog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTest>

namespace tst_fleetpage {

using namespace tipscope;
using namespace tipscope::model;
using tipscope::gui::FleetPage;
using tipscope::gui::FleetTileWidget;
using tipscope::testing::demoTransport;
using tipscope::testing::demoWorkspaceLine;

namespace {
constexpr int kConnectMs = 60000;

QStringList shownNames(const FleetPage &page) {
    QStringList names;
    for (const FleetTileWidget *tile : page.shownTiles())
        names.append(tile->shown().deviceName);
    return names;
}

// Every line has found its devices and every station tile shows all its ports read.
bool stationsRead(const FleetPage &page) {
    for (const FleetTileWidget *tile : page.shownTiles()) {
        if (!tile->tile().device())
            return false;
        for (const FleetPortState &p : tile->shown().ports)
            if (!p.tip || !p.setpoint)
                return false;
    }
    return page.tileCount() > 0;
}

// A loopback port nobody listens on: connecting is refused at once.
quint16 refusingPort() {
    QTcpServer server;
    if (!server.listen(QHostAddress::LocalHost))
        return 0;
    return server.serverPort();
}
} // namespace

class TestFleetPage : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void aTilePerDeviceWithTheNamesTheWorkspaceGives();
    void tilesSortByNameLineAndStateWithTheWorstFirst();
    void theFilterShowsOnlyTheDevicesThatNeedAttention();
    void aClickOpensTheDeviceOfItsLine();
    void aLineTakenDownGreysItsTilesAndSaysSinceWhen();
    void theColumnsGrowWithTheWidth();
    void aTileRepaintsOnlyWhenWhatItShowsChangedAndSaysHowLate();
    void aLineJoiningAddsItsTilesAndKeepsTheOthers();
    void aLineWithoutADeviceHasATileThatSaysWhy();
    void aLineStillConnectingSaysSoNotThatItLooksForDevices();

private:
    [[nodiscard]] FleetTileWidget *tileNamed(const QString &name) const;

    std::unique_ptr<Workspace> m_workspace;
    std::unique_ptr<FleetPage> m_page;
};

void TestFleetPage::init() {
    m_workspace = std::make_unique<Workspace>();
    m_page = std::make_unique<FleetPage>(*m_workspace);
    m_page->resize(1200, 800);
    m_page->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_page.get()));
    QVERIFY(testing::openDemoWorkspace(
        *m_workspace, {demoWorkspaceLine(QStringLiteral("line-b"), QStringLiteral("Cell 2"),
                                         QStringLiteral("Robot 10"), QStringLiteral("Feeder 10")),
                       demoWorkspaceLine(QStringLiteral("line-a"), QStringLiteral("Cell 1"),
                                         QStringLiteral("Robot 9"), QStringLiteral("Feeder 9")),
                       demoWorkspaceLine(QStringLiteral("line-c"), QStringLiteral("Cell 3"),
                                         QStringLiteral("Robot 2"), QStringLiteral("Feeder 2"))}));
    QTRY_VERIFY_WITH_TIMEOUT(stationsRead(*m_page), kConnectMs);
}

void TestFleetPage::cleanup() {
    m_page.reset();
    m_workspace.reset();
}

FleetTileWidget *TestFleetPage::tileNamed(const QString &name) const {
    for (FleetTileWidget *tile : m_page->shownTiles())
        if (tile->shown().deviceName == name)
            return tile;
    return nullptr;
}

void TestFleetPage::aTilePerDeviceWithTheNamesTheWorkspaceGives() {
    QCOMPARE(m_page->tileCount(), 6);
    QCOMPARE(m_page->shownTiles().size(), 6);
    FleetTileWidget *robot = tileNamed(QStringLiteral("Robot 9"));
    QVERIFY(robot);
    const QStringList lines = robot->lines();
    QCOMPARE(lines.first(), QStringLiteral("Robot 9"));
    QCOMPARE(lines.at(1), QStringLiteral("line-a · Cell 1 · ") +
                              m_workspace->session(1)->station()->info().model);
    // A row per port, with its tip temperature and setpoint.
    QCOMPARE(lines.filter(QRegularExpression(QStringLiteral("^P\\d .*°C / .*°C"))).size(), 4);
    QVERIFY(tileNamed(QStringLiteral("Feeder 2")));
    QCOMPARE(m_page->summaryText(), QStringLiteral("Devices: 6 · need attention: 0"));
}

void TestFleetPage::tilesSortByNameLineAndStateWithTheWorstFirst() {
    m_page->setSortKey(FleetSortKey::Name);
    QCOMPARE(shownNames(*m_page).join(QLatin1Char(',')),
             QStringLiteral("Feeder 2,Feeder 9,Feeder 10,Robot 2,Robot 9,Robot 10"));
    m_page->setSortKey(FleetSortKey::Line);
    QCOMPARE(shownNames(*m_page).join(QLatin1Char(',')),
             QStringLiteral("Feeder 9,Robot 9,Feeder 10,Robot 10,Feeder 2,Robot 2"));
    QCOMPARE(m_page->findChild<QComboBox *>()->currentData().toInt(), int(FleetSortKey::Line));
    // The combo box sorts too; a port in error puts its station first, as it happens.
    QComboBox *sort = m_page->findChild<QComboBox *>();
    sort->setCurrentIndex(sort->findData(int(FleetSortKey::State)));
    QCOMPARE(m_page->sortKey(), FleetSortKey::State);
    m_workspace->session(0)->demoLine()->station()->setPortError(3, 4);
    QTRY_COMPARE_WITH_TIMEOUT(shownNames(*m_page).first(), QStringLiteral("Robot 10"), kConnectMs);
    QCOMPARE(shownNames(*m_page).size(), 6);
}

void TestFleetPage::theFilterShowsOnlyTheDevicesThatNeedAttention() {
    m_page->setAttentionOnly(true);
    QVERIFY(m_page->findChild<QCheckBox *>()->isChecked());
    QVERIFY(m_page->shownTiles().isEmpty());
    QCOMPARE(m_page->tileCount(), 6);
    m_workspace->session(2)->demoLine()->station()->setPortError(1, 4);
    QTRY_COMPARE_WITH_TIMEOUT(shownNames(*m_page), QStringList{QStringLiteral("Robot 2")},
                              kConnectMs);
    FleetTileWidget *robot = tileNamed(QStringLiteral("Robot 2"));
    QVERIFY(robot->isVisible());
    QVERIFY2(robot->lines().filter(QStringLiteral("Port 1: ")).size() == 1,
             qPrintable(robot->lines().join(QLatin1Char('\n'))));
    QCOMPARE(m_page->summaryText(), QStringLiteral("Devices: 6 · need attention: 1"));
    m_page->findChild<QCheckBox *>()->setChecked(false);
    QVERIFY(!m_page->attentionOnly());
    QCOMPARE(m_page->shownTiles().size(), 6);
}

void TestFleetPage::aClickOpensTheDeviceOfItsLine() {
    QSignalSpy activated(m_page.get(), &FleetPage::deviceActivated);
    QVERIFY(activated.isValid());
    FleetTileWidget *feeder = tileNamed(QStringLiteral("Feeder 10"));
    QVERIFY(feeder);
    QTest::mouseClick(feeder, Qt::LeftButton, {}, feeder->rect().center());
    QCOMPARE(activated.size(), 1);
    QCOMPARE(activated.at(0).at(0).toInt(), 0);
    QCOMPARE(activated.at(0).at(1).value<DeviceModel *>(),
             static_cast<DeviceModel *>(m_workspace->session(0)->feeder()));
    FleetTileWidget *robot = tileNamed(QStringLiteral("Robot 2"));
    robot->setFocus();
    QTest::keyClick(robot, Qt::Key_Return);
    QCOMPARE(activated.size(), 2);
    QCOMPARE(activated.at(1).at(0).toInt(), 2);
    QCOMPARE(activated.at(1).at(1).value<DeviceModel *>(),
             static_cast<DeviceModel *>(m_workspace->session(2)->station()));
}

void TestFleetPage::aLineTakenDownGreysItsTilesAndSaysSinceWhen() {
    demoTransport(*m_workspace, 1).setPlugged(false);
    FleetTileWidget *robot = tileNamed(QStringLiteral("Robot 9"));
    QTRY_VERIFY_WITH_TIMEOUT(!robot->shown().lineUp, kConnectMs);
    const QString down = robot->lines().at(2);
    QVERIFY2(down.startsWith(QStringLiteral("Line down since ")), qPrintable(down));
    // Each tile is repainted at its own turn of the refresh period: the feeder's may come later.
    QTRY_VERIFY_WITH_TIMEOUT(tileNamed(QStringLiteral("Feeder 9"))->lines().contains(down), 2000);
    QVERIFY(tileNamed(QStringLiteral("Robot 10"))->shown().lineUp);
    QVERIFY(robot->shown().needsAttention());
    // Greyed: drawn with the palette's disabled colours, not the tile's usual base.
    const QImage image = robot->grab().toImage();
    const QColor inside = image.pixelColor(image.width() - 4, image.height() - 4);
    QCOMPARE(inside, robot->palette().color(QPalette::Disabled, QPalette::Window));
    const QImage live = tileNamed(QStringLiteral("Robot 10"))->grab().toImage();
    QVERIFY(live.pixelColor(live.width() - 4, live.height() - 4) != inside);
    demoTransport(*m_workspace, 1).setPlugged(true);
    QTRY_VERIFY_WITH_TIMEOUT(robot->shown().lineUp, kConnectMs);
    QVERIFY(!robot->lines().join(QLatin1Char('\n')).contains(QStringLiteral("Line down")));
}

void TestFleetPage::theColumnsGrowWithTheWidth() {
    const int tileWidth = m_page->shownTiles().first()->sizeHint().width();
    m_page->resize(tileWidth + tileWidth / 2, 800);
    QTRY_COMPARE(m_page->columnCount(), 1);
    m_page->resize(tileWidth * 7, 800);
    QTRY_VERIFY(m_page->columnCount() >= 5);
    m_page->resize(tileWidth * 3, 800);
    QTRY_COMPARE(m_page->columnCount(), 2);
}

void TestFleetPage::aTileRepaintsOnlyWhenWhatItShowsChangedAndSaysHowLate() {
    m_page->clearTileLatencies();
    QVERIFY(m_page->tileLatenciesMs().empty());
    FleetTileWidget *robot = tileNamed(QStringLiteral("Robot 9"));
    // A tile brought up to date has nothing more to repaint until something arrives.
    m_page->refreshNow();
    QVERIFY(!robot->refresh());
    // The demo tips wander by a degree or so: readings that change a tile come, and are timed.
    QTRY_VERIFY_WITH_TIMEOUT(!m_page->tileLatenciesMs().empty(), kConnectMs);
    for (double ms : m_page->tileLatenciesMs())
        QVERIFY(ms >= 0);
    m_page->clearTileLatencies();
    QVERIFY(m_page->tileLatenciesMs().empty());
}

void TestFleetPage::aLineJoiningAddsItsTilesAndKeepsTheOthers() {
    FleetTileWidget *robot = tileNamed(QStringLiteral("Robot 9"));
    QVERIFY(m_workspace
                ->addLine(demoWorkspaceLine(QStringLiteral("line-d"), {}, QStringLiteral("Robot 1"),
                                            QStringLiteral("Feeder 1")))
                .ok());
    QTRY_COMPARE_WITH_TIMEOUT(m_page->tileCount(), 8, kConnectMs);
    QCOMPARE(tileNamed(QStringLiteral("Robot 9")), robot);
    m_page->setSortKey(FleetSortKey::Name);
    QTRY_COMPARE_WITH_TIMEOUT(shownNames(*m_page).first(), QStringLiteral("Feeder 1"), kConnectMs);
    // Its ports are polled without the page asking: the workspace watches every port.
    QTRY_VERIFY_WITH_TIMEOUT(stationsRead(*m_page), kConnectMs);
    m_workspace->close();
    QCOMPARE(m_page->tileCount(), 0);
    QVERIFY(m_page->shownTiles().isEmpty());
}

// A line that never came up is on the overview, worst first, saying since when and why, instead
// of being missing from it; its click opens the line.
void TestFleetPage::aLineWithoutADeviceHasATileThatSaysWhy() {
    const quint16 port = refusingPort();
    QVERIFY(port != 0);
    WorkspaceLine dead;
    dead.name = QStringLiteral("line-dead");
    dead.cell = QStringLiteral("Cell 9");
    dead.session.line.kind = link::LineSettings::Kind::Tcp;
    dead.session.line.tcpHost = QStringLiteral("127.0.0.1");
    dead.session.line.tcpPort = port;
    QVERIFY(m_workspace->addLine(dead).ok());
    const int line = m_workspace->indexOf(dead.name);
    m_page->setSortKey(FleetSortKey::State);
    QTRY_VERIFY_WITH_TIMEOUT(m_page->shownTiles().size() == 7 &&
                                 !m_page->shownTiles().first()->shown().lineText.isEmpty() &&
                                 m_page->shownTiles().first()->shown().downSinceMs.has_value() &&
                                 m_workspace->session(line)->state() == Session::State::Retrying,
                             kConnectMs);
    FleetTileWidget *tile = m_page->shownTiles().first();
    QCOMPARE(tile->tile().lineIndex(), line);
    QVERIFY(!tile->tile().device());
    const QStringList lines = tile->lines();
    QCOMPARE(lines.at(0), QStringLiteral("No device"));
    QCOMPARE(lines.at(1), QStringLiteral("line-dead · Cell 9"));
    QVERIFY2(lines.at(2).startsWith(QStringLiteral("Line down since ")), qPrintable(lines.at(2)));
    // Why, in full: the reason wraps rather than losing its end to the tile's edge.
    QVERIFY2(lines.mid(3).join(QLatin1Char(' ')).endsWith(QStringLiteral("Connection refused")),
             qPrintable(lines.join(QLatin1Char('|'))));
    QVERIFY(tile->shown().needsAttention());
    QCOMPARE(m_page->summaryText(),
             QStringLiteral("Devices: 6 · need attention: 1 · lines without a device: 1"));
    m_page->setAttentionOnly(true);
    QCOMPARE(m_page->shownTiles(), QList<FleetTileWidget *>{tile});

    QSignalSpy activated(m_page.get(), &FleetPage::deviceActivated);
    QTest::mouseClick(tile, Qt::LeftButton);
    QCOMPARE(activated.size(), 1);
    QCOMPARE(activated.first().at(0).toInt(), line);
    QCOMPARE(activated.first().at(1).value<DeviceModel *>(), nullptr);
}

// A server that never accepts keeps the line connecting: its tile says so, not that devices are
// being looked for, and it is not down yet.
void TestFleetPage::aLineStillConnectingSaysSoNotThatItLooksForDevices() {
    const tipscope::testing::FullBacklog server;
    QVERIFY(server.port() != 0);
    WorkspaceLine slow;
    slow.name = QStringLiteral("line-slow");
    slow.session.line.kind = link::LineSettings::Kind::Tcp;
    slow.session.line.tcpHost = QStringLiteral("127.0.0.1");
    slow.session.line.tcpPort = server.port();
    QVERIFY(m_workspace->addLine(slow).ok());
    const int line = m_workspace->indexOf(slow.name);
    QTRY_VERIFY_WITH_TIMEOUT(m_page->shownTiles().size() == 7, kConnectMs);
    FleetTileWidget *tile = nullptr;
    for (FleetTileWidget *t : m_page->shownTiles())
        if (t->tile().lineIndex() == line)
            tile = t;
    QVERIFY(tile);
    QCOMPARE(m_workspace->session(line)->state(), Session::State::Connecting);
    QTRY_COMPARE_WITH_TIMEOUT(tile->shown().lineText, QStringLiteral("Connecting"), kConnectMs);
    QVERIFY(!tile->shown().downSinceMs); // not down: no "since"
}

TIPSCOPE_TEST_MAIN(TestFleetPage)

} // namespace tst_fleetpage
#include "tst_fleetpage.moc"
