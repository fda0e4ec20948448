// MainWindow: the connection bar, the device tree, the pages, and the status bar with the
// line's state and statistics. It owns the connection bar's Session and the Workspace of lines
// opened together (File › Open workspace); each line has its own pages (LinePages), made when one
// of its devices is first selected, and pages and widgets talk to the models of their line. It
// keeps every line's joints and events in the journal (the default file, shared with the CLI),
// stamped with the work context of the shared context file, and judges joints by the shared
// joint limits file unless a workspace line names its own.
// File › Connect to plant watches the plant's broker: every device other TipScopes publish joins
// the fleet overview, with read-only pages (mainwindowplant.cpp).
// Window geometry, splitter state, the last connection and the last workspace are remembered.
#pragma once

#include "model/appsettings.h"

#include "model/session.h"
#include "mqtt/mqttsettings.h"
#include "plant/plantwatch.h"
#include "service/lineservice.h"

#include <QMainWindow>
#include <map>
#include <memory>
#include <vector>

class QTabWidget;
class QSplitter;
class QLabel;
class QStackedWidget;
class QMenu;
class QAction;

namespace tipscope::gui {

class ConnectionBar;
class FleetPage;
class DeviceTree;
class LinkStatusLabel;
class LinePages;
class Page;
class RemoteDevicePage;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    // The connection bar's line, and its pages.
    [[nodiscard]] model::Session &session() { return m_session; }
    [[nodiscard]] ConnectionBar &connectionBar() const { return *m_connection; }
    [[nodiscard]] QTabWidget &pages() const;
    [[nodiscard]] Page *page(const QString &title) const;
    [[nodiscard]] model::Workspace &workspace() { return m_workspace; }
    [[nodiscard]] QString workspacePath() const { return m_workspacePath; }
    // The pages of a workspace line (made now when they were not yet).
    [[nodiscard]] LinePages &linePages(int line);
    // The pages on screen.
    [[nodiscard]] QWidget *shownPages() const;
    [[nodiscard]] DeviceTree &deviceTree() const { return *m_tree; }
    [[nodiscard]] FleetPage &fleetPage() const { return *m_fleet; }
    [[nodiscard]] journal::Journal &journal() { return m_journal; }
    [[nodiscard]] journal::WorkContextFollower &workContext() { return m_context; }

    // Connects with the connection bar's settings (saving them); a refusal is shown and returned.
    QString connectLine();
    void connectWith(const model::AppSettings &settings);
    // Opens the workspace file, closing the one open; a refusal is returned, and the one open
    // stays open.
    QString openWorkspace(const QString &path);
    QString saveWorkspace(const QString &path);
    void closeWorkspace();
    // File › Save workspace, Save workspace as… and Close workspace, by their text as shown
    // ("Close workspace"), for tests.
    [[nodiscard]] QAction *workspaceAction(const QString &name) const;
    // Reopens the workspace open when TipScope last closed, if there was one.
    void reopenLastWorkspace();
    void writeSupportReport();
    void editJointLimits();
    // Watches the plant's broker: every device published there joins the fleet overview.
    void watchPlant(const mqtt::MqttSettings &broker, const QString &site);
    void stopWatchingPlant();
    [[nodiscard]] plant::PlantWatch &plantWatch() { return m_plant; }
    [[nodiscard]] RemoteDevicePage &remoteDevicePage() const { return *m_remotePage; }

protected:
    void closeEvent(QCloseEvent *event) override;

private:
    void buildMenus();
    void buildWorkspaceMenu(QMenu &file);
    void buildPlantMenu(QMenu &file);
    void showRemoteDevice(const QString &root);
    void updatePlantStatus();
    void applyPreferences(const model::AppSettings &settings);
    void applyPreferencesTo(model::Session &session) const;
    void onSelection(int line, model::DeviceModel *device, int port);
    void showPagesOf(LinePages &pages);
    void showFleet();
    void updateTitle();
    void updateWorkspaceStatus();
    void updateWorkspaceActions();
    void updateBarNote();
    [[nodiscard]] QString workOrderOf(int line) const;
    void loadJointLimits();
    void sayLimitsProblem();
    void onWorkspaceLines();
    void dropWorkspace();
    void askToOpenWorkspace();
    void askToSaveWorkspace(bool choosePath);
    void addBarLineToWorkspace();

    model::Session m_session; // the connection bar's line
    // The joint limits file could not be read (said once, in the bar line's events); set while
    // the service starts, so declared before it.
    std::optional<QString> m_limitsProblem;
    // The journal, the shared joint limits, the work context and the workspace's lines: the one
    // path from the wire to the journal that every front end opens. It keeps m_session too.
    service::LineService m_service;
    model::Workspace &m_workspace;
    journal::Journal &m_journal;
    journal::WorkContextFollower &m_context;
    QString m_workspacePath;
    model::AppSettings m_settings;
    ConnectionBar *m_connection;
    DeviceTree *m_tree;
    QStackedWidget *m_stack;
    LinePages *m_barPages;
    FleetPage *m_fleet;
    QString m_frontBeforeFleet; // the page in front when the fleet overview was chosen
    std::map<int, LinePages *> m_linePages;
    QSplitter *m_splitter;
    LinkStatusLabel *m_linkStatus;
    QLabel *m_stateLabel;
    QLabel *m_workspaceLabel;
    plant::PlantWatch m_plant;
    QString m_plantWhere; // host:port while watching
    RemoteDevicePage *m_remotePage;
    QLabel *m_plantLabel;
    QAction *m_stopWatchingPlant = nullptr;
    QList<QAction *> m_workspaceOnlyActions; // Save, Save as, Close: off with no workspace open
};

} // namespace tipscope::gui
