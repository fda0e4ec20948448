#include "mainwindow.h"

#include "connectionbar.h"
#include "devicetree.h"
#include "dialogs/boardreportdialog.h"
#include "dialogs/jointlimitsdialog.h"
#include "dialogs/preferencesdialog.h"
#include "dialogs/workcontextdialog.h"
#include "journalstatusbutton.h"

#include "journal/jointstatistics.h"
#include "journal/journalhealth.h"
#include "linepages.h"
#include "linkstatuslabel.h"
#include "pages/fleet/fleetpage.h"
#include "pages/fleet/remotedevicepage.h"
#include "pages/page.h"

#include "model/joints/jointlimitsfile.h"
#include "model/report/supportreport.h"

#include "widgets/startfolder.h"

#include <QApplication>
#include <QCloseEvent>
#include <QDesktopServices>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QSplitter>
#include <QStackedWidget>
#include <QStatusBar>
#include <QToolBar>
#include <QUrl>

namespace tipscope::gui {

using namespace tipscope::model;

namespace {
// The service started before the window's members that show its journal are bound to it.
service::LineService &started(service::LineService &service,
                              std::optional<QString> *limitsProblem) {
    if (const auto limits = service.start({}); !limits)
        *limitsProblem = limits.error();
    return service;
}
} // namespace

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent)
    , m_workspace(started(m_service, &m_limitsProblem).workspace())
    , m_journal(m_service.journal())
    , m_context(*m_service.workContext()) {
    m_service.keep(m_session);
    QSettings store;
    m_settings = AppSettings::load(store);
    m_connection = new ConnectionBar(this);
    m_connection->setSettings(m_settings);
    auto *bar = addToolBar(tr("Connection"));
    bar->setObjectName(QStringLiteral("connectionToolBar"));
    bar->setMovable(false);
    bar->addWidget(m_connection);
    m_tree = new DeviceTree(m_session, m_workspace, this);
    m_stack = new QStackedWidget(this);
    m_barPages = new LinePages(m_session, m_journal.path(), LinePages::PortsPolled::Shown, m_stack);
    m_barPages->setWorkOrder(m_journal.context().workOrder);
    m_stack->addWidget(m_barPages);
    m_fleet = new FleetPage(m_workspace, m_stack);
    m_stack->addWidget(m_fleet);
    m_remotePage = new RemoteDevicePage(m_plant, m_stack);
    m_stack->addWidget(m_remotePage);
    connect(m_fleet, &FleetPage::remoteDeviceActivated, this, &MainWindow::showRemoteDevice);
    connect(m_remotePage, &RemoteDevicePage::backRequested, this, &MainWindow::showFleet);
    connect(m_fleet, &FleetPage::deviceActivated, this,
            [this](int line, DeviceModel *device) { m_tree->select(line, device); });
    connect(&m_context, &journal::WorkContextFollower::contextChanged, this,
            [this](const WorkContext &context) {
                m_barPages->setWorkOrder(context.workOrder);
                for (const auto &[line, pages] : m_linePages)
                    pages->setWorkOrder(workOrderOf(line));
            });
    m_splitter = new QSplitter(this);
    m_splitter->setObjectName(QStringLiteral("mainSplitter"));
    m_splitter->addWidget(m_tree);
    m_splitter->addWidget(m_stack);
    m_splitter->setStretchFactor(1, 1);
    m_splitter->setSizes({230, 1000});
    setCentralWidget(m_splitter);
    m_stateLabel = new QLabel(this);
    m_linkStatus = new LinkStatusLabel(m_session, this);
    m_workspaceLabel = new QLabel(this);
    m_workspaceLabel->hide();
    statusBar()->addWidget(m_stateLabel, 1);
    statusBar()->addPermanentWidget(m_workspaceLabel);
    m_plantLabel = new QLabel(this);
    m_plantLabel->hide();
    statusBar()->addPermanentWidget(m_plantLabel);
    statusBar()->addPermanentWidget(new JournalStatusButton(m_journal, m_context, this));
    statusBar()->addPermanentWidget(m_linkStatus);
    buildMenus();
    sayLimitsProblem();

    connect(m_connection, &ConnectionBar::connectRequested, this, &MainWindow::connectLine);
    connect(m_connection, &ConnectionBar::disconnectRequested, &m_session,
            &Session::disconnectFromLine);
    connect(m_connection, &ConnectionBar::monitorOnlyToggled, &m_session, &Session::setMonitorOnly);
    connect(&m_session, &Session::stateChanged, this,
            [this](Session::State s, const QString &text) {
                m_connection->setState(s, text);
                m_stateLabel->setText(text);
                updateTitle();
            });
    connect(&m_session, &Session::devicesChanged, this, &MainWindow::updateTitle);
    connect(m_tree, &DeviceTree::selectionChangedTo, this, &MainWindow::onSelection);
    connect(&m_workspace, &Workspace::linesChanged, this, &MainWindow::onWorkspaceLines);
    connect(&m_workspace, &Workspace::lineStateChanged, this, &MainWindow::updateWorkspaceStatus);
    applyPreferences(m_settings);
    restoreGeometry(store.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(store.value(QStringLiteral("window/state")).toByteArray());
    m_splitter->restoreState(store.value(QStringLiteral("window/splitter")).toByteArray());
    const int tab = store.value(QStringLiteral("window/tab"), 0).toInt();
    m_barPages->setCurrentIndex(tab >= 0 && tab < m_barPages->count() ? tab : 0);
    showPagesOf(*m_barPages);
    updateTitle();
    if (size().width() < 400)
        resize(1280, 820);
}

MainWindow::~MainWindow() {
    m_fleet->watchPlant(nullptr); // its remote tiles read the watch, which goes first
    dropWorkspace();
}

void MainWindow::buildMenus() {
    QMenu *file = menuBar()->addMenu(tr("&File"));
    buildWorkspaceMenu(*file);
    buildPlantMenu(*file);
    file->addSeparator();
    file->addAction(tr("Work &context…"), this, [this] {
        WorkContextDialog dialog(m_context, this);
        dialog.exec();
    });
    file->addAction(tr("Write &support report…"), this, &MainWindow::writeSupportReport);
    file->addAction(tr("&Board report…"), this, [this] {
        (void)m_journal.flush(2000); // the board's last joints count too
        const auto context = journal::readWorkContext(m_context.path());
        BoardReportDialog dialog(m_journal.path(), context ? context->boardSerial : QString(),
                                 this);
        dialog.exec();
    });
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);
    QMenu *tools = menuBar()->addMenu(tr("&Tools"));
    tools->addAction(tr("&Preferences…"), QKeySequence::Preferences, this, [this] {
        PreferencesDialog dialog(m_settings, m_journal.retentionDays(), this);
        if (dialog.exec() != QDialog::Accepted)
            return;
        applyPreferences(dialog.result());
        if (dialog.journalRetentionDays() != m_journal.retentionDays())
            (void)m_journal.setRetentionDays(dialog.journalRetentionDays()); // in range by its box
    });
    tools->addAction(tr("&Joint limits…"), this, &MainWindow::editJointLimits);
    QMenu *help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About TipScope"), this, [this] {
        QMessageBox::about(
            this, tr("About TipScope"),
            tr("<b>TipScope %1</b><p>Configures and monitors JBC soldering control units "
               "(UCR, ALE, NAE, DDE, DME, HDE, DDR, HDR) and the SFR solder feeder over "
               "their RS-232 robot protocol.</p>")
                .arg(QApplication::applicationVersion()));
    });
}

