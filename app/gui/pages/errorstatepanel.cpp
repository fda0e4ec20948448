#include "errorstatepanel.h"

#include "levelstyle.h"

#include "widgets/deferredrefresh.h"

#include <QDateTime>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QTableWidget>
#include <QVBoxLayout>

namespace tipscope::gui {

using namespace tipscope::model;
using protocol::Role;

namespace {

constexpr int kMaxRowsShown = 10;
constexpr int kAdviceLinesShown = 4; // more scroll

void setCell(QTableWidget *table, int row, int column, const QString &text, Level tintLevel,
             const QString &tip = {}, const QIcon &icon = {}) {
    QTableWidgetItem *item = table->item(row, column);
    if (!item) {
        item = new QTableWidgetItem;
        table->setItem(row, column, item);
    }
    item->setText(text);
    item->setIcon(icon);
    item->setToolTip(tip.isEmpty() ? text : tip);
    item->setData(Qt::BackgroundRole, levelTint(tintLevel));
}

// What one row says: where, which tool, the error and (for ports) the temperature alarm.
struct RowState {
    QString where;
    QString tool;
    std::optional<int> code;
    Level errorLevel = Level::Unknown;
    QString explanation;
    bool hasAlarm = false;
    std::optional<TemperatureAlarm> alarm;
};

RowState stateOf(DeviceModel *device, int portNumber) {
    // "Where" reads exactly like the history's Source column, so the two can be matched.
    RowState s;
    s.where = device->displayName();
    if (auto *station = qobject_cast<StationModel *>(device)) {
        if (portNumber == 0) {
            s.code = station->stationError();
            s.errorLevel = station->stationErrorLevel();
            s.explanation = station->stationErrorText();
            return s;
        }
        PortModel *port = station->port(portNumber);
        s.where = ErrorStatePanel::tr("%1, port %2").arg(s.where).arg(portNumber);
        s.tool = port->toolName();
        s.code = port->error();
        s.errorLevel = port->errorLevel();
        s.explanation = port->errorText();
        s.hasAlarm = port->parameter(Role::Alarm) != nullptr;
        s.alarm = port->alarm();
    } else if (auto *feeder = qobject_cast<FeederModel *>(device)) {
        s.code = feeder->errorCode();
        s.errorLevel = feeder->errorLevel();
        s.explanation = feeder->errorText();
    }
    return s;
}

} // namespace

ErrorStatePanel::ErrorStatePanel(Session &session, QWidget *parent)
    : QGroupBox(tr("Current state"), parent)
    , m_session(session) {
    m_table = new QTableWidget(0, 5, this);
    m_table->setObjectName(QStringLiteral("currentState"));
    m_table->setAccessibleName(tr("Current errors and alarms"));
    m_table->setHorizontalHeaderLabels(
        {tr("Where"), tr("Tool"), tr("Severity"), tr("Error"), tr("Temperature alarm")});
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setTabKeyNavigation(false);
    m_table->setWordWrap(false);
    QHeaderView *header = m_table->horizontalHeader();
    header->setDefaultAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    header->setSectionResizeMode(QHeaderView::ResizeToContents);
    header->setSectionResizeMode(3, QHeaderView::Stretch);

    m_resetFeeder = new QPushButton(tr("&Reset feeder error"), this);
    m_resetFeeder->setObjectName(QStringLiteral("resetFeederError"));
    m_resetFeeder->setAccessibleName(tr("Reset feeder error"));
    m_status = new QLabel(this);
    m_status->setAccessibleName(tr("Result of the last action"));
    auto *row = new QHBoxLayout;
    row->addWidget(m_resetFeeder);
    row->addWidget(m_status, 1);

    m_advice = new QLabel(this);
    m_advice->setObjectName(QStringLiteral("errorAdvice"));
    m_advice->setAccessibleName(tr("What to check"));
    m_advice->setWordWrap(true);
    m_advice->setTextFormat(Qt::PlainText);
    m_advice->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // Several ports in error have much to check: their advice scrolls in a few lines of its own
    // rather than leave the history below two or three rows.
    m_adviceBox = new QScrollArea(this);
    m_adviceBox->setWidget(m_advice);
    m_adviceBox->setWidgetResizable(true);
    m_adviceBox->setFrameShape(QFrame::NoFrame);
    m_adviceBox->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_adviceBox->setMaximumHeight(fontMetrics().lineSpacing() * kAdviceLinesShown +
                                  2 * m_advice->margin());
    m_adviceBox->hide();

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_table);
    layout->addWidget(m_adviceBox);
    layout->addLayout(row);
    connect(m_resetFeeder, &QPushButton::clicked, this, &ErrorStatePanel::resetFeederError);
    connect(&m_session, &Session::devicesChanged, this, &ErrorStatePanel::rebuild);
    connect(&m_session, &Session::monitorOnlyChanged, this, &ErrorStatePanel::updateButtons);
    rebuild();
}

ErrorStatePanel::~ErrorStatePanel() {
    // Before the table: no connection may outlive the rows it writes to.
    delete m_bindings;
}

void ErrorStatePanel::rebuild() {
    // The old devices are gone (or going): drop every connection to them before the rows.
    delete m_bindings;
    m_bindings = new QObject(this);
    // Status values change with every poll; rows of a hidden page catch up when it is shown.
    m_refresh = new DeferredRefresh(
        *m_table, [this](int row) { updateRow(row); }, m_bindings);
    m_rows.clear();
    m_rowAdvice.clear();
    m_table->setRowCount(0);
    for (DeviceModel *device : m_session.devices()) {
        addRow(device, 0);
        if (auto *station = qobject_cast<StationModel *>(device))
            for (PortModel *port : station->ports())
                addRow(device, port->number());
    }
    const int shown = qBound(1, int(m_rows.size()), kMaxRowsShown);
    m_table->setFixedHeight(m_table->horizontalHeader()->sizeHint().height() +
                            shown * m_table->verticalHeader()->defaultSectionSize() +
                            2 * m_table->frameWidth());
    if (m_rows.isEmpty()) {
        m_table->setRowCount(1);
        setCell(m_table, 0, 0, tr("No device is connected."), Level::Unknown);
    }
    updateAdvice();
    updateButtons();
}

