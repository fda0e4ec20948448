#include "portcard.h"

#include "widgets/deferredrefresh.h"

#include "model/stationmodel.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

namespace tipscope::gui {

using namespace tipscope::model;
using protocol::Role;

PortCard::PortCard(PortModel &port, QWidget *parent)
    : QFrame(parent)
    , m_port(&port) {
    setFrameShape(QFrame::StyledPanel);
    setAccessibleName(tr("Port %1").arg(port.number()));
    m_title = new QLabel(this);
    QFont titleFont = m_title->font();
    titleFont.setBold(true);
    titleFont.setPointSizeF(titleFont.pointSizeF() * 1.2);
    m_title->setFont(titleFont);
    m_tip = new QLabel(this);
    QFont big = m_tip->font();
    big.setPointSizeF(big.pointSizeF() * 3.2);
    big.setBold(true);
    m_tip->setFont(big);
    m_tip->setAccessibleName(tr("Tip temperature, port %1").arg(port.number()));
    m_setpoint = new QLabel(this);
    QFont mid = m_setpoint->font();
    mid.setPointSizeF(mid.pointSizeF() * 1.3);
    m_setpoint->setFont(mid);
    m_power = new QProgressBar(this);
    m_power->setRange(0, 1000);
    m_power->setAccessibleName(tr("Power, port %1").arg(port.number()));
    m_status = new QLabel(this);
    m_status->setFont(mid);
    m_details = new QLabel(this);
    m_problem = new QLabel(this);
    m_problem->setWordWrap(true);
    m_work = new QPushButton(tr("Work"), this);
    m_stand = new QPushButton(tr("Stand"), this);
    m_cool = new QPushButton(tr("Cool"), this);
    m_work->setToolTip(tr("W-PS%1 00000: heat to the selected temperature").arg(port.number()));
    m_stand->setToolTip(tr("W-PS%1 00001: stand; sleep and hibernation follow after their delays")
                            .arg(port.number()));
    m_cool->setToolTip(tr("W-PS%1 00010: cooling (extractor stand-by)").arg(port.number()));
    const Parameter *ps = port.parameter(Role::Status);
    m_cool->setVisible(ps && ps->spec().values.contains(10));
    m_newSetpoint = new QDoubleSpinBox(this);
    m_newSetpoint->setAccessibleName(tr("New selected temperature, port %1").arg(port.number()));
    m_set = new QPushButton(tr("Set"), this);
    m_feedback = new QLabel(this);
    m_feedback->setWordWrap(true);

    auto *controls = new QHBoxLayout;
    controls->addWidget(m_work);
    controls->addWidget(m_stand);
    controls->addWidget(m_cool);
    controls->addStretch(1);
    controls->addWidget(m_newSetpoint);
    controls->addWidget(m_set);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    auto *temps = new QHBoxLayout;
    temps->addWidget(m_tip);
    temps->addStretch(1);
    temps->addWidget(m_setpoint, 0, Qt::AlignBottom);
    layout->addLayout(temps);
    layout->addWidget(m_power);
    layout->addWidget(m_status);
    layout->addWidget(m_details);
    layout->addWidget(m_problem);
    layout->addLayout(controls);
    layout->addWidget(m_feedback);

    connect(m_work, &QPushButton::clicked, this, [this] { requestMode(0); });
    connect(m_stand, &QPushButton::clicked, this, [this] { requestMode(1); });
    connect(m_cool, &QPushButton::clicked, this, [this] { requestMode(10); });
    connect(m_set, &QPushButton::clicked, this,
            [this] { requestSetpoint(m_newSetpoint->value()); });
    m_refresh = new DeferredRefresh(*this, [this] { refresh(); });
    connect(&port, &PortModel::changed, m_refresh, &DeferredRefresh::request);
    connect(&port.station(), &DeviceModel::temperatureUnitChanged, m_refresh,
            &DeferredRefresh::request);
    for (Parameter *p : port.parameters({Role::Setpoint, Role::Status}))
        connect(p, &Parameter::stateChanged, this, [this, p] {
            if (p->state() == Parameter::State::Failed)
                m_feedback->setText(
                    tr("<span style='color:#c01c28'>%1</span>").arg(p->failure().toHtmlEscaped()));
            else if (p->state() == Parameter::State::InSync)
                m_feedback->clear();
        });
    refresh();
}

void PortCard::setWritesAllowed(bool allowed) {
    const QString why = allowed ? QString() : tr("Monitor-only mode is on: nothing is written");
    for (QWidget *w : {static_cast<QWidget *>(m_work), static_cast<QWidget *>(m_stand),
                       static_cast<QWidget *>(m_cool), static_cast<QWidget *>(m_set),
                       static_cast<QWidget *>(m_newSetpoint)}) {
        w->setEnabled(allowed);
        if (!allowed)
            w->setToolTip(why);
    }
}

QString PortCard::tipText() {
    m_refresh->flush();
    return m_tip->text();
}
QString PortCard::statusText() {
    m_refresh->flush();
    return m_status->text();
}
QString PortCard::problemText() {
    m_refresh->flush();
    return m_problem->text();
}

void PortCard::refresh() {
    if (!m_port)
        return;
    PortModel &port = *m_port;
    const TemperatureUnit unit = port.station().temperatureUnit();
    m_title->setText(tr("Port %1 — %2").arg(port.number()).arg(port.toolName()));
    m_tip->setText(port.tipTemperature() ? port.displayText(Role::TipTemperature) : tr("— °"));
    m_setpoint->setText(tr("set %1").arg(port.displayText(Role::Setpoint)));
    m_power->setValue(int(port.power().value_or(0)));
    m_power->setFormat(tr("power %1").arg(port.displayText(Role::Power)));
    const auto status = port.status();
    m_status->setText(status ? status->text() : tr("status unknown"));
    QStringList details;
    if (Parameter *qt = port.parameter(Role::TransistorTemperature); qt && qt->value())
        details.append(tr("transistor %1").arg(qt->displayText()));
    if (Parameter *ed = port.parameter(Role::TimeToNextMode); ed && ed->number().value_or(0) > 0)
        details.append(tr("%1 until the next mode").arg(ed->displayText()));
    m_details->setText(details.join(QStringLiteral(" · ")));
    QStringList problems;
    if (const auto e = port.error(); e && *e != 0)
        problems.append(port.errorText());
    if (const auto alarm = port.alarm(); alarm && alarm->any())
        problems.append(port.displayText(Role::Alarm));
    m_problem->setText(
        problems.isEmpty() ? QString() : QStringLiteral("⚠ ") + problems.join(QLatin1String("; ")));
    m_problem->setStyleSheet(
        problems.isEmpty() ? QString() : QStringLiteral("color: #c01c28; font-weight: bold;"));
    // Keep the setpoint editor in display units and within the station's limits.
    const Parameter *st = port.parameter(Role::Setpoint);
    if (!st)
        return;
    const DisplayFormat f = displayFormat(st->spec(), unit);
    m_newSetpoint->blockSignals(true);
    m_newSetpoint->setSuffix(QLatin1Char(' ') + f.unit);
    m_newSetpoint->setDecimals(0);
    m_newSetpoint->setSingleStep(st->meta().step * f.scale);
    m_newSetpoint->setRange(toDisplay(st->spec(), st->minimum(), unit),
                            toDisplay(st->spec(), st->maximum(), unit));
    if (!m_newSetpoint->hasFocus() && st->number())
        m_newSetpoint->setValue(toDisplay(st->spec(), *st->number(), unit));
    m_newSetpoint->blockSignals(false);
}

QString PortCard::requestMode(int mode) {
    const QString why = m_port ? m_port->setMode(mode) : QString();
    m_feedback->setText(
        why.isEmpty()
            ? QString()
            : QStringLiteral("<span style='color:#c01c28'>%1</span>").arg(why.toHtmlEscaped()));
    return why;
}

QString PortCard::requestSetpoint(double displayValue) {
    if (!m_port)
        return {};
    // A port without a setpoint is refused by the model, which says why.
    const Parameter *st = m_port->parameter(Role::Setpoint);
    const qint64 wire =
        st ? fromDisplay(st->spec(), displayValue, m_port->station().temperatureUnit()) : 0;
    const QString why = m_port->setSelectedTemperature(wire);
    m_feedback->setText(
        why.isEmpty()
            ? QString()
            : QStringLiteral("<span style='color:#c01c28'>%1</span>").arg(why.toHtmlEscaped()));
    return why;
}

} // namespace tipscope::gui