QTabWidget &MainWindow::pages() const {
    return *m_barPages;
}

Page *MainWindow::page(const QString &title) const {
    return m_barPages->page(title);
}

QWidget *MainWindow::shownPages() const {
    return m_stack->currentWidget();
}

void MainWindow::applyPreferences(const AppSettings &settings) {
    m_settings = settings;
    QSettings store;
    m_settings.save(store);
    applyPreferencesTo(m_session);
    // A workspace line keeps the link timing its file gives it.
    if (link::Line *line = m_session.line()) {
        link::QueueSettings q = line->queue().settings();
        q.turnaroundMs = m_settings.turnaroundMs;
        q.retries = m_settings.retries;
        line->queue().setSettings(q);
    }
    for (int i = 0; i < m_workspace.count(); ++i)
        applyPreferencesTo(*m_workspace.session(i));
}

void MainWindow::applyPreferencesTo(Session &session) const {
    session.setTemperatureUnit(m_settings.unit);
    session.scheduler().setInterval(PollClass::Live, m_settings.liveMs);
    session.scheduler().setInterval(PollClass::Status, m_settings.statusMs);
    session.scheduler().setInterval(PollClass::Counter, m_settings.counterMs);
    // For the histories of the devices found from now on; those held keep their size.
    session.telemetry().setTiers(m_settings.telemetryTiers());
}

QString MainWindow::connectLine() {
    const AppSettings wanted = m_connection->settings(m_settings);
    const auto session = wanted.sessionSettings();
    if (!session) {
        m_connection->setState(Session::State::Failed, session.error());
        return session.error();
    }
    m_settings = wanted;
    QSettings store;
    m_settings.save(store);
    m_session.connectTo(*session);
    return {};
}

void MainWindow::connectWith(const AppSettings &settings) {
    m_connection->setSettings(settings);
    connectLine();
}

LinePages &MainWindow::linePages(int line) {
    if (line == DeviceTree::kBarLine)
        return *m_barPages;
    auto it = m_linePages.find(line);
    if (it == m_linePages.end()) {
        auto *pages = new LinePages(*m_workspace.session(line), m_journal.path(),
                                    LinePages::PortsPolled::Every, m_stack);
        pages->setWorkOrder(workOrderOf(line));
        m_stack->addWidget(pages);
        it = m_linePages.emplace(line, pages).first;
    }
    return *it->second;
}

