#include "portcard.h"

#include "widgets/deferredrefresh.h"
#include "widgets/sparkline.h"
#include "widgets/valuespinbox.h"

#include "model/device/stationmodel.h"
#include "model/joints/jointtable.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QStyle>
#include <QVBoxLayout>

namespace tipscope::gui {

using namespace tipscope::model;
using protocol::Role;

namespace {
const QString kRed = QStringLiteral("#c01c28");
const QString kAmber = QStringLiteral("#8a5a00");
const QString kGreen = QStringLiteral("#26734d");
const QString kBlue = QStringLiteral("#1c5ea8");
constexpr int kLineSpacing = 2;
constexpr int kMargin = 8;

QString coloured(const QString &colour, const QString &text) {
    return QStringLiteral("<span style='color:%1'>%2</span>").arg(colour, text.toHtmlEscaped());
}

QFont scaled(const QFont &base, double factor, bool bold) {
    QFont f = base;
    f.setPointSizeF(f.pointSizeF() * factor);
    f.setBold(bold);
    return f;
}
} // namespace

PortCard::PortCard(PortModel &port, Telemetry &telemetry, const QString &telemetryKey,
                   QWidget *parent)
    : QFrame(parent)
    , m_port(&port) {
    setObjectName(QStringLiteral("portCard"));
    setFrameShape(QFrame::StyledPanel);
    setAccessibleName(tr("Port %1").arg(port.number()));
    m_values = new QWidget(this);
    m_title = new QLabel(m_values);
    m_title->setFont(scaled(m_title->font(), 1.2, true));
    // The title and the last joint share a line; the title wraps rather than widen the card (a
    // long tool name beside a joint pushed the right-hand cards under a side scroll bar). The
    // joint keeps one line: wrapping too, it took two where the title had room to give.
    m_title->setWordWrap(true);
    m_joint = new QLabel(m_values);
    m_joint->setObjectName(QStringLiteral("lastJoint"));
    m_joint->setAlignment(Qt::AlignRight | Qt::AlignBottom);
    m_joint->hide();
    m_tip = new QLabel(m_values);
    m_tip->setFont(scaled(m_tip->font(), 3.2, true));
    m_tip->setAccessibleName(tr("Tip temperature, port %1").arg(port.number()));
    m_setpoint = new QLabel(m_values);
    const QFont mid = scaled(m_setpoint->font(), 1.3, false);
    m_setpoint->setFont(mid);
    m_power = new QProgressBar(m_values);
    m_power->setRange(0, 1000);
    m_power->setAccessibleName(tr("Power, port %1").arg(port.number()));
    // The words beside the bar, not on it: centred on the bar they ran into the fill and were
    // hard to read on its colour ("potencia 40,7 %").
    m_power->setTextVisible(false);
    m_power->setMaximumHeight(fontMetrics().height());
    m_powerText = new QLabel(m_values);
    m_powerText->setObjectName(QStringLiteral("powerText"));
    m_status = new QLabel(m_values);
    m_status->setFont(mid);
    m_status->setWordWrap(true);
    m_details = new QLabel(m_values);
    m_details->setWordWrap(true);
    m_problem = new QLabel(m_values);
    m_problem->setWordWrap(true);
    m_sparkline = new Sparkline(telemetry, telemetryKey, m_values);
    m_sparkline->setTemperatureText([this](qint32 celsius) {
        const Parameter *tip = m_port ? m_port->parameter(Role::TipTemperature) : nullptr;
        return tip ? formatNumber(tip->spec(), celsius, m_port->station().temperatureUnit())
                   : QString::number(celsius);
    });
    m_stale = new QLabel(this);
    m_stale->setVisible(false);
    m_work = new QPushButton(tr("Work"), this);
    m_stand = new QPushButton(tr("Stand"), this);
    m_cool = new QPushButton(tr("Cool"), this);
    m_work->setToolTip(tr("W-PS%1 00000: heat to the selected temperature").arg(port.number()));
    m_stand->setToolTip(tr("W-PS%1 00001: stand; sleep and hibernation follow after their delays")
                            .arg(port.number()));
    m_cool->setToolTip(tr("W-PS%1 00010: cooling (extractor stand-by)").arg(port.number()));
    const Parameter *ps = port.parameter(Role::Status);
    m_cool->setVisible(ps && ps->spec().values.contains(10));
    m_newSetpoint = new ValueSpinBox(this);
    m_newSetpoint->setAccessibleName(tr("New selected temperature, port %1").arg(port.number()));
    m_set = new QPushButton(tr("Set"), this);
    m_feedback = new QLabel(this);
    m_feedback->setWordWrap(true);
    m_feedback->hide();

    auto *temps = new QHBoxLayout;
    temps->addWidget(m_tip);
    temps->addStretch(1);
    temps->addWidget(m_setpoint, 0, Qt::AlignBottom);
    // What the port does and its side readings share a line; the lines sit close together, so
    // four cards fit in two rows at 1280×720 and the rest of a taller page goes to the sparkline.
    auto *state = new QHBoxLayout;
    state->addWidget(m_status, 1);
    state->addWidget(m_details, 0, Qt::AlignBottom);
    m_details->setAlignment(Qt::AlignRight | Qt::AlignBottom);
    auto *values = new QVBoxLayout(m_values);
    values->setContentsMargins(0, 0, 0, 0);
    values->setSpacing(kLineSpacing);
    // The last joint shares the title's line: the cards grow no taller for it.
    auto *title = new QHBoxLayout;
    title->addWidget(m_title, 1);
    title->addWidget(m_joint, 0, Qt::AlignRight | Qt::AlignBottom);
    values->addLayout(title);
    values->addLayout(temps);
    auto *power = new QHBoxLayout;
    power->addWidget(m_power, 1);
    power->addWidget(m_powerText);
    values->addLayout(power);
    values->addLayout(state);
    values->addWidget(m_problem);
    values->addWidget(m_sparkline, 1);
    // The style gives every button at least 80 px; four of them and the setpoint box made the
    // card wider than half the page at the window's default size. They may shrink to their
    // words when room is short.
    for (QPushButton *b : {m_work, m_stand, m_cool, m_set})
        b->setMinimumWidth(b->fontMetrics().horizontalAdvance(b->text()) +
                           4 * style()->pixelMetric(QStyle::PM_ButtonMargin, nullptr, b));
    auto *controls = new QHBoxLayout;
    controls->addWidget(m_work);
    controls->addWidget(m_stand);
    controls->addWidget(m_cool);
    controls->addStretch(1);
    controls->addWidget(m_newSetpoint);
    controls->addWidget(m_set);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(kMargin, kMargin, kMargin, kMargin);
    layout->setSpacing(kLineSpacing * 2);
    layout->addWidget(m_values, 1);
    layout->addWidget(m_stale);
    layout->addLayout(controls);
    layout->addWidget(m_feedback);

    connect(m_work, &QPushButton::clicked, this, [this] { requestMode(0); });
    connect(m_stand, &QPushButton::clicked, this, [this] { requestMode(1); });
    connect(m_cool, &QPushButton::clicked, this, [this] { requestMode(10); });
    connect(m_set, &QPushButton::clicked, this, [this] {
        m_newSetpoint->interpretText();
        requestSetpoint(m_newSetpoint->value());
    });
    m_refresh = new DeferredRefresh(*this, [this] { refresh(); });
    m_pace.setSingleShot(true);
    connect(&m_pace, &QTimer::timeout, m_refresh, &DeferredRefresh::request);
    connect(&port, &PortModel::changed, this, &PortCard::onPortChanged);
    connect(&port.station(), &DeviceModel::temperatureUnitChanged, m_refresh,
            &DeferredRefresh::request);
    connect(&port.station(), &DeviceModel::lineUpChanged, m_refresh, &DeferredRefresh::request);
    // A failure of the robot controls stays in sight until the value is proved or the failure
    // is cleared (the line that caused it is back).
    for (Parameter *p : port.parameters({Role::Setpoint, Role::Status}))
        connect(p, &Parameter::stateChanged, this, [this, p] {
            if (p->state() == Parameter::State::Failed)
                showFeedback(p->failure());
            else if (p->state() != Parameter::State::Writing)
                showFeedback({});
        });
    refresh();
}

void PortCard::setWritesAllowed(bool allowed) {
    for (QWidget *w : {static_cast<QWidget *>(m_work), static_cast<QWidget *>(m_stand),
                       static_cast<QWidget *>(m_cool), static_cast<QWidget *>(m_set),
                       static_cast<QWidget *>(m_newSetpoint)})
        w->setEnabled(allowed);
}

bool PortCard::controlsEnabled() const {
    return m_work->isEnabled() && m_set->isEnabled();
}

void PortCard::onPortChanged() {
    if (m_pace.isActive())
        return;
    constexpr qint64 kPaceMs = 1000 / kMaxRefreshesPerSecond;
    const qint64 since = m_lastRefresh.isValid() ? m_lastRefresh.elapsed() : kPaceMs;
    if (since >= kPaceMs)
        m_refresh->request();
    else
        m_pace.start(int(kPaceMs - since));
}

void PortCard::settle() {
    if (m_pace.isActive()) {
        m_pace.stop();
        m_refresh->request();
    }
    m_refresh->flush();
}

QString PortCard::tipText() {
    settle();
    return m_tip->text();
}
QString PortCard::statusText() {
    settle();
    return m_status->text();
}
QString PortCard::problemText() {
    settle();
    return m_problem->text();
}
QString PortCard::staleText() {
    settle();
    return m_stale->isHidden() ? QString() : m_stale->text();
}
void PortCard::showJoint(const JointRecord &joint) {
    const QString recovery =
        joint.recoveryMs ? JointTableModel::secondsText(*joint.recoveryMs) : tr("no recovery");
    const QString text =
        tr("last joint %1, %2").arg(recovery, JointTableModel::verdictText(joint.verdict));
    const Level level = jointLevel(joint.verdict);
    const QString colour = level == Level::Ok ? kGreen : level == Level::Warning ? kAmber : kBlue;
    m_joint->setText(coloured(colour, text));
    m_joint->setAccessibleName(text);
    m_joint->show();
}

QString PortCard::jointText() const {
    return m_joint->isHidden() ? QString() : m_joint->accessibleName();
}

QString PortCard::powerText() {
    settle();
    return m_powerText->text();
}
QString PortCard::feedbackText() const {
    return m_feedback->text();
}
Level PortCard::look() {
    settle();
    return m_shownLook;
}

void PortCard::refresh() {
    if (!m_port)
        return;
    m_lastRefresh.start();
    PortModel &port = *m_port;
    m_title->setText(tr("Port %1 — %2").arg(port.number()).arg(port.toolName()));
    m_tip->setText(port.tipTemperature() ? port.displayText(Role::TipTemperature) : tr("— °"));
    m_setpoint->setText(tr("set %1").arg(port.displayText(Role::Setpoint)));
    m_power->setValue(int(port.power().value_or(0)));
    m_powerText->setText(tr("power %1").arg(port.displayText(Role::Power)));
    m_power->setAccessibleDescription(m_powerText->text());
    QStringList details;
    if (Parameter *qt = port.parameter(Role::TransistorTemperature); qt && qt->value())
        details.append(tr("transistor %1").arg(qt->displayText()));
    if (Parameter *ed = port.parameter(Role::TimeToNextMode); ed && ed->number().value_or(0) > 0)
        details.append(tr("%1 until the next mode").arg(ed->displayText()));
    showLine(m_details, details.join(QStringLiteral(" · ")));
    refreshProblem();
    const Parameter *tip = port.parameter(Role::TipTemperature);
    const bool stale = !port.station().isLineUp();
    m_values->setEnabled(!stale);
    m_sparkline->setEnabled(!stale);
    m_stale->setVisible(stale);
    const QDateTime last = tip ? tip->lastUpdate() : QDateTime();
    m_stale->setText(last.isValid()
                         ? tr("Not connected: last read %1")
                               .arg(QLocale().toString(last.time(), QStringLiteral("HH:mm:ss")))
                         : tr("Not connected: not read yet"));
    applyLook(stale ? Level::Unknown : m_look);
    refreshSetpointEditor();
}

void PortCard::refreshProblem() {
    PortModel &port = *m_port;
    const auto status = port.status();
    const QString mode = status ? status->text() : tr("status unknown");
    const auto error = port.error();
    const bool inError = error && *error != 0;
    const auto alarm = port.alarm();
    const bool alarmed = alarm && alarm->any();
    // Not connected, the words stay but their colour goes: an amber error would read as current.
    const bool stale = !port.station().isLineUp();
    // The error in words is the status line; what the port is doing besides goes under it.
    m_look = inError   ? qMax(Level::Warning, port.errorLevel())
             : alarmed ? Level::Warning
                       : Level::Ok;
    if (inError && stale)
        m_status->setText(tr("⚠ Error: %1").arg(port.errorText()).toHtmlEscaped());
    else if (inError)
        m_status->setText(coloured(m_look == Level::Error ? kRed : kAmber,
                                   tr("⚠ Error: %1").arg(port.errorText())));
    else
        m_status->setText(mode.toHtmlEscaped());
    QStringList problems;
    if (inError)
        problems.append(tr("status: %1").arg(mode));
    if (alarmed)
        problems.append(tr("alarm: %1").arg(port.displayText(Role::Alarm)));
    showLine(m_problem, problems.join(QLatin1String(" · ")));
    m_problem->setStyleSheet(alarmed && !stale
                                 ? QStringLiteral("color: %1; font-weight: bold;").arg(kAmber)
                                 : QString());
}

void PortCard::applyLook(Level level) {
    m_shownLook = level;
    // Only the card's own frame: the children keep the style they have.
    QString sheet;
    if (level == Level::Error)
        sheet = QStringLiteral("QFrame#portCard { border: 3px solid %1; border-radius: 4px; "
                               "background: #fbe3e4; }")
                    .arg(kRed);
    else if (level == Level::Warning)
        sheet = QStringLiteral("QFrame#portCard { border: 3px solid #e5a50a; border-radius: 4px; "
                               "background: #fdf3d8; }");
    if (styleSheet() != sheet)
        setStyleSheet(sheet);
}

void PortCard::refreshSetpointEditor() {
    // The setpoint editor in display units; its arrows stay within the station's limits.
    PortModel &port = *m_port;
    const Parameter *st = port.parameter(Role::Setpoint);
    if (!st)
        return;
    const TemperatureUnit unit = port.station().temperatureUnit();
    const DisplayFormat f = displayFormat(st->spec(), unit);
    // Each of these repaints the box, also when nothing changed: only what changed is set.
    const EditorFrame frame{QLatin1Char(' ') + f.unit, st->meta().step * f.scale,
                            toDisplay(st->spec(), st->minimum(), unit),
                            toDisplay(st->spec(), st->maximum(), unit)};
    m_newSetpoint->blockSignals(true);
    if (!frame.sameAs(m_editorFrame)) {
        m_editorFrame = frame;
        m_newSetpoint->setSuffix(frame.suffix);
        m_newSetpoint->setDecimals(0);
        m_newSetpoint->setSingleStep(frame.step);
        m_newSetpoint->setAllowedRange(frame.minimum, frame.maximum);
    }
    if (!m_newSetpoint->hasFocus() && st->number()) {
        const double shown = toDisplay(st->spec(), *st->number(), unit);
        if (m_newSetpoint->value() != shown)
            m_newSetpoint->setValue(shown);
    }
    m_newSetpoint->blockSignals(false);
}

void PortCard::showFeedback(const QString &why) {
    showLine(m_feedback, why.isEmpty() ? QString() : coloured(kRed, why));
}

// An empty line takes no room: four cards fit in two rows at 1280×720 without scrolling.
void PortCard::showLine(QLabel *label, const QString &text) {
    label->setText(text);
    label->setVisible(!text.isEmpty());
}

QString PortCard::requestMode(int mode) {
    const QString why = m_port ? m_port->setMode(mode) : QString();
    showFeedback(why);
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
    showFeedback(why);
    return why;
}

} // namespace tipscope::gui
