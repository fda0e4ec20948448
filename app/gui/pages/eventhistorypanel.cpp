#include "eventhistorypanel.h"

#include "levelstyle.h"

#include "base/atomicsave.h"

#include "widgets/startfolder.h"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollBar>
#include <QStyle>
#include <QTableView>
#include <QVBoxLayout>

#include <algorithm>
#include <functional>

namespace tipscope::gui {

using namespace tipscope::model;

namespace {

constexpr int kFlushMs = 100; // new events are shown at most ten times a second

// Tabs and line breaks inside a field would break the one-event-a-line text format.
QString flat(QString text) {
    text.replace(QLatin1Char('\t'), QLatin1Char(' '));
    text.replace(QLatin1Char('\n'), QLatin1Char(' '));
    return text;
}

} // namespace

EventHistoryPanel::EventHistoryPanel(Session &session, QWidget *parent)
    : QGroupBox(tr("History"), parent)
    , m_session(session) {
    m_flush.setSingleShot(true);
    m_flush.setInterval(kFlushMs);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(buildFilters());
    buildView(*layout);

    connect(&m_flush, &QTimer::timeout, this, &EventHistoryPanel::flushEvents);
    connect(&m_session.eventLog(), &EventLog::appended, this, [this](const Event &e) {
        m_pending.append(e);
        if (!m_flush.isActive())
            m_flush.start();
    });
    connect(&m_session.eventLog(), &EventLog::repeated, this, [this](const Event &e) {
        // Not yet shown: the pending copy takes the new count; else the row does at the flush.
        for (Event &pending : m_pending)
            if (pending.id == e.id) {
                pending = e;
                return;
            }
        m_repeats.insert(e.id, e);
        if (!m_flush.isActive())
            m_flush.start();
    });
    connect(&m_session.eventLog(), &EventLog::cleared, this, [this] {
        m_pending.clear();
        m_repeats.clear();
        m_events->reset({});
        updateCount();
    });
    m_events->reset(m_session.eventLog().events());
    addDevices(m_session.eventLog().events());
    fitTimeColumn();
    fitSourceColumn(m_session.eventLog().events());
    updateCount();
}

QLayout *EventHistoryPanel::buildFilters() {
    m_kindFilter = new QComboBox(this);
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
        {Event::Kind::Connection, tr("Connection")},
        {Event::Kind::ToolChange, tr("Tool changes")},
        {Event::Kind::JointWarning, tr("Joints")},
        {Event::Kind::ProfileApply, tr("Profile applies")}};
    for (const auto &[kind, name] : kinds)
        m_kindFilter->addItem(name, eventKindBit(kind));
    m_deviceFilter = new QComboBox(this);
    m_deviceFilter->setObjectName(QStringLiteral("deviceFilter"));
    m_deviceFilter->setAccessibleName(tr("Show events of device"));
    m_deviceFilter->addItem(tr("Every device"), QString());
    // A device is named with its line and software, which can be long: the list shows it whole.
    m_deviceFilter->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_deviceFilter->setMinimumContentsLength(14);
    m_severityFilter = new QComboBox(this);
    m_severityFilter->setObjectName(QStringLiteral("severityFilter"));
    m_severityFilter->setAccessibleName(tr("Show events of severity"));
    m_severityFilter->addItem(tr("Any severity"), int(Event::Severity::Info));
    m_severityFilter->addItem(tr("Warnings and errors"), int(Event::Severity::Warning));
    m_severityFilter->addItem(tr("Errors only"), int(Event::Severity::Error));
    m_textFilter = new QLineEdit(this);
    m_textFilter->setObjectName(QStringLiteral("textFilter"));
    m_textFilter->setAccessibleName(tr("Show events containing"));
    m_textFilter->setPlaceholderText(tr("Text in any column"));
    m_textFilter->setClearButtonEnabled(true);
    auto *deviceLabel = new QLabel(tr("&Device:"), this);
    deviceLabel->setBuddy(m_deviceFilter);
    auto *kindLabel = new QLabel(tr("&Kind:"), this);
    kindLabel->setBuddy(m_kindFilter);
    auto *severityLabel = new QLabel(tr("Se&verity:"), this);
    severityLabel->setBuddy(m_severityFilter);
    auto *textLabel = new QLabel(tr("&Search:"), this);
    textLabel->setBuddy(m_textFilter);
    auto *filters = new QHBoxLayout;
    filters->addWidget(deviceLabel);
    filters->addWidget(m_deviceFilter);
    filters->addSpacing(12);
    filters->addWidget(kindLabel);
    filters->addWidget(m_kindFilter);
    filters->addSpacing(12);
    filters->addWidget(severityLabel);
    filters->addWidget(m_severityFilter);
    filters->addSpacing(12);
    filters->addWidget(textLabel);
    filters->addWidget(m_textFilter, 1);
    connect(m_deviceFilter, &QComboBox::currentIndexChanged, this,
            &EventHistoryPanel::applyFilters);
    connect(m_kindFilter, &QComboBox::currentIndexChanged, this, &EventHistoryPanel::applyFilters);
    connect(m_severityFilter, &QComboBox::currentIndexChanged, this,
            &EventHistoryPanel::applyFilters);
    connect(m_textFilter, &QLineEdit::textChanged, this, &EventHistoryPanel::applyFilters);
    return filters;
}

