// MainWindow: the connection bar, the device tree, the pages, and the status bar with the
// line's state and statistics. It owns the Session; pages and widgets talk to its models. It
// keeps the session's joints and events in the journal (the default file, shared with the CLI),
// stamped with the work context of the shared context file, and judges joints by the shared
// joint limits file.
// Window geometry, splitter state and the last connection are remembered (AppSettings).
#pragma once

#include "model/appsettings.h"

#include "journal/journal.h"
#include "journal/sessionjournal.h"
#include "journal/workcontextfile.h"
#include "model/session.h"

#include <QMainWindow>

class QTabWidget;
class QSplitter;
class QLabel;

namespace tipscope::gui {

class ConnectionBar;
class DeviceTree;
class LinkStatusLabel;
class JointsPage;
class Page;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    [[nodiscard]] model::Session &session() { return m_session; }
    [[nodiscard]] ConnectionBar &connectionBar() const { return *m_connection; }
    [[nodiscard]] QTabWidget &pages() const { return *m_tabs; }
    [[nodiscard]] Page *page(const QString &title) const;
    [[nodiscard]] DeviceTree &deviceTree() const { return *m_tree; }
    [[nodiscard]] journal::Journal &journal() { return m_journal; }
    [[nodiscard]] journal::WorkContextFollower &workContext() { return m_context; }

    // Connects with the connection bar's settings (saving them); a refusal is shown and returned.
    QString connectLine();
    void connectWith(const model::AppSettings &settings);
    void writeSupportReport();
    void editJointLimits();

protected:
    void closeEvent(QCloseEvent *event) override;

private:
    void buildMenus();
    void connectJointsPage(JointsPage &joints);
    void applyPreferences(const model::AppSettings &settings);
    void onSelection(model::DeviceModel *device, int port);
    void onTabChanged(int index);
    void updateVisiblePorts();
    void updateTitle();
    void loadJointLimits();

    model::Session m_session;
    journal::Journal m_journal;
    journal::SessionJournal m_kept;
    journal::WorkContextFollower m_context;
    model::AppSettings m_settings;
    ConnectionBar *m_connection;
    DeviceTree *m_tree;
    QTabWidget *m_tabs;
    QSplitter *m_splitter;
    LinkStatusLabel *m_linkStatus;
    QLabel *m_stateLabel;
    QList<Page *> m_pages;
};

} // namespace tipscope::gui
