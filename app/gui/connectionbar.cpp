#include "connectionbar.h"

#include "link/ports/serialportlist.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>

namespace tipscope::gui {

using namespace tipscope::model;

namespace {
// What follows the coloured state word. The session's and the line's texts stand alone in the
// event log and in tipscope-cli, so they begin with the state ("disconnected, retrying every
// 5 s: …"); after the bar's own word that would say it twice, so the repeated start is dropped
// and the rest continues the sentence.
QString detailAfter(const QString &label, const QString &text) {
    if (text.startsWith(label, Qt::CaseInsensitive))
        return text.mid(label.size());
    return text.isEmpty() ? QString() : QStringLiteral(": ") + text;
}
} // namespace

ConnectionBar::ConnectionBar(QWidget *parent)
    : QWidget(parent)
    , m_ports(new link::SerialPortList(QStringLiteral("/sys"), QStringLiteral("/dev/serial/by-id"),
                                       this)) {
    m_kind = new QComboBox(this);
    m_kind->addItem(tr("Serial port"), int(AppSettings::Kind::Serial));
    m_kind->addItem(tr("TCP serial server"), int(AppSettings::Kind::Tcp));
    m_kind->addItem(tr("Demo (simulated DME + SFR)"), int(AppSettings::Kind::Demo));
    m_kind->setAccessibleName(tr("Connection type"));
    m_port = new QComboBox(this);
    m_port->setEditable(true);
    m_port->setMinimumContentsLength(28);
    m_port->setAccessibleName(tr("Serial port"));
    m_port->setToolTip(tr("Serial ports on this computer; you may also type a device path"));
    m_tcp = new QLineEdit(this);
    m_tcp->setPlaceholderText(tr("host:port"));
    m_tcp->setAccessibleName(tr("TCP serial server"));
    m_baud = new QComboBox(this);
    for (int b : {9600, 19200, 38400, 57600, 115200})
        m_baud->addItem(QString::number(b), b);
    m_baud->setAccessibleName(tr("Baud rate"));
    m_parity = new QComboBox(this);
    m_parity->addItem(tr("no parity"), QStringLiteral("none"));
    m_parity->addItem(tr("even"), QStringLiteral("even"));
    m_parity->addItem(tr("odd"), QStringLiteral("odd"));
    m_stopBits = new QComboBox(this);
    m_stopBits->addItem(tr("1 stop bit"), 1);
    m_stopBits->addItem(tr("2 stop bits"), 2);
    m_addressing = new QComboBox(this);
    m_addressing->addItem(tr("Find devices"), int(Session::Addressing::Auto));
    m_addressing->addItem(tr("With addresses"), int(Session::Addressing::With));
    m_addressing->addItem(tr("Without addresses"), int(Session::Addressing::Without));
    m_addressing->setAccessibleName(tr("Addressing"));
    m_robot = new QSpinBox(this);
    m_robot->setRange(0, 99);
    m_robot->setPrefix(tr("robot "));
    m_robot->setAccessibleName(tr("Robot address"));
    m_target = new QSpinBox(this);
    m_target->setRange(0, 99);
    m_target->setPrefix(tr("device "));
    m_target->setAccessibleName(tr("Device address"));
    m_connect = new QPushButton(tr("&Connect"), this);
    m_monitorOnly = new QCheckBox(tr("&Monitor only"), this);
    m_monitorOnly->setToolTip(tr("Block every write: watch a production line without risk"));
    m_state = new QLabel(this);
    m_state->setWordWrap(true);
    m_state->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *row = new QHBoxLayout;
    for (QWidget *w : {static_cast<QWidget *>(m_kind), static_cast<QWidget *>(m_port),
                       static_cast<QWidget *>(m_tcp), static_cast<QWidget *>(m_baud),
                       static_cast<QWidget *>(m_parity), static_cast<QWidget *>(m_stopBits),
                       static_cast<QWidget *>(m_addressing), static_cast<QWidget *>(m_robot),
                       static_cast<QWidget *>(m_target), static_cast<QWidget *>(m_connect),
                       static_cast<QWidget *>(m_monitorOnly)})
        row->addWidget(w);
    row->addStretch(1);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(row);
    layout->addWidget(m_state);

    connect(m_kind, &QComboBox::currentIndexChanged, this, &ConnectionBar::updateVisibility);
    connect(m_addressing, &QComboBox::currentIndexChanged, this, &ConnectionBar::updateVisibility);
    connect(m_connect, &QPushButton::clicked, this, [this] {
        if (m_connected)
            Q_EMIT disconnectRequested();
        else
            Q_EMIT connectRequested();
    });
    connect(m_monitorOnly, &QCheckBox::toggled, this, &ConnectionBar::monitorOnlyToggled);
    connect(m_ports, &link::SerialPortList::changed, this, &ConnectionBar::refreshPorts);
    m_ports->start();
    refreshPorts();
    updateVisibility();
    setState(Session::State::Disconnected, tr("disconnected"));
}

void ConnectionBar::refreshPorts() {
    const QString typed = m_port->currentText();
    const QString current =
        m_port->currentData().toString().isEmpty() ? typed : m_port->currentData().toString();
    m_port->clear();
    for (const link::SerialPortEntry &e : m_ports->ports()) {
        m_port->addItem(e.displayName(), e.systemLocation);
        const int i = m_port->count() - 1;
        QString tip = e.byIdPath.isEmpty() ? e.systemLocation : e.byIdPath;
        if (!e.latencyAdvice().isEmpty())
            tip += QStringLiteral("\n\n") + e.latencyAdvice();
        m_port->setItemData(i, tip, Qt::ToolTipRole);
    }
    const int found = m_port->findData(current);
    if (found >= 0)
        m_port->setCurrentIndex(found);
    else
        m_port->setEditText(current);
}

void ConnectionBar::updateVisibility() {
    const auto kind = AppSettings::Kind(m_kind->currentData().toInt());
    m_port->setVisible(kind == AppSettings::Kind::Serial);
    m_tcp->setVisible(kind == AppSettings::Kind::Tcp);
    const bool serialLine = kind == AppSettings::Kind::Serial;
    m_baud->setVisible(kind != AppSettings::Kind::Demo);
    m_parity->setVisible(serialLine);
    m_stopBits->setVisible(serialLine);
    m_addressing->setVisible(kind != AppSettings::Kind::Demo);
    const auto addressing = Session::Addressing(m_addressing->currentData().toInt());
    m_robot->setVisible(kind != AppSettings::Kind::Demo && addressing == Session::Addressing::With);
    m_target->setVisible(kind != AppSettings::Kind::Demo &&
                         addressing == Session::Addressing::With);
}

void ConnectionBar::setSettings(const AppSettings &a) {
    m_kind->setCurrentIndex(m_kind->findData(int(a.kind)));
    const int p = m_port->findData(a.serialPort);
    if (p >= 0)
        m_port->setCurrentIndex(p);
    else
        m_port->setEditText(a.serialPort);
    m_tcp->setText(a.tcpAddress);
    const int b = m_baud->findData(a.baud);
    if (b >= 0)
        m_baud->setCurrentIndex(b);
    m_parity->setCurrentIndex(qMax(0, m_parity->findData(a.parity)));
    m_stopBits->setCurrentIndex(qMax(0, m_stopBits->findData(a.stopBits)));
    m_addressing->setCurrentIndex(m_addressing->findData(int(a.addressing)));
    m_robot->setValue(a.robotAddress);
    m_target->setValue(a.targetAddress);
    updateVisibility();
}

AppSettings ConnectionBar::settings(const AppSettings &base) const {
    AppSettings a = base;
    a.kind = AppSettings::Kind(m_kind->currentData().toInt());
    const int i = m_port->findText(m_port->currentText());
    a.serialPort = i >= 0 ? m_port->itemData(i).toString() : m_port->currentText().trimmed();
    a.tcpAddress = m_tcp->text().trimmed();
    a.baud = m_baud->currentData().toInt();
    a.parity = m_parity->currentData().toString();
    a.stopBits = m_stopBits->currentData().toInt();
    a.addressing = Session::Addressing(m_addressing->currentData().toInt());
    a.robotAddress = m_robot->value();
    a.targetAddress = m_target->value();
    return a;
}

void ConnectionBar::setBesideNote(const QString &note) {
    m_besideNote = note;
    setState(m_stateShown, m_stateText);
}

void ConnectionBar::setState(Session::State state, const QString &text) {
    m_stateShown = state;
    m_stateText = text;
    m_connected = state != Session::State::Disconnected && state != Session::State::Failed;
    m_connect->setText(m_connected ? tr("&Disconnect") : tr("&Connect"));
    for (QWidget *w : {static_cast<QWidget *>(m_kind), static_cast<QWidget *>(m_port),
                       static_cast<QWidget *>(m_tcp), static_cast<QWidget *>(m_baud),
                       static_cast<QWidget *>(m_parity), static_cast<QWidget *>(m_stopBits),
                       static_cast<QWidget *>(m_addressing), static_cast<QWidget *>(m_robot),
                       static_cast<QWidget *>(m_target)})
        w->setEnabled(!m_connected);
    QString colour = QStringLiteral("#5e5c64");
    QString label;
    switch (state) {
    case Session::State::Connected:
        colour = QStringLiteral("#26a269");
        label = tr("Connected");
        break;
    case Session::State::Connecting:
    case Session::State::Detecting:
        colour = QStringLiteral("#1c71d8");
        label = state == Session::State::Connecting ? tr("Connecting") : tr("Detecting devices");
        break;
    case Session::State::Retrying:
        colour = QStringLiteral("#c64600");
        label = tr("Disconnected, retrying");
        break;
    case Session::State::Failed:
        colour = QStringLiteral("#c01c28");
        label = tr("Cannot connect");
        break;
    case Session::State::Disconnected:
        label = tr("Disconnected");
        break;
    }
    QString detail = detailAfter(label, text);
    if (state == Session::State::Disconnected && !m_besideNote.isEmpty())
        detail = tr(" (this bar's line only: %1)").arg(m_besideNote);
    m_state->setText(QStringLiteral("<span style='color:%1; font-weight:bold'>● %2</span>%3")
                         .arg(colour, label, detail.toHtmlEscaped()));
    m_state->setAccessibleName(label + detail);
}

void ConnectionBar::setMonitorOnly(bool on) {
    m_monitorOnly->setChecked(on);
}

QString ConnectionBar::stateText() const {
    return m_state->accessibleName();
}

} // namespace tipscope::gui
