#include "errorspage.h"

#include "eventhistorymodel.h"
#include "problemlevel.h"

#include "protocol/catalog.h"
#include "widgets/deferredrefresh.h"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSaveFile>
#include <QScrollBar>
#include <QStandardPaths>
#include <QStyle>
#include <QTableView>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace tipscope::gui {

using namespace tipscope::model;
using protocol::Catalog;

namespace {

constexpr int kFlushMs = 100; // new events are shown at most ten times a second
constexpr int kMaxStateRowsShown = 10;

// Tabs and line breaks inside a field would break the one-event-a-line text format.
QString flat(QString text) {
    text.replace(QLatin1Char('\t'), QLatin1Char(' '));
    text.replace(QLatin1Char('\n'), QLatin1Char(' '));
    return text;
}

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

} // namespace

ErrorsPage::ErrorsPage(Session &session, QWidget *parent)
    : Page(session, parent) {
    m_flush.setSingleShot(true);
    m_flush.setInterval(kFlushMs);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(buildStatePanel());
    layout->addWidget(buildHistoryPanel(), 1);

    connect(&m_flush, &QTimer::timeout, this, &ErrorsPage::flushEvents);
    connect(&m_session.eventLog(), &EventLog::appended, this, [this](const Event &e) {
        m_pending.append(e);
        if (!m_flush.isActive())
            m_flush.start();
    });
    connect(&m_session.eventLog(), &EventLog::cleared, this, [this] {
        m_pending.clear();
        m_events->reset({});
        updateCount();
    });
    connect(&m_session, &Session::devicesChanged, this, &ErrorsPage::rebuildState);
    connect(&m_session, &Session::monitorOnlyChanged, this, &ErrorsPage::updateButtons);
    m_events->reset(m_session.eventLog().events());
    m_history->scrollToBottom();
    updateCount();
    rebuildState();
}

ErrorsPage::~ErrorsPage() {
    // Before the tables: no connection may outlive the rows it writes to.
    delete m_bindings;
}

QWidget *ErrorsPage::buildStatePanel() {
    auto *box = new QGroupBox(tr("Current state"), this);
    m_state = new QTableWidget(0, 5, box);
    m_state->setObjectName(QStringLiteral("currentState"));
    m_state->setAccessibleName(tr("Current errors and alarms"));
    m_state->setHorizontalHeaderLabels(
        {tr("Where"), tr("Tool"), tr("Severity"), tr("Error"), tr("Temperature alarm")});
    m_state->verticalHeader()->hide();
    m_state->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_state->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_state->setTabKeyNavigation(false);
    m_state->setWordWrap(false);
    QHeaderView *header = m_state->horizontalHeader();
    header->setDefaultAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    header->setSectionResizeMode(QHeaderView::ResizeToContents);
    header->setSectionResizeMode(3, QHeaderView::Stretch);

    m_resetFeeder = new QPushButton(tr("&Reset feeder error"), box);
    m_resetFeeder->setObjectName(QStringLiteral("resetFeederError"));
    m_resetFeeder->setAccessibleName(tr("Reset feeder error"));
    m_status = new QLabel(box);
    m_status->setAccessibleName(tr("Result of the last action"));
    auto *row = new QHBoxLayout;
    row->addWidget(m_resetFeeder);
    row->addWidget(m_status, 1);

    auto *layout = new QVBoxLayout(box);
    layout->addWidget(m_state);
    layout->addLayout(row);
    connect(m_resetFeeder, &QPushButton::clicked, this, &ErrorsPage::resetFeederError);
    return box;
}

