#include "counterspage.h"

#include "base/atomicsave.h"
#include "base/csv.h"
#include "model/device/displayunits.h"
#include "widgets/deferredrefresh.h"

#include "widgets/startfolder.h"

#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QTableWidget>
#include <QVBoxLayout>

namespace tipscope::gui {

using namespace tipscope::model;

namespace {

// The port's counter from the same catalog entry as `row` (another port's), if it has one.
Parameter *sameCounter(const PortModel &port, const Parameter &row) {
    if (row.spec().port == 0)
        return nullptr;
    for (Parameter *p : port.counters())
        if (p->spec().spec == row.spec().spec)
            return p;
    return nullptr;
}

// The words on the button that resets a partial counter: the catalog's label for it.
QString buttonText(const Action &reset) {
    const protocol::CommandSpec &s = *reset.command().spec;
    return s.label.isEmpty() ? reset.name() : protocol::catalogText(s.label);
}

// A value as a spreadsheet parses it: display units, '.' decimal point, empty when unknown. The
// counter keeps the catalog's English name, like the header, whatever the interface language.
QString csvLine(const QString &device, int port, const Parameter &p) {
    const TemperatureUnit unit = p.device().temperatureUnit();
    const DisplayFormat f = displayFormat(p.spec(), unit);
    const auto wire = p.number();
    const QString value =
        wire ? QString::number(toDisplay(p.spec(), *wire, unit), 'f', f.decimals) : QString();
    const QStringList fields{base::csv::quoted(device),
                             port > 0 ? QString::number(port) : QString(),
                             base::csv::quoted(p.meta().name), value, base::csv::quoted(f.unit)};
    return fields.join(QLatin1Char(',')) + QLatin1Char('\n');
}

// The table shows every row without scrolling; the page scrolls instead.
void fitHeight(QTableWidget *table) {
    table->setFixedHeight(table->horizontalHeader()->sizeHint().height() +
                          table->verticalHeader()->length() + 2 * table->frameWidth());
}

QString now() {
    return QDateTime::currentDateTime().toString(QStringLiteral("HH:mm:ss"));
}

} // namespace

CountersPage::CountersPage(Session &session, QWidget *parent)
    : Page(session, parent) {
    m_readAt = new QLabel(this);
    m_readAt->setAccessibleName(tr("When the counters were read"));
    m_status = new QLabel(this);
    m_status->setAccessibleName(tr("Result of the last action"));
    m_status->setWordWrap(true);
    m_refresh = new QPushButton(tr("Re&fresh"), this);
    m_refresh->setToolTip(tr("Read every counter of every device now (they are otherwise read "
                             "once a minute)"));
    m_refresh->setAccessibleName(tr("Refresh counters"));
    m_refresh->setObjectName(QStringLiteral("refreshCounters"));
    m_export = new QPushButton(tr("&Export CSV…"), this);
    m_export->setToolTip(tr("Save every counter of every device as a CSV file"));
    m_export->setAccessibleName(tr("Export counters as CSV"));
    m_export->setObjectName(QStringLiteral("exportCounters"));
    auto *top = new QHBoxLayout;
    top->addWidget(m_readAt);
    top->addSpacing(24);
    top->addWidget(m_status, 1);
    top->addWidget(m_refresh);
    top->addWidget(m_export);

    m_placeholder =
        new QLabel(tr("No device is connected. Connect to a line to read its counters."), this);
    m_placeholder->setAlignment(Qt::AlignCenter);
    auto *content = new QWidget;
    m_boxLayout = new QVBoxLayout(content);
    m_boxLayout->setContentsMargins(0, 0, 0, 0);
    m_boxLayout->addWidget(m_placeholder);
    m_boxLayout->addStretch(1);
    auto *scroll = new QScrollArea(this);
    scroll->setWidget(content);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(scroll, 1);

    connect(m_refresh, &QPushButton::clicked, this, &CountersPage::refresh);
    connect(m_export, &QPushButton::clicked, this, &CountersPage::chooseExportFile);
    connect(&m_session, &Session::devicesChanged, this, &CountersPage::rebuild);
    connect(&m_session, &Session::monitorOnlyChanged, this, &CountersPage::updateButtons);
    rebuild();
}

CountersPage::~CountersPage() {
    // Before the tables: no connection may outlive the cells it writes to.
    delete m_bindings;
}

void CountersPage::setActive(bool active) {
    Page::setActive(active);
    // Counters are polled once a minute; someone opening the page wants today's numbers.
    if (active)
        refresh();
}

void CountersPage::refresh() {
    for (DeviceModel *device : m_session.devices())
        m_session.scheduler().requestRefresh(device, PollClass::Counter);
    m_waiting = !m_session.devices().isEmpty();
    updateReadAt();
}

void CountersPage::noteReading(const QDateTime &when) {
    m_lastRead = qMax(m_lastRead, when);
    m_waiting = false;
    m_deferred->requestPart(kReadAtPart);
}

void CountersPage::updateReadAt() {
    if (m_session.devices().isEmpty())
        m_readAt->clear();
    else if (m_waiting)
        m_readAt->setText(tr("Reading the counters…"));
    else if (m_lastRead.isValid())
        m_readAt->setText(
            tr("Last reading at %1").arg(m_lastRead.toString(QStringLiteral("HH:mm:ss"))));
    else
        m_readAt->setText(tr("Waiting for the first reading…"));
}

void CountersPage::rebuild() {
    // The old devices are gone (or going): drop every connection to them before the cells.
    delete m_bindings;
    m_bindings = new QObject(this);
    m_cellUpdates.clear();
    // Cells of a hidden page catch up when it is shown; part kReadAtPart is the reading time.
    m_deferred = new DeferredRefresh(
        *this,
        [this](int part) {
            if (part == kReadAtPart)
                updateReadAt();
            else if (part >= 0 && part < m_cellUpdates.size())
                m_cellUpdates.at(part)();
        },
        m_bindings);
    qDeleteAll(m_boxes);
    m_boxes.clear();
    m_resets.clear();
    for (DeviceModel *device : m_session.devices()) {
        if (auto *station = qobject_cast<StationModel *>(device))
            addStation(station);
        else if (auto *feeder = qobject_cast<FeederModel *>(device))
            addFeeder(feeder);
    }
    m_placeholder->setVisible(m_boxes.isEmpty());
    m_lastRead = {};
    m_waiting = false;
    m_status->clear();
    updateReadAt();
    updateButtons();
}

QTableWidget *CountersPage::makeTable(const QString &objectName, const QString &accessibleName) {
    auto *table = new QTableWidget(this);
    table->setObjectName(objectName);
    table->setAccessibleName(accessibleName);
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->setSelectionMode(QAbstractItemView::ContiguousSelection);
    // Tab leaves the table instead of walking its cells, so the buttons stay reachable.
    table->setTabKeyNavigation(false);
    table->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    table->setAlternatingRowColors(true);
    // Narrow columns keep each number next to its row name; the box leaves the rest empty.
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table->horizontalHeader()->setMinimumSectionSize(120);
    table->setSizeAdjustPolicy(QAbstractScrollArea::AdjustToContents);
    table->setSizePolicy(QSizePolicy::Maximum, QSizePolicy::Fixed);
    table->horizontalHeader()->setDefaultAlignment(Qt::AlignRight | Qt::AlignVCenter);
    table->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    table->verticalHeader()->setDefaultAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    return table;
}

void CountersPage::addStation(StationModel *station) {
    const QList<PortModel *> &ports = station->ports();
    if (ports.isEmpty())
        return;
    auto *box = new QGroupBox(tr("Station %1").arg(station->displayName()));
    QTableWidget *table = makeTable(QStringLiteral("stationCounters"),
                                    tr("Counters of %1").arg(station->displayName()));
    // Every port has the same counters; the first port names the rows. The station's own
    // counters follow, each across all the ports' columns.
    const QList<Parameter *> rows = ports.first()->counters() + station->counters();
    table->setRowCount(int(rows.size()));
    table->setColumnCount(int(ports.size()));
    for (int r = 0; r < rows.size(); ++r) {
        auto *header = new QTableWidgetItem(rows[r]->label());
        header->setToolTip(rows[r]->description());
        table->setVerticalHeaderItem(r, header);
        if (rows[r]->spec().port == 0) {
            table->setSpan(r, 0, 1, int(ports.size()));
            bindCell(table, r, 0, rows[r]);
        }
    }
    for (int c = 0; c < ports.size(); ++c) {
        table->setHorizontalHeaderItem(c, new QTableWidgetItem(tr("Port %1").arg(c + 1)));
        for (int r = 0; r < rows.size(); ++r)
            if (Parameter *p = sameCounter(*ports[c], *rows[r]))
                bindCell(table, r, c, p);
    }
    fitHeight(table);
    auto *layout = new QVBoxLayout(box);
    layout->addWidget(table, 0, Qt::AlignLeft);
    m_boxLayout->insertWidget(m_boxLayout->count() - 1, box);
    m_boxes.append(box);
}

void CountersPage::addFeeder(FeederModel *feeder) {
    auto *box = new QGroupBox(tr("Solder feeder %1").arg(feeder->displayName()));
    QTableWidget *table = makeTable(QStringLiteral("feederCounters"),
                                    tr("Counters of %1").arg(feeder->displayName()));
    const QList<FeederModel::CounterRow> rows = feeder->counterRows();
    table->setRowCount(int(rows.size()));
    table->setColumnCount(2);
    table->setHorizontalHeaderLabels({tr("Total"), tr("Partial")});
    auto *buttons = new QHBoxLayout;
    for (int r = 0; r < rows.size(); ++r) {
        const FeederModel::CounterRow &row = rows.at(r);
        table->setVerticalHeaderItem(r, new QTableWidgetItem(protocol::catalogText(row.quantity)));
        if (row.total)
            bindCell(table, r, 0, row.total);
        if (row.partial)
            bindCell(table, r, 1, row.partial);
        const Action *reset = row.reset;
        if (!reset)
            continue;
        auto *button = new QPushButton(buttonText(*reset) + QStringLiteral("…"));
        button->setObjectName(QLatin1String("reset") + QString::fromLatin1(reset->code()));
        button->setAccessibleName(buttonText(*reset));
        const QByteArray code = reset->code();
        QPointer<FeederModel> target = feeder;
        connect(button, &QPushButton::clicked, this, [this, target, code] {
            if (target)
                resetPartialOf(target, code);
        });
        buttons->addWidget(button);
        m_resets.append({feeder, code, button});
    }
    buttons->addStretch(1);
    fitHeight(table);
    auto *layout = new QVBoxLayout(box);
    layout->addWidget(table, 0, Qt::AlignLeft);
    layout->addLayout(buttons);
    m_boxLayout->insertWidget(m_boxLayout->count() - 1, box);
    m_boxes.append(box);
}

void CountersPage::bindCell(QTableWidget *table, int row, int column, Parameter *parameter) {
    auto *item = new QTableWidgetItem;
    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    table->setItem(row, column, item);
    // The connections live in m_bindings, which goes before the table does, and end with the
    // parameter; `item` and `parameter` are therefore alive whenever this runs.
    auto update = [this, item, parameter] {
        item->setText(parameter->displayText());
        QString tip =
            tr("%1 (R-%2)").arg(parameter->label(), QString::fromLatin1(parameter->code()));
        if (parameter->state() == Parameter::State::Failed)
            tip += QLatin1Char('\n') + tr("Last read failed: %1").arg(parameter->failure());
        else if (parameter->lastUpdate().isValid())
            tip += QLatin1Char('\n') +
                   tr("Read at %1")
                       .arg(QLocale().toString(parameter->lastUpdate(), QLocale::ShortFormat));
        else
            tip += QLatin1Char('\n') + tr("Not read yet");
        item->setToolTip(tip);
    };
    update();
    const int part = int(m_cellUpdates.size());
    m_cellUpdates.append(update);
    // Every reading, changed or not, comes with updated(): the cell shows when it was read.
    for (auto signal : {&Parameter::updated, &Parameter::stateChanged})
        connect(parameter, signal, m_deferred, [this, part] { m_deferred->requestPart(part); });
    connect(parameter, &Parameter::updated, m_bindings,
            [this, parameter] { noteReading(parameter->lastUpdate()); });
}

void CountersPage::resetPartial(const QByteArray &code) {
    if (FeederModel *feeder = m_session.feeder())
        resetPartialOf(feeder, code);
}

void CountersPage::resetPartialOf(FeederModel *feeder, const QByteArray &code) {
    QPointer<FeederModel> target = feeder;
    QPointer<Action> action = feeder->action(code);
    QPointer<Parameter> counter = feeder->parameter(code);
    if (!action || !counter)
        return;
    // No question that could only be answered with a refusal.
    if (feeder->writesBlocked()) {
        showStatus(tr("%1 Monitor-only mode is on: nothing is reset.").arg(now()));
        return;
    }
    QMessageBox box(QMessageBox::Warning, tr("Reset partial counter"),
                    tr("Reset “%1” on %2?").arg(counter->label(), feeder->displayName()),
                    QMessageBox::Cancel, this);
    box.setInformativeText(tr("It now reads %1.").arg(counter->displayText()) + QLatin1Char(' ') +
                           action->danger() + QLatin1Char(' ') +
                           tr("The total counter is not affected."));
    QPushButton *reset = box.addButton(tr("Reset counter"), QMessageBox::DestructiveRole);
    box.setDefaultButton(QMessageBox::Cancel);
    box.exec();
    // The dialog ran an event loop: the feeder may have gone in the meantime.
    if (box.clickedButton() != reset || !target || !action) {
        showStatus(tr("%1 Nothing was reset.").arg(now()));
        return;
    }
    const QString name = counter->label();
    const QString why = target->resetPartialCounter(code, Confirmation::Confirmed);
    if (!why.isEmpty()) {
        showStatus(tr("%1 Not reset: %2").arg(now(), why));
        return;
    }
    showStatus(tr("%1 Resetting %2…").arg(now(), name));
    connect(
        action, &Action::finished, this,
        [this, counter, name](bool ok, const QString &reason) {
            if (ok && counter)
                counter->refresh(); // show the zero now rather than at the next counter poll
            showStatus(ok ? tr("%1 %2 reset.").arg(now(), name)
                          : tr("%1 %2 was not reset: %3").arg(now(), name, reason));
            updateButtons();
        },
        Qt::SingleShotConnection);
    updateButtons();
}

void CountersPage::updateButtons() {
    const bool blocked = m_session.monitorOnly();
    for (const ResetButton &r : std::as_const(m_resets)) {
        Action *action = r.feeder ? r.feeder->action(r.code) : nullptr;
        r.button->setEnabled(action && !blocked && !action->isRunning());
        if (blocked)
            r.button->setToolTip(tr("Monitor-only mode is on: TipScope writes nothing to the "
                                    "devices. Turn it off to reset counters."));
        else if (action)
            r.button->setToolTip(action->description() + QLatin1String(". ") + action->danger());
    }
    const bool any = !m_session.devices().isEmpty();
    m_refresh->setEnabled(any);
    m_export->setEnabled(any);
}

void CountersPage::showStatus(const QString &text) {
    m_status->setText(text);
}

void CountersPage::chooseExportFile() {
    const QString name =
        QStringLiteral("tipscope-counters-%1.csv")
            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmm")));
    const QString dir = startFolder();
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export counters"), QDir(dir).filePath(name), tr("CSV files (*.csv)"));
    if (path.isEmpty())
        return;
    if (const auto saved = exportCsv(path); saved.ok())
        showStatus(tr("%1 Counters saved to %2").arg(now(), QDir::toNativeSeparators(path)));
    else
        QMessageBox::warning(this, tr("Export counters"),
                             tr("The counters could not be saved: %1").arg(saved.error()));
}

base::Outcome<void> CountersPage::exportCsv(const QString &path) const {
    // The header is a file format that scripts match on, so it is not translated.
    QString text = QStringLiteral("device,port,counter,value,unit\n");
    for (DeviceModel *device : m_session.devices()) {
        if (auto *station = qobject_cast<StationModel *>(device)) {
            for (PortModel *port : station->ports())
                for (Parameter *p : port->counters())
                    text += csvLine(station->displayName(), port->number(), *p);
            for (Parameter *p : station->counters())
                text += csvLine(station->displayName(), 0, *p);
        } else if (auto *feeder = qobject_cast<FeederModel *>(device)) {
            for (Parameter *p : feeder->counters())
                text += csvLine(feeder->displayName(), 0, *p);
        }
    }
    return base::io::saveAtomically(path, text.toUtf8());
}

} // namespace tipscope::gui