void ErrorStatePanel::addRow(DeviceModel *device, int port) {
    const int row = int(m_rows.size());
    m_rows.append({device, port});
    m_table->setRowCount(row + 1);
    // The values the row shows: the error, and on a port its alarm and tool.
    QList<Parameter *> watched{device->parameter(Role::Error, port)};
    if (port > 0)
        watched << device->parameter(Role::Alarm, port)
                << device->parameter(Role::ConnectedTool, port);
    // m_bindings goes before the table, and the connections end with the parameters.
    for (Parameter *p : std::as_const(watched)) {
        if (!p)
            continue;
        for (auto signal : {&Parameter::valueChanged, &Parameter::stateChanged})
            connect(p, signal, m_refresh, [this, row] { m_refresh->requestPart(row); });
    }
    updateRow(row);
}

void ErrorStatePanel::updateRow(int row) {
    DeviceModel *device = m_rows.value(row).device;
    if (!device)
        return;
    RowState s = stateOf(device, m_rows.at(row).port);
    if (!s.code)
        s.explanation = tr("Not read yet");
    const QString errorTip =
        s.code ? tr("Error code %1: %2").arg(*s.code).arg(s.explanation) : s.explanation;
    const Level alarmLevel = s.alarm ? s.alarm->level() : Level::Unknown;
    const QString alarmText = s.alarm      ? s.alarm->text()
                              : s.hasAlarm ? tr("Not read yet")
                                           : QString();
    // The row is as bad as its worst part; it is only "OK" once its error has been read.
    Level worst = qMax(s.errorLevel, alarmLevel);
    if (s.errorLevel == Level::Unknown && worst <= Level::Ok)
        worst = Level::Unknown;
    setCell(m_table, row, 0, s.where, Level::Unknown);
    setCell(m_table, row, 1, s.tool, Level::Unknown);
    setCell(m_table, row, 2, levelName(worst), worst, {}, levelIcon(worst));
    setCell(m_table, row, 3, s.explanation, s.errorLevel, errorTip);
    setCell(m_table, row, 4, alarmText, alarmLevel,
            s.hasAlarm ? QString() : tr("This device has no temperature alarm"));
    // "No tool" on an empty port is information, not a fault to chase.
    const QString advice =
        s.errorLevel >= Level::Warning ? device->errorAdvice(m_rows.at(row).port) : QString();
    QStringList saidParts;
    if (!advice.isEmpty())
        saidParts.append(tr("%1, %2: %3").arg(s.where, s.explanation, advice));
    // An alarm is no error code, but the technician has as much to look at.
    if (s.alarm && s.alarm->any())
        saidParts.append(tr("%1, %2 alarm: %3").arg(s.where, s.alarm->text(), s.alarm->advice()));
    const QString said = saidParts.join(QStringLiteral("\n• "));
    if (said != m_rowAdvice.value(row)) {
        if (said.isEmpty())
            m_rowAdvice.remove(row);
        else
            m_rowAdvice.insert(row, said);
        updateAdvice();
    }
}

void ErrorStatePanel::updateAdvice() {
    QStringList lines;
    for (const QString &said : std::as_const(m_rowAdvice))
        lines.append(QStringLiteral("• ") + said);
    m_advice->setText(lines.isEmpty() ? QString()
                                      : tr("What to check:") + QLatin1Char('\n') +
                                            lines.join(QLatin1Char('\n')));
    m_adviceBox->setVisible(!lines.isEmpty());
}

void ErrorStatePanel::resetFeederError() {
    FeederModel *feeder = m_session.feeder();
    if (!feeder)
        return;
    const QString why = feeder->resetError();
    if (!why.isEmpty()) {
        showStatus(tr("Not reset: %1").arg(why));
        return;
    }
    showStatus(tr("Resetting the feeder error…"));
    QPointer<Parameter> code = feeder->parameter(Role::Error);
    connect(
        feeder->action(Role::ResetError), &Action::finished, this,
        [this, code](bool ok, const QString &reason) {
            if (ok && code)
                code->refresh(); // show the cleared code now rather than at the next poll
            showStatus(ok ? tr("Feeder error reset.")
                          : tr("The feeder error was not reset: %1").arg(reason));
            updateButtons();
        },
        Qt::SingleShotConnection);
    updateButtons();
}

void ErrorStatePanel::updateButtons() {
    FeederModel *feeder = m_session.feeder();
    const Action *reset = feeder ? feeder->action(Role::ResetError) : nullptr;
    const bool blocked = m_session.monitorOnly();
    m_resetFeeder->setEnabled(reset && !blocked && !reset->isRunning());
    if (blocked)
        m_resetFeeder->setToolTip(tr("Monitor-only mode is on: TipScope writes nothing to the "
                                     "devices. Turn it off to reset the feeder error."));
    else if (!reset)
        m_resetFeeder->setToolTip(tr("No feeder is connected"));
    else
        m_resetFeeder->setToolTip(
            tr("Clears the feeder's error code (W-ECV); the feeder does not feed while an error "
               "is set"));
}

void ErrorStatePanel::showStatus(const QString &text) {
    m_status->setText(QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss ")) + text);
}

} // namespace tipscope::gui