QWidget *ErrorsPage::buildHistoryPanel() {
    auto *box = new QGroupBox(tr("History"), this);
    m_kindFilter = new QComboBox(box);
    m_kindFilter->setObjectName(QStringLiteral("kindFilter"));
    m_kindFilter->setAccessibleName(tr("Show events of kind"));
    m_kindFilter->addItem(tr("All kinds"), kAllEventKinds);
    m_kindFilter->addItem(tr("Errors and alarms"), kErrorEventKinds);
    const std::pair<Event::Kind, QString> kinds[] = {
        {Event::Kind::StationError, tr("Station errors")},
        {Event::Kind::PortError, tr("Port errors")},
        {Event::Kind::FeederError, tr("Feeder errors")},
        {Event::Kind::Alarm, tr("Alarms")},
        {Event::Kind::Status, tr("Status changes")},
        {Event::Kind::Write, tr("Writes")},
        {Event::Kind::Communication, tr("Communication")},
        {Event::Kind::Connection, tr("Connection")}};
    for (const auto &[kind, name] : kinds)
        m_kindFilter->addItem(name, eventKindBit(kind));
    m_severityFilter = new QComboBox(box);
    m_severityFilter->setObjectName(QStringLiteral("severityFilter"));
    m_severityFilter->setAccessibleName(tr("Show events of severity"));
    m_severityFilter->addItem(tr("Any severity"), int(Event::Severity::Info));
    m_severityFilter->addItem(tr("Warnings and errors"), int(Event::Severity::Warning));
    m_severityFilter->addItem(tr("Errors only"), int(Event::Severity::Error));
    m_textFilter = new QLineEdit(box);
    m_textFilter->setObjectName(QStringLiteral("textFilter"));
    m_textFilter->setAccessibleName(tr("Show events containing"));
    m_textFilter->setPlaceholderText(tr("Text in any column"));
    m_textFilter->setClearButtonEnabled(true);
    auto *kindLabel = new QLabel(tr("&Kind:"), box);
    kindLabel->setBuddy(m_kindFilter);
    auto *severityLabel = new QLabel(tr("Se&verity:"), box);
    severityLabel->setBuddy(m_severityFilter);
    auto *textLabel = new QLabel(tr("&Search:"), box);
    textLabel->setBuddy(m_textFilter);
    auto *filters = new QHBoxLayout;
    filters->addWidget(kindLabel);
    filters->addWidget(m_kindFilter);
    filters->addSpacing(12);
    filters->addWidget(severityLabel);
    filters->addWidget(m_severityFilter);
    filters->addSpacing(12);
    filters->addWidget(textLabel);
    filters->addWidget(m_textFilter, 1);

    m_events = new EventHistoryModel(this);
    m_filter = new EventHistoryFilter(this);
    m_filter->setSourceModel(m_events);
    m_history = new QTableView(box);
    m_history->setObjectName(QStringLiteral("history"));
    m_history->setAccessibleName(tr("Event history"));
    m_history->setModel(m_filter);
    m_history->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_history->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_history->setTabKeyNavigation(false);
    m_history->setWordWrap(false);
    m_history->setAlternatingRowColors(true);
    m_history->verticalHeader()->hide();
    // Fixed row heights and column widths: measuring 10 000 rows on every insert would not be.
    m_history->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_history->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 8);
    QHeaderView *header = m_history->horizontalHeader();
    header->setDefaultAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    header->setStretchLastSection(true);
    const int pad = 24 + style()->pixelMetric(QStyle::PM_SmallIconSize);
    const QFontMetrics fm = fontMetrics();
    header->resizeSection(EventHistoryModel::Time,
                          fm.horizontalAdvance(QStringLiteral("00:00:00")) + pad);
    header->resizeSection(EventHistoryModel::Severity,
                          fm.horizontalAdvance(levelName(Level::Warning)) + pad);
    header->resizeSection(EventHistoryModel::Kind,
                          fm.horizontalAdvance(Event::kindTitle(Event::Kind::Communication)) + pad);
    header->resizeSection(EventHistoryModel::Source,
                          fm.horizontalAdvance(QStringLiteral("DME-2C at 01, port 4")) + pad);
    auto *copyAction = new QAction(tr("Copy"), m_history);
    copyAction->setShortcut(QKeySequence::Copy);
    copyAction->setShortcutContext(Qt::WidgetShortcut);
    m_history->addAction(copyAction);

    m_count = new QLabel(box);
    m_count->setAccessibleName(tr("Events shown"));
    m_copy = new QPushButton(tr("&Copy"), box);
    m_copy->setObjectName(QStringLiteral("copyEvents"));
    m_copy->setToolTip(tr("Copy the selected events to the clipboard (Ctrl+C)"));
    m_copy->setAccessibleName(tr("Copy selected events"));
    m_export = new QPushButton(tr("E&xport…"), box);
    m_export->setObjectName(QStringLiteral("exportEvents"));
    m_export->setToolTip(tr("Save the events shown as a tab-separated text file"));
    m_export->setAccessibleName(tr("Export events"));
    m_historyStatus = new QLabel(box);
    m_historyStatus->setAccessibleName(tr("Result of the last export"));
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_count);
    buttons->addWidget(m_historyStatus, 1);
    buttons->addWidget(m_copy);
    buttons->addWidget(m_export);

    auto *layout = new QVBoxLayout(box);
    layout->addLayout(filters);
    layout->addWidget(m_history, 1);
    layout->addLayout(buttons);

    connect(m_kindFilter, &QComboBox::currentIndexChanged, this, &ErrorsPage::applyFilters);
    connect(m_severityFilter, &QComboBox::currentIndexChanged, this, &ErrorsPage::applyFilters);
    connect(m_textFilter, &QLineEdit::textChanged, this, &ErrorsPage::applyFilters);
    connect(copyAction, &QAction::triggered, this, &ErrorsPage::copySelection);
    connect(m_copy, &QPushButton::clicked, this, &ErrorsPage::copySelection);
    connect(m_export, &QPushButton::clicked, this, &ErrorsPage::chooseExportFile);
    connect(m_history->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &ErrorsPage::updateButtons);
    return box;
}