void EventHistoryPanel::buildView(QVBoxLayout &layout) {
    m_events = new EventHistoryModel(this);
    m_filter = new EventHistoryFilter(this);
    m_filter->setSourceModel(m_events);
    // The newest first, where the eye starts: at the bottom of ten thousand rows it was missed.
    m_filter->sort(0, Qt::DescendingOrder);
    auto *styled =
        new LevelStyleProxy(EventHistoryModel::LevelRole, EventHistoryModel::Severity, this);
    styled->setSourceModel(m_filter);
    m_history = new QTableView(this);
    m_history->setObjectName(QStringLiteral("history"));
    m_history->setAccessibleName(tr("Event history"));
    m_history->setModel(styled);
    m_history->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_history->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_history->setTabKeyNavigation(false);
    m_history->setWordWrap(false);
    m_history->setAlternatingRowColors(true);
    // Whole rows: keeping a reader's rows in place as new ones arrive above counts rows.
    m_history->setVerticalScrollMode(QAbstractItemView::ScrollPerItem);
    m_history->verticalHeader()->hide();
    // Fixed row heights and column widths: measuring 10 000 rows on every insert would not be.
    m_history->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_history->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 8);
    QHeaderView *header = m_history->horizontalHeader();
    header->setDefaultAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    header->setStretchLastSection(true);
    const int pad = 24 + style()->pixelMetric(QStyle::PM_SmallIconSize);
    const QFontMetrics fm = fontMetrics();
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

    m_count = new QLabel(this);
    m_count->setAccessibleName(tr("Events shown"));
    m_copy = new QPushButton(tr("&Copy"), this);
    m_copy->setObjectName(QStringLiteral("copyEvents"));
    m_copy->setToolTip(tr("Copy the selected events to the clipboard (Ctrl+C)"));
    m_copy->setAccessibleName(tr("Copy selected events"));
    m_export = new QPushButton(tr("E&xport…"), this);
    m_export->setObjectName(QStringLiteral("exportEvents"));
    m_export->setToolTip(tr("Save the events shown as a tab-separated text file"));
    m_export->setAccessibleName(tr("Export events"));
    m_status = new QLabel(this);
    m_status->setAccessibleName(tr("Result of the last export"));
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_count);
    buttons->addWidget(m_status, 1);
    buttons->addWidget(m_copy);
    buttons->addWidget(m_export);
    layout.addWidget(m_history, 1);
    layout.addLayout(buttons);

    connect(copyAction, &QAction::triggered, this, &EventHistoryPanel::copySelection);
    connect(m_copy, &QPushButton::clicked, this, &EventHistoryPanel::copySelection);
    connect(m_export, &QPushButton::clicked, this, &EventHistoryPanel::chooseExportFile);
    connect(m_history->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &EventHistoryPanel::updateButtons);
}

void EventHistoryPanel::flushEvents() {
    if (!m_repeats.isEmpty()) {
        m_events->update(m_repeats.values());
        m_repeats.clear();
    }
    if (m_pending.isEmpty())
        return;
    // Follow the newest event (at the top) only while the reader is there; someone reading
    // back keeps the rows they read in place while new ones arrive above.
    QScrollBar *bar = m_history->verticalScrollBar();
    const bool follow = bar->value() <= bar->minimum();
    const int before = m_filter->rowCount();
    m_events->append(m_pending);
    addDevices(m_pending);
    fitSourceColumn(m_pending);
    m_pending.clear();
    fitTimeColumn();
    if (follow)
        m_history->scrollToTop();
    else
        bar->setValue(bar->value() + qMax(0, m_filter->rowCount() - before));
    updateCount();
}

void EventHistoryPanel::fitTimeColumn() {
    // Today's times are short; the date shows (and needs the room) only for older events.
    const bool dated = m_events->rowCount() > 0 &&
                       m_events->event(0).time.toLocalTime().date() != QDate::currentDate();
    const QString widest =
        dated ? QStringLiteral("0000-00-00 00:00:00") : QStringLiteral("00:00:00");
    const int pad = 24 + style()->pixelMetric(QStyle::PM_SmallIconSize);
    m_history->horizontalHeader()->resizeSection(EventHistoryModel::Time,
                                                 fontMetrics().horizontalAdvance(widest) + pad);
}

