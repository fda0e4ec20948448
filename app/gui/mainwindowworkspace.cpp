// MainWindow's workspace: File › Open, Save, Save as, Close workspace, and adding the connection
// bar's line to it; the last workspace reopens at start.
#include "mainwindow.h"

#include "connectionbar.h"
#include "devicetree.h"
#include "linepages.h"

#include "widgets/startfolder.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QStackedWidget>

namespace tipscope::gui {

using namespace tipscope::model;

namespace {
const QString kLastWorkspaceKey = QStringLiteral("workspace/last");
} // namespace

void MainWindow::buildWorkspaceMenu(QMenu &file) {
    file.addAction(tr("&Open workspace…"), QKeySequence::Open, this,
                   &MainWindow::askToOpenWorkspace);
    m_workspaceOnlyActions = {file.addAction(tr("&Save workspace"), QKeySequence::Save, this,
                                             [this] { askToSaveWorkspace(false); }),
                              file.addAction(tr("Save workspace &as…"), QKeySequence::SaveAs, this,
                                             [this] { askToSaveWorkspace(true); })};
    file.addAction(tr("&Add this line to the workspace…"), this,
                   &MainWindow::addBarLineToWorkspace);
    m_workspaceOnlyActions.append(
        file.addAction(tr("C&lose workspace"), this, &MainWindow::closeWorkspace));
    file.addSeparator();
    updateWorkspaceActions();
}

// Saving or closing no workspace would write an empty file or do nothing at all.
void MainWindow::updateWorkspaceActions() {
    for (QAction *a : std::as_const(m_workspaceOnlyActions))
        a->setEnabled(m_workspace.count() > 0);
}

QAction *MainWindow::workspaceAction(const QString &name) const {
    for (QAction *a : m_workspaceOnlyActions)
        if (QString(a->text()).remove(QLatin1Char('&')) == name)
            return a;
    return nullptr;
}

QString MainWindow::openWorkspace(const QString &path) {
    const auto file = WorkspaceFile::load(path);
    if (!file)
        return tr("%1: %2").arg(QDir::toNativeSeparators(path), file.error());
    dropWorkspace();
    m_workspacePath = QFileInfo(path).absoluteFilePath();
    m_workspace.open(file.value());
    m_tree->selectFleet(); // a fleet is seen whole first
    QSettings().setValue(kLastWorkspaceKey, m_workspacePath);
    updateWorkspaceStatus();
    return {};
}

QString MainWindow::saveWorkspace(const QString &path) {
    if (const auto saved = m_workspace.file().save(path); !saved)
        return tr("%1: %2").arg(QDir::toNativeSeparators(path), saved.error());
    m_workspacePath = QFileInfo(path).absoluteFilePath();
    QSettings().setValue(kLastWorkspaceKey, m_workspacePath);
    updateWorkspaceStatus();
    return {};
}

void MainWindow::closeWorkspace() {
    dropWorkspace();
    m_workspacePath.clear();
    QSettings().remove(kLastWorkspaceKey);
    updateWorkspaceStatus();
}

// The pages and journals of the lines go before their sessions do.
void MainWindow::dropWorkspace() {
    showPagesOf(*m_barPages);
    for (const auto &[line, pages] : m_linePages) {
        m_stack->removeWidget(pages);
        delete pages;
    }
    m_linePages.clear();
    m_service.closeLines();
}

void MainWindow::reopenLastWorkspace() {
    const QString last = QSettings().value(kLastWorkspaceKey).toString();
    if (last.isEmpty())
        return;
    if (const QString refused = openWorkspace(last); !refused.isEmpty())
        m_stateLabel->setText(tr("The last workspace was not reopened: %1").arg(refused));
}

// Every line of the workspace, as soon as its session exists and before it connects, polls at the
// intervals of the preferences (the line service already keeps it in the journal).
void MainWindow::onWorkspaceLines() {
    for (int line = 0; line < m_workspace.count(); ++line)
        applyPreferencesTo(*m_workspace.session(line));
    updateWorkspaceStatus();
}

void MainWindow::updateWorkspaceStatus() {
    updateWorkspaceActions();
    const int lines = m_workspace.count();
    m_workspaceLabel->setVisible(lines > 0);
    QStringList down;
    for (int i = 0; i < lines; ++i)
        if (m_workspace.session(i)->state() != Session::State::Connected)
            down << tr("%1: %2").arg(m_workspace.line(i).name, m_workspace.session(i)->stateText());
    m_workspaceLabel->setText(
        tr("Workspace: %1 of %n line(s) connected", nullptr, lines).arg(lines - down.size()));
    m_workspaceLabel->setToolTip(down.join(QLatin1Char('\n')));
    m_workspaceLabel->setStyleSheet(down.isEmpty() ? QString() : QStringLiteral("color: #b35c00;"));
    updateBarNote();
    updateTitle();
}

void MainWindow::updateBarNote() {
    if (m_workspace.count() > 0)
        m_connection->setBesideNote(
            tr("the workspace's %n line(s) are in the tree", nullptr, m_workspace.count()));
    else if (!m_plantWhere.isEmpty())
        m_connection->setBesideNote(tr("the plant's devices are on the fleet overview"));
    else
        m_connection->setBesideNote({});
}

void MainWindow::askToOpenWorkspace() {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open workspace"), QFileInfo(m_workspacePath).absolutePath(),
        tr("TipScope workspaces (*.json);;All files (*)"));
    if (path.isEmpty())
        return;
    if (const QString refused = openWorkspace(path); !refused.isEmpty())
        QMessageBox::critical(this, tr("Open workspace"), refused);
}

void MainWindow::askToSaveWorkspace(bool choosePath) {
    QString path = m_workspacePath;
    if (choosePath || path.isEmpty())
        path = QFileDialog::getSaveFileName(
            this, tr("Save workspace"),
            path.isEmpty() ? startFolder() + QStringLiteral("/workspace.json") : path,
            tr("TipScope workspaces (*.json)"));
    if (path.isEmpty())
        return;
    if (const QString refused = saveWorkspace(path); !refused.isEmpty())
        QMessageBox::critical(this, tr("Save workspace"), refused);
}

// The line the connection bar would open joins the workspace under a name: the bar lets it go
// first, as a serial port opens only once.
void MainWindow::addBarLineToWorkspace() {
    const AppSettings wanted = m_connection->settings(m_settings);
    const auto settings = wanted.sessionSettings();
    if (!settings) {
        QMessageBox::critical(this, tr("Add this line to the workspace"), settings.error());
        return;
    }
    bool ok = false;
    const QString name = QInputDialog::getText(
        this, tr("Add this line to the workspace"), tr("Name of the line (cell, station):"),
        QLineEdit::Normal, tr("line-%1").arg(m_workspace.count() + 1), &ok);
    if (!ok)
        return;
    WorkspaceLine line;
    line.name = name.trimmed();
    line.session = *settings;
    m_session.disconnectFromLine();
    if (const auto added = m_workspace.addLine(line); !added)
        QMessageBox::critical(this, tr("Add this line to the workspace"), added.error());
}

} // namespace tipscope::gui