void ErrorsPage::setActive(bool active) {
    Page::setActive(active);
    // Errors are polled every few seconds; someone opening the page wants them now.
    if (active)
        for (DeviceModel *device : m_session.devices())
            m_session.scheduler().requestRefresh(device, PollClass::Status);
}

void ErrorsPage::rebuildState() {
    // The old devices are gone (or going): drop every connection to them before the rows.
    delete m_bindings;
    m_bindings = new QObject(this);
    // Status values change with every poll; rows of a hidden page catch up when it is shown.
    m_stateRefresh = new DeferredRefresh(
        *m_state, [this](int row) { updateStateRow(row); }, m_bindings);
    m_rows.clear();
    m_state->setRowCount(0);
    for (DeviceModel *device : m_session.devices()) {
        addStateRow(device, 0);
        if (auto *station = qobject_cast<StationModel *>(device))
            for (PortModel *port : station->ports())
                addStateRow(device, port->number());
    }
    const int shown = qBound(1, int(m_rows.size()), kMaxStateRowsShown);
    m_state->setFixedHeight(m_state->horizontalHeader()->sizeHint().height() +
                            shown * m_state->verticalHeader()->defaultSectionSize() +
                            2 * m_state->frameWidth());
    if (m_rows.isEmpty()) {
        m_state->setRowCount(1);
        setCell(m_state, 0, 0, tr("No device is connected."), Level::Unknown);
    }
    updateButtons();
}

void ErrorsPage::addStateRow(DeviceModel *device, int port) {
    const int row = int(m_rows.size());
    m_rows.append({device, port});
    m_state->setRowCount(row + 1);
    QList<Parameter *> watched;
    if (auto *station = qobject_cast<StationModel *>(device)) {
        if (port == 0)
            watched = {station->parameter("SER")};
        else
            for (const char *base : {"PE", "TA", "CT"})
                watched.append(station->port(port)->param(base));
    } else {
        watched = {device->parameter("ECV")};
    }
    // m_bindings goes before the table, and the connections end with the parameters.
    for (Parameter *p : std::as_const(watched)) {
        if (!p)
            continue;
        for (auto signal : {&Parameter::valueChanged, &Parameter::stateChanged})
            connect(p, signal, m_stateRefresh, [this, row] { m_stateRefresh->requestPart(row); });
    }
    updateStateRow(row);
}

void ErrorsPage::updateStateRow(int row) {
    DeviceModel *device = m_rows.value(row).device;
    if (!device)
        return;
    const int portNumber = m_rows.at(row).port;
    const Catalog &catalog = Catalog::builtin();
    // "Where" reads exactly like the history's Source column, so the two can be matched.
    QString where = device->displayName();
    QString tool;
    std::optional<int> code;
    QString table;
    QString explanation;
    std::optional<int> alarms; // ports only
    bool hasAlarms = false;
    if (auto *station = qobject_cast<StationModel *>(device)) {
        if (portNumber == 0) {
            code = station->stationError();
            table = station->familyInfo().stationErrors;
            explanation = station->stationErrorText();
        } else {
            PortModel *port = station->port(portNumber);
            where = tr("%1, port %2").arg(where).arg(portNumber);
            tool = port->toolName();
            code = port->error();
            table = station->familyInfo().portErrors;
            explanation = port->errorText();
            hasAlarms = true;
            if (Parameter *ta = port->param("TA"); ta && ta->number())
                alarms = port->alarmFlags();
        }
    } else if (auto *feeder = qobject_cast<FeederModel *>(device)) {
        code = feeder->errorCode();
        table = QStringLiteral("feederErrors"); // the SFR's one table (Catalog::feederErrorText)
        explanation = feeder->errorText();
    }
    const Level errorLevel = code ? levelOf(catalog.severity(table, *code)) : Level::Unknown;
    if (!code)
        explanation = tr("Not read yet");
    const QString errorTip =
        code ? tr("Error code %1: %2").arg(*code).arg(explanation) : explanation;

    Level alarmLevel = Level::Unknown;
    QString alarmText;
    if (alarms) {
        QStringList parts;
        if (*alarms % 10 == 1)
            parts.append(tr("High temperature"));
        if ((*alarms / 10) % 10 == 1)
            parts.append(tr("Low temperature"));
        alarmLevel = parts.isEmpty() ? Level::Ok : Level::Warning;
        alarmText = parts.isEmpty() ? tr("None") : parts.join(QLatin1String(", "));
    } else if (hasAlarms) {
        alarmText = tr("Not read yet");
    }

    // The row is as bad as its worst part; it is only "OK" once its error has been read.
    Level worst = qMax(errorLevel, alarmLevel);
    if (errorLevel == Level::Unknown && worst <= Level::Ok)
        worst = Level::Unknown;
    setCell(m_state, row, 0, where, Level::Unknown);
    setCell(m_state, row, 1, tool, Level::Unknown);
    setCell(m_state, row, 2, levelName(worst), worst, {}, levelIcon(worst));
    setCell(m_state, row, 3, explanation, errorLevel, errorTip);
    setCell(m_state, row, 4, alarmText, alarmLevel,
            hasAlarms ? QString() : tr("This device has no temperature alarm"));
}