// A source names its device and port in the interface language ("DME-2C, Adresse 01, Port 4"),
// and a workspace line may give the device a long name: the column grows to the widest source
// shown, never narrower than it was, and leaves the text of what happened at least half.
void EventHistoryPanel::fitSourceColumn(const QList<Event> &events) {
    constexpr int kPad = 24;
    for (const Event &e : events)
        m_widestSource =
            qMax(m_widestSource, fontMetrics().horizontalAdvance(
                                     EventHistoryModel::text(e, EventHistoryModel::Source, false)) +
                                     kPad);
    QHeaderView *header = m_history->horizontalHeader();
    const int shown = header->sectionSize(EventHistoryModel::Source);
    const int wanted = qMin(m_widestSource, qMax(shown, m_history->viewport()->width() / 3));
    if (wanted > shown)
        header->resizeSection(EventHistoryModel::Source, wanted);
}

void EventHistoryPanel::addDevices(const QList<Event> &events) {
    for (const Event &e : events) {
        if (e.device.isEmpty())
            continue;
        const QString key = e.device.key();
        if (m_deviceFilter->findData(key) >= 0)
            continue;
        const QString name = e.device.description();
        m_deviceFilter->addItem(name, key);
        m_deviceFilter->setItemData(m_deviceFilter->count() - 1, name, Qt::ToolTipRole);
    }
}

void EventHistoryPanel::applyFilters() {
    m_filter->setDevice(m_deviceFilter->currentData().toString());
    m_deviceFilter->setToolTip(m_deviceFilter->currentText());
    m_filter->setFilter(m_kindFilter->currentData().toUInt(),
                        Event::Severity(m_severityFilter->currentData().toInt()),
                        m_textFilter->text());
    m_history->scrollToTop();
    updateCount();
}

void EventHistoryPanel::updateCount() {
    QString text = tr("%1 of %2 events shown").arg(m_filter->rowCount()).arg(m_events->rowCount());
    if (const qint64 dropped = m_session.eventLog().dropped(); dropped > 0)
        text += QLatin1String("; ") + tr("%n older events were dropped", nullptr, int(dropped));
    m_count->setText(text);
    updateButtons();
}

void EventHistoryPanel::updateButtons() {
    m_copy->setEnabled(m_history->selectionModel()->hasSelection());
}

QString EventHistoryPanel::rowText(int proxyRow) const {
    const Event &e = m_events->event(m_filter->mapToSource(m_filter->index(proxyRow, 0)).row());
    QStringList fields;
    for (int c = 0; c < EventHistoryModel::ColumnCount; ++c)
        fields.append(flat(EventHistoryModel::text(e, c, true)));
    return fields.join(QLatin1Char('\t'));
}

void EventHistoryPanel::copySelection() const {
    QList<int> rows;
    for (const QModelIndex &index : m_history->selectionModel()->selectedRows())
        rows.append(index.row());
    if (rows.isEmpty())
        return;
    // In time order (the view shows the newest first), whatever order they were picked in.
    std::sort(rows.begin(), rows.end(), std::greater<>());
    QStringList lines;
    for (int row : std::as_const(rows))
        lines.append(rowText(row));
    QApplication::clipboard()->setText(lines.join(QLatin1Char('\n')) + QLatin1Char('\n'));
}

base::Outcome<void> EventHistoryPanel::exportText(const QString &path) const {
    QStringList header;
    for (int c = 0; c < EventHistoryModel::ColumnCount; ++c)
        header.append(EventHistoryModel::columnName(c));
    QString text = header.join(QLatin1Char('\t')) + QLatin1Char('\n');
    for (int row = m_filter->rowCount() - 1; row >= 0; --row) // in time order, as logs are read
        text += rowText(row) + QLatin1Char('\n');
    return base::io::saveAtomically(path, text.toUtf8());
}

void EventHistoryPanel::chooseExportFile() {
    const QString name =
        QStringLiteral("tipscope-events-%1.txt")
            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmm")));
    const QString dir = startFolder();
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export events"), QDir(dir).filePath(name), tr("Text files (*.txt *.tsv)"));
    if (path.isEmpty())
        return;
    if (const auto saved = exportText(path); saved.ok())
        m_status->setText(tr("Saved to %1").arg(QDir::toNativeSeparators(path)));
    else
        QMessageBox::warning(this, tr("Export events"),
                             tr("The events could not be saved: %1").arg(saved.error()));
}

} // namespace tipscope::gui
