// The main window with a workspace open, on the offscreen platform: the lines of the file, each
// under its name in the device tree with its own pages; a file that cannot be read refused with
// the reason while the open workspace stays; the workspace saved, and reopened at the next start.
#include "connectionbar.h"
#include "devicetree.h"
#include "linepages.h"
#include "linkstatuslabel.h"
#include "mainwindow.h"
#include "pages/fleet/fleetpage.h"
#include "pages/fleet/fleettilewidget.h"
#include "pages/jointspage.h"
#include "pages/page.h"
#include "testmain.h"

#include "i18n/translations.h"
#include "model/workspace/workspacefile.h"

#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

namespace tst_mainwindowworkspace {

using namespace tipscope;
using namespace tipscope::gui;
using namespace tipscope::model;

namespace {
constexpr int kConnectMs = 20000;

WorkspaceFile twoDemoLines() {
    WorkspaceFile file;
    for (const char *name : {"cell-1", "cell-2"}) {
        WorkspaceLine line;
        line.name = QLatin1String(name);
        line.cell = QStringLiteral("Cell %1").arg(file.lines.size() + 1);
        line.session.line.kind = link::LineSettings::Kind::Demo;
        file.lines.append(line);
    }
    file.lines[1].deviceNames.insert(1, QStringLiteral("Rework B"));
    file.lines[1].context.workOrder = QStringLiteral("WO-cell-2");
    return file;
}

void waitForEveryLine(MainWindow &w) {
    for (int i = 0; i < w.workspace().count(); ++i) {
        QTRY_COMPARE_WITH_TIMEOUT(w.workspace().session(i)->state(), Session::State::Connected,
                                  kConnectMs);
        QTRY_COMPARE_WITH_TIMEOUT(w.workspace().session(i)->devices().size(), 2, kConnectMs);
    }
}
} // namespace

class TestMainWindowWorkspace : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void theTreeHoldsEveryLineUnderItsName();
    void everyPageWorksForTheDeviceSelectedOnAnyLine();
    void aWorkspaceOpensOnItsFleetAndATileOpensItsDevice();
    void aWorkspaceThatCannotBeReadIsRefusedAndTheOpenOneStays();
    void theSavedWorkspaceReopensAtTheNextStartUntilItIsClosed();

private:
    QTemporaryDir m_dir;
    QString m_path;
};

void TestMainWindowWorkspace::initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    // English plurals ("2 lines") come from the English translation, as in the application.
    QCOMPARE(i18n::installTranslators(*QCoreApplication::instance(), QStringLiteral("en")),
             QStringLiteral("en"));
    QCoreApplication::setOrganizationName(QStringLiteral("TipScopeTests"));
    QSettings().clear();
    QVERIFY(m_dir.isValid());
    m_path = m_dir.filePath(QStringLiteral("plant.json"));
    QVERIFY(twoDemoLines().save(m_path).ok());
}

void TestMainWindowWorkspace::theTreeHoldsEveryLineUnderItsName() {
    MainWindow w;
    w.show();
    QCOMPARE(w.openWorkspace(m_path), QString());
    waitForEveryLine(w);
    DeviceTree &tree = w.deviceTree();
    QCOMPARE(tree.topLevelItemCount(), 4);     // the fleet, the connection bar's line, two lines
    QVERIFY(tree.topLevelItem(1)->isHidden()); // the connection bar's line, not connected
    QTreeWidgetItem *cell1 = tree.topLevelItem(2), *cell2 = tree.topLevelItem(3);
    QVERIFY(cell1->text(0).startsWith(QStringLiteral("cell-1: ")));
    QVERIFY(cell2->text(0).startsWith(QStringLiteral("cell-2: ")));
    QCOMPARE(cell1->childCount(), 2);
    QCOMPARE(cell2->childCount(), 2);
    // The name the workspace gives the station at address 1 of cell-2, and only there.
    QTRY_VERIFY(cell2->child(0)->text(0).startsWith(QStringLiteral("Rework B, ")));
    QVERIFY(!cell1->child(0)->text(0).contains(QStringLiteral("Rework B")));
    QVERIFY2(w.windowTitle().contains(QStringLiteral("plant (2 lines)")),
             qPrintable(w.windowTitle()));
    // The bar's "Disconnected" is its own line's, and says so above a running workspace.
    QCOMPARE(w.connectionBar().stateText(),
             QStringLiteral("Disconnected (this bar's line only: the workspace's 2 lines are in "
                            "the tree)"));
    w.closeWorkspace();
    QCOMPARE(w.connectionBar().stateText(), QStringLiteral("Disconnected"));
}