// A line's joints are stamped with its own work context when it has one, else the shared one.
QString MainWindow::workOrderOf(int line) const {
    if (line >= 0 && line < m_workspace.count())
        if (const auto own = m_workspace.line(line).ownContext())
            return own->workOrder;
    return m_journal.context().workOrder;
}

void MainWindow::onSelection(int line, DeviceModel *device, int port) {
    if (line == DeviceTree::kFleet) {
        showFleet();
        return;
    }
    LinePages &pages = linePages(line);
    pages.select(device, port);
    showPagesOf(pages);
}

// Moving to another line keeps the page in front: Charts stays Charts.
void MainWindow::showPagesOf(LinePages &pages) {
    const auto *before = qobject_cast<LinePages *>(m_stack->currentWidget());
    const auto *front = before ? qobject_cast<Page *>(before->currentWidget()) : nullptr;
    if (before != &pages && front)
        pages.showPage(front->title());
    else if (!before && !m_frontBeforeFleet.isEmpty())
        pages.showPage(m_frontBeforeFleet);
    m_stack->setCurrentWidget(&pages);
    m_linkStatus->setSession(&pages.session());
    m_barPages->setShown(&pages == m_barPages);
    for (const auto &[line, other] : m_linePages)
        other->setShown(other == &pages);
}

// The line pages behind the fleet poll nothing for being shown; the page in front of the last
// pages seen comes back with them.
void MainWindow::showFleet() {
    if (const auto *before = qobject_cast<LinePages *>(m_stack->currentWidget()))
        if (const auto *front = qobject_cast<Page *>(before->currentWidget()))
            m_frontBeforeFleet = front->title();
    m_stack->setCurrentWidget(m_fleet);
    m_linkStatus->setSession(nullptr); // many lines: the workspace's count says how they are
    m_barPages->setShown(false);
    for (const auto &[line, pages] : m_linePages)
        pages->setShown(false);
}

void MainWindow::updateTitle() {
    if (m_workspace.count() > 0) {
        const QString name = m_workspacePath.isEmpty()
                                 ? tr("new workspace")
                                 : QFileInfo(m_workspacePath).completeBaseName();
        setWindowTitle(tr("TipScope — %1 (%n line(s))", nullptr, m_workspace.count()).arg(name));
        return;
    }
    QString what = tr("not connected");
    if (StationModel *st = m_session.station())
        what = st->displayName();
    else if (!m_session.devices().isEmpty())
        what = m_session.devices().first()->displayName();
    setWindowTitle(tr("TipScope — %1").arg(what));
}

void MainWindow::writeSupportReport() {
    const QString folder =
        QFileDialog::getExistingDirectory(this, tr("Folder for the support report"), startFolder());
    if (folder.isEmpty())
        return;
    QList<ReportedLine> lines;
    for (int i = 0; i < m_workspace.count(); ++i) {
        const WorkspaceLine &line = m_workspace.line(i);
        lines.append({line.name, line.cell, line.location, m_workspace.session(i)});
    }
    QJsonObject report = model::supportReportJson(m_session, lines);
    (void)m_journal.flush(2000); // the last joints count too
    report.insert(QStringLiteral("journal"), journal::journalHealth(m_journal));
    report.insert(QStringLiteral("joints"), journal::lastDayOfJoints(m_journal.path()));
    const auto files = model::writeSupportReport(report, folder);
    if (!files) {
        QMessageBox::critical(this, tr("Support report"), files.error());
        return;
    }
    QMessageBox::information(this, tr("Support report"),
                             tr("Written:\n%1\n\nAttach both files to the support ticket.")
                                 .arg(files->join(QLatin1Char('\n'))));
}

void MainWindow::loadJointLimits() {
    if (const auto limits = m_service.reloadLimits(); !limits)
        m_limitsProblem = limits.error();
    sayLimitsProblem();
}

// Said where the problems are read, and the defaults judge meanwhile.
void MainWindow::sayLimitsProblem() {
    if (const auto problem = std::exchange(m_limitsProblem, std::nullopt))
        m_session.eventLog().add(Event::Kind::JointWarning, Event::Severity::Warning,
                                 tr("joint limits"),
                                 tr("%1; the default limits judge joints").arg(*problem));
}

void MainWindow::editJointLimits() {
    JointLimitsDialog dialog(m_session.joints().rules(), model::defaultJointLimitsPath(), this);
    if (dialog.exec() == QDialog::Accepted)
        loadJointLimits();
}

void MainWindow::closeEvent(QCloseEvent *event) {
    QSettings store;
    store.setValue(QStringLiteral("window/geometry"), saveGeometry());
    store.setValue(QStringLiteral("window/state"), saveState());
    store.setValue(QStringLiteral("window/splitter"), m_splitter->saveState());
    store.setValue(QStringLiteral("window/tab"), m_barPages->currentIndex());
    m_session.disconnectFromLine();
    dropWorkspace();
    // The last joints and the disconnect reach the file before the window goes.
    (void)m_journal.flush(5000);
    event->accept();
}

} // namespace tipscope::gui
