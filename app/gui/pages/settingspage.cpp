#include "settingspage.h"

#include "dialogs/profiledialog.h"
#include "widgets/deferredrefresh.h"
#include "widgets/flowlayout.h"
#include "widgets/parametereditor.h"

#include "model/profiles/profile.h"

#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QTimer>
#include <QToolButton>

namespace tipscope::gui {

using namespace tipscope::model;
using protocol::Role;

SettingsPage::SettingsPage(Session &session, QWidget *parent)
    : Page(session, parent) {
    auto *bar = new QWidget(this);
    auto *top = new FlowLayout(bar);
    top->setContentsMargins(0, 0, 0, 0);
    m_portBox = new QComboBox(this);
    m_portBox->setAccessibleName(tr("Port"));
    // The items come after the first show: sized once, the box cut "Port 1 (T245/T470 …)" short.
    m_portBox->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_refresh = new QPushButton(tr("Re&fresh"), this);
    m_apply = new QPushButton(tr("&Apply"), this);
    m_revert = new QPushButton(tr("Re&vert"), this);
    m_save = new QPushButton(tr("Save to station &memory"), this);
    m_save->setToolTip(tr("The selected temperature is volatile: W-NVS stores it so that it "
                          "survives a restart"));
    m_actions = new QToolButton(this);
    m_actions->setText(tr("Station actions"));
    m_actions->setPopupMode(QToolButton::InstantPopup);
    m_profiles = new QToolButton(this);
    m_profiles->setText(tr("Profiles"));
    m_profiles->setPopupMode(QToolButton::InstantPopup);
    auto *profileMenu = new QMenu(m_profiles);
    profileMenu->addAction(tr("Save device settings to a profile…"), this,
                           &SettingsPage::saveProfile);
    profileMenu->addAction(tr("Open a profile (compare, dry run, apply)…"), this,
                           &SettingsPage::openProfile);
    m_profiles->setMenu(profileMenu);
    // The port box and the buttons wrap onto a second line where the page is narrow: in one
    // row, the Spanish labels made the page 12 px wider than the others, which took that width
    // from the device tree each time the page was shown.
    auto *portPair = new QWidget(this);
    auto *portLayout = new QHBoxLayout(portPair);
    portLayout->setContentsMargins(0, 0, 0, 0);
    portLayout->addWidget(new QLabel(tr("Port:"), portPair));
    portLayout->addWidget(m_portBox);
    top->addWidget(portPair);
    for (QWidget *w : {static_cast<QWidget *>(m_refresh), static_cast<QWidget *>(m_revert),
                       static_cast<QWidget *>(m_apply), static_cast<QWidget *>(m_save),
                       static_cast<QWidget *>(m_actions), static_cast<QWidget *>(m_profiles)})
        top->addWidget(w);
    m_notice = new QLabel(this);
    m_notice->setWordWrap(true);
    m_notice->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_notice->setVisible(false);
    m_scroll = new QScrollArea(this);
    m_scroll->setWidgetResizable(true);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(bar);
    layout->addWidget(m_notice);
    layout->addWidget(m_scroll, 1);
    connect(m_portBox, &QComboBox::activated, this, [this] {
        m_port = m_portBox->currentData().toInt();
        m_saved.clear();
        rebuild();
    });
    connect(m_apply, &QPushButton::clicked, this, &SettingsPage::applyEdits);
    connect(m_revert, &QPushButton::clicked, this, &SettingsPage::revertEdits);
    connect(m_refresh, &QPushButton::clicked, this, &SettingsPage::refreshValues);
    connect(m_save, &QPushButton::clicked, this, &SettingsPage::saveToMemory);
    connect(&m_session, &Session::monitorOnlyChanged, this, &SettingsPage::updateButtons);
    rebuild();
}

void SettingsPage::setSelection(DeviceModel *device, int port) {
    const bool sameDevice = device == m_device;
    Page::setSelection(device, port);
    if (!sameDevice)
        m_saved.clear();
    if (!sameDevice || (port > 0 && port != m_portBox->currentData().toInt()))
        rebuild();
}

void SettingsPage::setActive(bool active) {
    Page::setActive(active);
    if (active && m_device)
        m_session.scheduler().requestRefresh(m_device, PollClass::Settings);
}

QList<Parameter *> SettingsPage::shownParameters() const {
    QList<Parameter *> out;
    for (ParameterEditor *e : m_editors)
        if (e->parameter())
            out.append(e->parameter());
    return out;
}

void SettingsPage::addGroup(const QString &title, const QList<Parameter *> &params) {
    if (params.isEmpty())
        return;
    auto *box = new QGroupBox(title, m_form);
    auto *form = new QFormLayout(box);
    // The editors take the width: the reason under a refused value wraps at the width shown.
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    for (Parameter *p : params) {
        auto *editor = new ParameterEditor(p, box);
        m_editors.append(editor);
        // In the form's refresh, so the connections end with the form on the next rebuild.
        connect(p, &Parameter::stateChanged, m_buttonsRefresh, &DeferredRefresh::request);
        connect(editor, &ParameterEditor::refusalChanged, m_buttonsRefresh,
                &DeferredRefresh::request);
        auto *label = new QLabel(ParameterEditor::labelFor(*p), box);
        label->setBuddy(editor);
        label->setToolTip(p->description());
        form->addRow(label, editor);
    }
    m_groups->addWidget(box);
}

void SettingsPage::rebuild() {
    m_editors.clear();
    m_form = new QWidget;
    m_groups = new QVBoxLayout(m_form);
    m_scroll->setWidget(m_form); // deletes the previous form and its editors
    m_buttonsRefresh = new DeferredRefresh(
        *this, [this] { updateButtons(); }, m_form);
    if (m_device)
        connect(m_device, &DeviceModel::lineUpChanged, m_buttonsRefresh, &DeferredRefresh::request);
    m_portBox->clear();
    m_actions->setMenu(nullptr);
    auto *station = qobject_cast<StationModel *>(m_device.data());
    auto *feeder = qobject_cast<FeederModel *>(m_device.data());
    if (!m_device) {
        m_groups->addWidget(
            new QLabel(tr("Connect and select a device to see its settings."), m_form));
    } else if (station) {
        auto itemText = [this](const PortModel *port) {
            return tr("Port %1 (%2)").arg(port->number()).arg(port->toolName());
        };
        for (PortModel *port : station->ports()) {
            m_portBox->addItem(itemText(port), port->number());
            // Every port's tool is read after the box is made: its text follows.
            if (Parameter *tool = port->parameter(Role::ConnectedTool))
                connect(tool, &Parameter::valueChanged, m_form, [this, port, itemText] {
                    m_portBox->setItemText(m_portBox->findData(port->number()), itemText(port));
                });
        }
        const int portNumber = qBound(1, m_port, qMax(1, int(station->ports().size())));
        m_portBox->setCurrentIndex(m_portBox->findData(portNumber));
        addGroup(tr("Station"), station->stationSettings());
        if (PortModel *port = station->port(portNumber)) {
            // Another tool on the shown port changes which settings come first: lay out again,
            // once, after the current event (the signal may come from inside a reply handler).
            if (Parameter *tool = port->parameter(Role::ConnectedTool))
                connect(tool, &Parameter::valueChanged, m_form,
                        [this] { QTimer::singleShot(0, m_form, [this] { rebuild(); }); });
            addGroup(tr("Port %1").arg(portNumber), port->settings());
            addGroup(tr("Alarms, port %1").arg(portNumber), port->alarmSettings());
            for (int tool : port->toolOrder()) {
                QString title = tr("Tool %1, port %2").arg(port->toolName(tool)).arg(portNumber);
                if (port->tool() == tool)
                    title += tr(" (connected)");
                addGroup(title, port->toolSettings(tool));
            }
        }
        addGroup(tr("Dispensing (ALE wire feed)"), station->dispensingSettings());
        auto *menu = new QMenu(m_actions);
        for (Action *a : station->actions())
            if (a->isDangerous())
                menu->addAction(a->name() + QStringLiteral("…"), this,
                                [this, code = a->code()] { runDangerous(code); });
        m_actions->setMenu(menu);
    } else if (feeder) {
        addGroup(tr("Feeding"), feeder->settings());
    }
    m_portBox->setVisible(station != nullptr);
    m_groups->addStretch(1);
    updateButtons();
}

ParameterEditor *SettingsPage::editorFor(const QByteArray &code) const {
    for (ParameterEditor *e : m_editors)
        if (e->parameter() && e->parameter()->code() == code)
            return e;
    return nullptr;
}

QWidget *SettingsPage::button(const QString &name) const {
    const QMap<QString, QWidget *> buttons{
        {QStringLiteral("apply"), m_apply},     {QStringLiteral("revert"), m_revert},
        {QStringLiteral("refresh"), m_refresh}, {QStringLiteral("save"), m_save},
        {QStringLiteral("actions"), m_actions}, {QStringLiteral("profiles"), m_profiles}};
    return buttons.value(name);
}

QString SettingsPage::noticeText() const {
    return m_notice->isHidden() ? QString() : m_notice->text();
}

int SettingsPage::editedCount() const {
    int n = 0;
    for (const Parameter *p : shownParameters())
        if (p->state() == Parameter::State::Edited ||
            (p->state() == Parameter::State::Failed && p->edit()))
            ++n;
    return n;
}

bool SettingsPage::anyRefusal() const {
    return std::any_of(m_editors.begin(), m_editors.end(),
                       [](const ParameterEditor *e) { return e->hasRefusal(); });
}

void SettingsPage::updateButtons() {
    const int edited = editedCount();
    const bool refused = anyRefusal();
    // An edit after the save is a new action: the confirmation of the old one would read as
    // being about it.
    if (edited != m_editsAtSave || refused != m_refusedAtSave)
        m_saved.clear();
    const bool lineUp = m_device && m_device->isLineUp();
    const bool writable = m_device && m_device->writesUnavailableReason().isEmpty();
    m_apply->setText(edited ? tr("&Apply (%1)").arg(edited) : tr("&Apply"));
    m_apply->setEnabled(writable && edited > 0);
    m_revert->setEnabled(edited > 0 || refused);
    m_refresh->setEnabled(lineUp);
    m_save->setEnabled(writable && m_device->action(Role::SaveToMemory));
    m_actions->setEnabled(writable && m_actions->menu() && !m_actions->menu()->isEmpty());
    m_profiles->setEnabled(lineUp); // saving and comparing write nothing; the dialog's Apply does
    QStringList notice;
    if (m_device && !lineUp)
        notice.append(tr("⚠ Not connected: the greyed values are as last read (the time is "
                         "beside each). Apply, Save to station memory, Station actions and "
                         "Profiles wait for the line."));
    else if (m_device && !writable)
        notice.append(tr("Monitor-only mode is on: Apply, Save to station memory and Station "
                         "actions are off, nothing is written."));
    if (!m_saved.isEmpty())
        notice.append(m_saved);
    m_notice->setText(notice.join(QLatin1Char('\n')));
    m_notice->setVisible(!notice.isEmpty());
    m_notice->setStyleSheet(m_device && !writable
                                ? QStringLiteral("QLabel { background: #fdf3d8; border: 1px solid "
                                                 "#e5a50a; padding: 6px; }")
                                : QStringLiteral("QLabel { padding: 6px; }"));
}

void SettingsPage::refreshValues() {
    forgetSavedProfile();
    for (ParameterEditor *e : std::as_const(m_editors))
        e->discardRefusal();
    for (Parameter *p : shownParameters())
        p->refresh();
    updateButtons();
}

void SettingsPage::applyEdits() {
    forgetSavedProfile();
    for (Parameter *p : shownParameters())
        if (p->edit() &&
            (p->state() == Parameter::State::Edited || p->state() == Parameter::State::Failed))
            p->apply();
}

void SettingsPage::revertEdits() {
    forgetSavedProfile();
    for (ParameterEditor *e : std::as_const(m_editors))
        e->discardRefusal();
    for (Parameter *p : shownParameters())
        p->revert();
    updateButtons();
}

// "✓ Profile saved" is about the save just done; the next action has a result of its own.
void SettingsPage::forgetSavedProfile() {
    if (m_saved.isEmpty())
        return;
    m_saved.clear();
    updateButtons();
}

void SettingsPage::saveToMemory() {
    forgetSavedProfile();
    QString why;
    if (auto *st = qobject_cast<StationModel *>(m_device.data()))
        why = st->saveToMemory();
    else if (auto *fd = qobject_cast<FeederModel *>(m_device.data()))
        why = fd->saveToMemory();
    if (!why.isEmpty())
        QMessageBox::warning(this, tr("Save to station memory"), why);
}

void SettingsPage::runDangerous(const QByteArray &code) {
    Action *a = m_device ? m_device->action(code) : nullptr;
    if (!a)
        return;
    forgetSavedProfile();
    qint64 argument = 0;
    if (a->command().spec->role == Role::SetAddress) {
        bool ok = false;
        argument = QInputDialog::getInt(
            this, a->name(), tr("New address (1-99), or 0 for frames without addresses:"),
            m_device->address().value_or(1), 0, 99, 1, &ok);
        if (!ok)
            return;
    }
    const auto answer = QMessageBox::warning(
        this, a->name(),
        tr("%1\n\n%2\n\nDo you want to continue?").arg(a->description(), a->danger()),
        QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel);
    if (answer != QMessageBox::Yes)
        return;
    const QString why = a->trigger(Confirmation::Confirmed, argument);
    if (!why.isEmpty())
        QMessageBox::warning(this, a->name(), why);
}

void SettingsPage::saveProfile() {
    if (!m_device)
        return;
    QStringList missing;
    (void)Profile::capture(*m_device, &missing);
    if (!missing.isEmpty()) {
        QMessageBox::warning(this, tr("Save profile"),
                             tr("Some settings have not been read yet (%1). Refresh and try again.")
                                 .arg(missing.mid(0, 8).join(QLatin1String(", "))));
        return;
    }
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save profile"), m_device->info().model + QStringLiteral(".json"),
        tr("TipScope profiles (*.json)"));
    if (path.isEmpty())
        return;
    bool ok = false;
    const QString comment = QInputDialog::getText(
        this, tr("Save profile"),
        tr("A comment for the profile (optional), e.g. what it is for or who set it:"),
        QLineEdit::Normal, QString(), &ok);
    if (!ok)
        return;
    if (const auto done = saveProfileTo(path, comment); !done)
        QMessageBox::critical(this, tr("Save profile"), done.error());
}

base::Outcome<QString> SettingsPage::saveProfileTo(const QString &path, const QString &comment) {
    if (!m_device)
        return base::failure(tr("no device is selected"));
    Profile p = Profile::capture(*m_device);
    p.comment = comment.trimmed();
    if (const auto saved = p.save(path); !saved.ok())
        return base::failure(saved.error());
    m_saved = tr("✓ Profile saved: %n setting(s) of %1 in %2", nullptr, int(p.values.size()))
                  .arg(m_device->displayName(), QDir::toNativeSeparators(path));
    m_editsAtSave = editedCount();
    m_refusedAtSave = anyRefusal();
    updateButtons();
    return m_saved;
}

void SettingsPage::openProfile() {
    forgetSavedProfile();
    if (!m_device)
        return;
    const QString path = QFileDialog::getOpenFileName(this, tr("Open profile"), QString(),
                                                      tr("TipScope profiles (*.json)"));
    if (path.isEmpty())
        return;
    const auto profile = Profile::load(path);
    if (!profile.ok()) {
        QMessageBox::critical(this, tr("Open profile"), profile.error());
        return;
    }
    ProfileDialog dialog(*m_device, profile.value(), this);
    dialog.exec();
}

} // namespace tipscope::gui