void TestMainWindowWorkspace::everyPageWorksForTheDeviceSelectedOnAnyLine() {
    MainWindow w;
    w.show();
    QCOMPARE(w.openWorkspace(m_path), QString());
    waitForEveryLine(w);
    Session &second = *w.workspace().session(1);
    QVERIFY(w.deviceTree().select(1, second.station(), 2));
    LinePages &pages = w.linePages(1);
    QCOMPARE(w.shownPages(), &pages);
    QCOMPARE(pages.selectedDevice(), second.station());
    QCOMPARE(w.deviceTree().selectedPort(), 2);
    pages.showPage(QStringLiteral("Charts"));

    // Another line's feeder: its own pages, the Feeder page among them, and still the Charts
    // page in front, as it was.
    Session &first = *w.workspace().session(0);
    QVERIFY(w.deviceTree().select(0, first.feeder()));
    LinePages &firstPages = w.linePages(0);
    QCOMPARE(w.shownPages(), &firstPages);
    QCOMPARE(firstPages.selectedDevice(), first.feeder());
    QCOMPARE(qobject_cast<Page *>(firstPages.currentWidget())->title(), QStringLiteral("Charts"));
    Page *feeder = firstPages.page(QStringLiteral("Feeder"));
    QVERIFY(feeder && firstPages.isTabVisible(firstPages.indexOf(feeder)));
    // Only the pages on screen are active.
    QVERIFY(!pages.page(QStringLiteral("Charts"))->isVisible());
    QVERIFY(firstPages.page(QStringLiteral("Charts"))->isVisible());
    // Each line's Joints page follows the work order its joints are stamped with: cell-2's own.
    const auto workOrderOn = [](LinePages &p) {
        return qobject_cast<JointsPage *>(p.page(QStringLiteral("Joints")))->workOrder();
    };
    QCOMPARE(workOrderOn(pages), QStringLiteral("WO-cell-2"));
    QVERIFY(workOrderOn(firstPages) != QStringLiteral("WO-cell-2"));
}

void TestMainWindowWorkspace::aWorkspaceOpensOnItsFleetAndATileOpensItsDevice() {
    MainWindow w;
    w.show();
    QVERIFY(!w.deviceTree().selectFleet()); // no workspace, no fleet
    QCOMPARE(w.openWorkspace(m_path), QString());
    QCOMPARE(w.shownPages(), &w.fleetPage());
    QCOMPARE(w.deviceTree().selectedLine(), DeviceTree::kFleet);
    QCOMPARE(w.deviceTree().topLevelItem(0)->text(0), QStringLiteral("Fleet overview"));
    // Many lines shown: no one line's statistics in the status bar.
    auto *statistics = w.findChild<LinkStatusLabel *>();
    QVERIFY(statistics && !statistics->isVisible());
    waitForEveryLine(w);
    QTRY_COMPARE(w.fleetPage().tileCount(), 4);
    QCOMPARE(w.deviceTree().selectedLine(), DeviceTree::kFleet); // devices found: still the fleet

    // The tile of cell-2's station opens that station's pages, with the page last in front.
    Session &second = *w.workspace().session(1);
    QVERIFY(w.deviceTree().select(0, w.workspace().session(0)->station()));
    w.linePages(0).showPage(QStringLiteral("Counters"));
    QVERIFY(w.deviceTree().selectFleet());
    QCOMPARE(w.shownPages(), &w.fleetPage());
    QVERIFY(!w.linePages(0).page(QStringLiteral("Counters"))->isVisible());
    FleetTileWidget *tile = nullptr;
    for (FleetTileWidget *t : w.fleetPage().shownTiles())
        if (t->tile().device() == second.station())
            tile = t;
    QVERIFY(tile);
    QTest::mouseClick(tile, Qt::LeftButton, {}, tile->rect().center());
    QCOMPARE(w.shownPages(), &w.linePages(1));
    QCOMPARE(w.deviceTree().selectedLine(), 1);
    QCOMPARE(w.linePages(1).selectedDevice(), second.station());
    QCOMPARE(qobject_cast<Page *>(w.linePages(1).currentWidget())->title(),
             QStringLiteral("Counters"));
    // The statistics are those of the device's line (the connection bar's has none: "no line").
    QVERIFY(statistics->isVisible());
    QVERIFY2(statistics->text().contains(QStringLiteral("tx/s")), qPrintable(statistics->text()));
}

