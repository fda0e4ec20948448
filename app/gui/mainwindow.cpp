#include "mainwindow.h"

#include "connectionbar.h"
#include "devicetree.h"
#include "dialogs/jointlimitsdialog.h"
#include "dialogs/preferencesdialog.h"
#include "dialogs/workcontextdialog.h"
#include "journalstatusbutton.h"

#include "journal/jointstatistics.h"
#include "journal/journalhealth.h"
#include "linkstatuslabel.h"
#include "pages/jointspage.h"
#include "pages/pagefactory.h"

#include "model/joints/jointlimitsfile.h"
#include "model/supportreport.h"

#include <QApplication>
#include <QCloseEvent>
#include <QDesktopServices>
#include <QFileDialog>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QSplitter>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QToolBar>
#include <QUrl>

namespace tipscope::gui {

using namespace tipscope::model;

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent)
    , m_kept(m_session, m_journal)
    , m_context(m_journal, journal::workContextPathFor(m_journal.path())) {
    QSettings store;
    m_settings = AppSettings::load(store);
    m_connection = new ConnectionBar(this);
    m_connection->setSettings(m_settings);
    auto *bar = addToolBar(tr("Connection"));
    bar->setObjectName(QStringLiteral("connectionToolBar"));
    bar->setMovable(false);
    bar->addWidget(m_connection);
    m_tree = new DeviceTree(m_session, this);
    m_tabs = new QTabWidget(this);
    m_tabs->setDocumentMode(true);
    m_pages = createPages(m_session, m_tabs);
    for (Page *p : std::as_const(m_pages)) {
        m_tabs->addTab(p, p->title());
        if (auto *joints = qobject_cast<JointsPage *>(p))
            connectJointsPage(*joints);
    }
    m_splitter = new QSplitter(this);
    m_splitter->setObjectName(QStringLiteral("mainSplitter"));
    m_splitter->addWidget(m_tree);
    m_splitter->addWidget(m_tabs);
    m_splitter->setStretchFactor(1, 1);
    m_splitter->setSizes({230, 1000});
    setCentralWidget(m_splitter);
    m_stateLabel = new QLabel(this);
    m_linkStatus = new LinkStatusLabel(m_session, this);
    statusBar()->addWidget(m_stateLabel, 1);
    statusBar()->addPermanentWidget(new JournalStatusButton(m_journal, m_context, this));
    statusBar()->addPermanentWidget(m_linkStatus);
    buildMenus();
    loadJointLimits();

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
    connect(&m_session, &Session::devicesChanged, this, &MainWindow::updateVisiblePorts);
    connect(m_tree, &DeviceTree::selectionChangedTo, this, &MainWindow::onSelection);
    connect(m_tabs, &QTabWidget::currentChanged, this, &MainWindow::onTabChanged);
    applyPreferences(m_settings);
    restoreGeometry(store.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(store.value(QStringLiteral("window/state")).toByteArray());
    m_splitter->restoreState(store.value(QStringLiteral("window/splitter")).toByteArray());
    const int tab = store.value(QStringLiteral("window/tab"), 0).toInt();
    m_tabs->setCurrentIndex(tab >= 0 && tab < m_tabs->count() ? tab : 0);
    onTabChanged(m_tabs->currentIndex());
    updateTitle();
    if (size().width() < 400)
        resize(1280, 820);
}

MainWindow::~MainWindow() = default;

// The Joints page reads this window's journal, stamps live joints with its work order until the
// journal has them, and brings the Charts page forward for a joint.
void MainWindow::connectJointsPage(JointsPage &joints) {
    joints.setJournalPath(m_journal.path());
    joints.setWorkOrder(m_journal.context().workOrder);
    connect(&m_context, &journal::WorkContextFollower::contextChanged, &joints,
            [&joints](const WorkContext &context) { joints.setWorkOrder(context.workOrder); });
    connect(&joints, &JointsPage::chartsShown, m_tabs, &QTabWidget::setCurrentWidget);
}

void MainWindow::buildMenus() {
    QMenu *file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("Work &context…"), this, [this] {
        WorkContextDialog dialog(m_context, this);
        dialog.exec();
    });
    file->addAction(tr("Write &support report…"), this, &MainWindow::writeSupportReport);
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

Page *MainWindow::page(const QString &title) const {
    for (Page *p : m_pages)
        if (p->title() == title)
            return p;
    return nullptr;
}

void MainWindow::applyPreferences(const AppSettings &settings) {
    m_settings = settings;
    QSettings store;
    m_settings.save(store);
    m_session.setTemperatureUnit(settings.unit);
    m_session.scheduler().setInterval(PollClass::Live, settings.liveMs);
    m_session.scheduler().setInterval(PollClass::Status, settings.statusMs);
    m_session.scheduler().setInterval(PollClass::Counter, settings.counterMs);
    // For the histories of the devices found from now on; those held keep their size.
    m_session.telemetry().setTiers(settings.telemetryTiers());
    if (link::Line *line = m_session.line()) {
        link::QueueSettings q = line->queue().settings();
        q.turnaroundMs = settings.turnaroundMs;
        q.retries = settings.retries;
        line->queue().setSettings(q);
    }
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

void MainWindow::onSelection(DeviceModel *device, int port) {
    for (Page *p : std::as_const(m_pages)) {
        p->setSelection(device, port);
        const int index = m_tabs->indexOf(p);
        m_tabs->setTabVisible(index, !device || p->appliesTo(device));
    }
    updateVisiblePorts();
}

void MainWindow::onTabChanged(int index) {
    for (int i = 0; i < m_pages.size(); ++i)
        m_pages.at(i)->setActive(m_tabs->indexOf(m_pages.at(i)) == index);
    updateVisiblePorts();
}

void MainWindow::updateVisiblePorts() {
    // The shown page decides which ports' live values are worth the wire.
    auto *current = qobject_cast<Page *>(m_tabs->currentWidget());
    const QSet<int> ports = current ? current->visiblePorts() : QSet<int>();
    for (DeviceModel *d : m_session.devices())
        m_session.scheduler().setVisiblePorts(d, qobject_cast<StationModel *>(d) ? ports
                                                                                 : QSet<int>());
}

void MainWindow::updateTitle() {
    QString what = tr("not connected");
    if (StationModel *st = m_session.station())
        what = st->displayName();
    else if (!m_session.devices().isEmpty())
        what = m_session.devices().first()->displayName();
    setWindowTitle(tr("TipScope — %1").arg(what));
}

void MainWindow::writeSupportReport() {
    const QString folder = QFileDialog::getExistingDirectory(
        this, tr("Folder for the support report"),
        QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation));
    if (folder.isEmpty())
        return;
    QJsonObject report = model::supportReportJson(m_session);
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
    const auto rules = model::loadJointLimits(model::defaultJointLimitsPath());
    if (!rules) {
        // Said where the problems are read, and the defaults judge meanwhile.
        m_session.eventLog().add(Event::Kind::Joint, Event::Severity::Warning, tr("joint limits"),
                                 tr("%1; the default limits judge joints").arg(rules.error()));
        return;
    }
    m_session.joints().setRules(rules.value());
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
    store.setValue(QStringLiteral("window/tab"), m_tabs->currentIndex());
    m_session.disconnectFromLine();
    // The last joints and the disconnect reach the file before the window goes.
    (void)m_journal.flush(5000);
    event->accept();
}

} // namespace tipscope::gui