void ErrorsPage::resetFeederError() {
    FeederModel *feeder = m_session.feeder();
    if (!feeder)
        return;
    const QString why = feeder->resetError();
    if (!why.isEmpty()) {
        showStatus(tr("Not reset: %1").arg(why));
        return;
    }
    showStatus(tr("Resetting the feeder error…"));
    QPointer<Parameter> code = feeder->parameter("ECV");
    connect(
        feeder->action("ECV"), &Action::finished, this,
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

void ErrorsPage::updateButtons() {
    FeederModel *feeder = m_session.feeder();
    const Action *reset = feeder ? feeder->action("ECV") : nullptr;
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
    m_copy->setEnabled(m_history->selectionModel()->hasSelection());
}

void ErrorsPage::showStatus(const QString &text) {
    m_status->setText(QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss ")) + text);
}

void ErrorsPage::flushEvents() {
    if (m_pending.isEmpty())
        return;
    // Follow the newest event only while the reader is at the bottom, not while reading back.
    const QScrollBar *bar = m_history->verticalScrollBar();
    const bool follow = bar->value() >= bar->maximum();
    m_events->append(m_pending);
    m_pending.clear();
    if (follow)
        m_history->scrollToBottom();
    updateCount();
}

void ErrorsPage::applyFilters() {
    m_filter->setFilter(m_kindFilter->currentData().toUInt(),
                        Event::Severity(m_severityFilter->currentData().toInt()),
                        m_textFilter->text());
    m_history->scrollToBottom();
    updateCount();
}

void ErrorsPage::updateCount() {
    QString text = tr("%1 of %2 events shown").arg(m_filter->rowCount()).arg(m_events->rowCount());
    if (const qint64 dropped = m_session.eventLog().dropped(); dropped > 0)
        text += QLatin1String("; ") + tr("%n older events were dropped", nullptr, int(dropped));
    m_count->setText(text);
    updateButtons();
}

QString ErrorsPage::rowText(int proxyRow) const {
    const Event &e = m_events->event(m_filter->mapToSource(m_filter->index(proxyRow, 0)).row());
    QStringList fields;
    for (int c = 0; c < EventHistoryModel::ColumnCount; ++c)
        fields.append(flat(EventHistoryModel::text(e, c, true)));
    return fields.join(QLatin1Char('\t'));
}

void ErrorsPage::copySelection() const {
    QList<int> rows;
    for (const QModelIndex &index : m_history->selectionModel()->selectedRows())
        rows.append(index.row());
    if (rows.isEmpty())
        return;
    std::sort(rows.begin(), rows.end()); // in time order, whatever order they were picked in
    QStringList lines;
    for (int row : std::as_const(rows))
        lines.append(rowText(row));
    QApplication::clipboard()->setText(lines.join(QLatin1Char('\n')) + QLatin1Char('\n'));
}

bool ErrorsPage::exportText(const QString &path, QString *error) const {
    QStringList header;
    for (int c = 0; c < EventHistoryModel::ColumnCount; ++c)
        header.append(EventHistoryModel::columnName(c));
    QString text = header.join(QLatin1Char('\t')) + QLatin1Char('\n');
    for (int row = 0; row < m_filter->rowCount(); ++row)
        text += rowText(row) + QLatin1Char('\n');
    // QSaveFile: a failed export never leaves half a file where an old one was.
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(text.toUtf8()) < 0 || !file.commit()) {
        if (error)
            *error = file.errorString();
        return false;
    }
    return true;
}

void ErrorsPage::chooseExportFile() {
    const QString name =
        QStringLiteral("tipscope-events-%1.txt")
            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmm")));
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export events"), QDir(dir).filePath(name), tr("Text files (*.txt *.tsv)"));
    if (path.isEmpty())
        return;
    QString error;
    if (exportText(path, &error))
        m_historyStatus->setText(tr("Saved to %1").arg(QDir::toNativeSeparators(path)));
    else
        QMessageBox::warning(this, tr("Export events"),
                             tr("The events could not be saved: %1").arg(error));
}

} // namespace tipscope::gui