void TestMainWindowWorkspace::aWorkspaceThatCannotBeReadIsRefusedAndTheOpenOneStays() {
    MainWindow w;
    QCOMPARE(w.openWorkspace(m_path), QString());
    const QString broken = m_dir.filePath(QStringLiteral("broken.json"));
    QFile f(broken);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(R"({"format": "tipscope-workspace", "version": 1, "lines": [{"name": "x"}]})");
    f.close();
    const QString refused = w.openWorkspace(broken);
    QVERIFY2(refused.contains(QStringLiteral("broken.json")) &&
                 refused.contains(QStringLiteral("connection")),
             qPrintable(refused));
    QCOMPARE(w.workspace().count(), 2);
    QCOMPARE(w.workspacePath(), QFileInfo(m_path).absoluteFilePath());
    QVERIFY(!w.openWorkspace(m_dir.filePath(QStringLiteral("absent.json"))).isEmpty());
    QCOMPARE(w.workspace().count(), 2);
}

void TestMainWindowWorkspace::theSavedWorkspaceReopensAtTheNextStartUntilItIsClosed() {
    const QString copy = m_dir.filePath(QStringLiteral("copy.json"));
    const QStringList workspaceOnly{QStringLiteral("Save workspace"),
                                    QStringLiteral("Save workspace as…"),
                                    QStringLiteral("Close workspace")};
    {
        MainWindow w;
        // Nothing to save or close yet: the menu says so before anyone tries.
        for (const QString &name : workspaceOnly) {
            QVERIFY2(w.workspaceAction(name), qPrintable(name));
            QVERIFY2(!w.workspaceAction(name)->isEnabled(), qPrintable(name));
        }
        QCOMPARE(w.openWorkspace(m_path), QString());
        for (const QString &name : workspaceOnly)
            QVERIFY2(w.workspaceAction(name)->isEnabled(), qPrintable(name));
        QCOMPARE(w.saveWorkspace(copy), QString());
        const auto saved = WorkspaceFile::load(copy);
        QVERIFY2(saved.ok(), qPrintable(saved.error()));
        QCOMPARE(saved.value().toJson(), twoDemoLines().toJson());
    }
    {
        MainWindow w;
        QCOMPARE(w.workspace().count(), 0);
        w.reopenLastWorkspace();
        QCOMPARE(w.workspacePath(), QFileInfo(copy).absoluteFilePath());
        QCOMPARE(w.workspace().count(), 2);
        w.closeWorkspace();
        QCOMPARE(w.workspace().count(), 0);
        for (const QString &name : workspaceOnly)
            QVERIFY2(!w.workspaceAction(name)->isEnabled(), qPrintable(name));
    }
    MainWindow w;
    w.reopenLastWorkspace();
    QCOMPARE(w.workspace().count(), 0);
}

TIPSCOPE_TEST_MAIN(TestMainWindowWorkspace)

} // namespace tst_mainwindowworkspace
#include "tst_mainwindowworkspace.moc"
