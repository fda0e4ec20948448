#include "jointspage.h"

#include "charts/chartspage.h"
#include "jointcharts.h"
#include "levelstyle.h"
#include "widgets/deferredrefresh.h"
#include "widgets/flowlayout.h"

#include "base/atomicsave.h"
#include "journal/journal.h"
#include "journal/journalreader.h"

#include "widgets/startfolder.h"

#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>

namespace tipscope::gui {

using namespace tipscope::model;

namespace {
constexpr qint64 kHourMs = 3600'000;
constexpr int kMaxPorts = 4;
// Columns are sized from this many rows: enough to be right, few enough to stay quick.
constexpr int kSizeColumnsFromRows = 200;
constexpr int kEditPadding = 8;

bool matches(const journal::JointFilter &f, const JointRow &row) {
    const JointRecord &j = row.joint;
    return (!f.sinceMs || j.startMs >= *f.sinceMs) && (!f.untilMs || j.startMs < *f.untilMs) &&
           (!f.deviceKey || j.device.key() == *f.deviceKey) && (!f.port || j.port == *f.port) &&
           (!f.tool || j.tool == *f.tool) && (!f.verdict || j.verdict == *f.verdict) &&
           (!f.workOrder || row.workOrder == *f.workOrder);
}

std::optional<QString> textFilter(const QLineEdit *edit) {
    const QString text = edit->text().trimmed();
    return text.isEmpty() ? std::nullopt : std::optional<QString>(text);
}

struct JournalJoints {
    QList<JointRow> rows;
    QList<DeviceIdentity> devices;
};

// The joints and devices the journal holds, or why it could not be read.
base::Outcome<JournalJoints> readJournal(const QString &path, const journal::JointFilter &filter) {
    journal::JournalReader reader;
    if (const auto opened = reader.open(path); !opened)
        return base::failure(opened.error());
    const auto stored = reader.joints(filter);
    if (!stored)
        return base::failure(stored.error());
    JournalJoints out;
    for (const journal::StoredJoint &s : *stored)
        out.rows.append({s.record, s.context.workOrder});
    if (const auto known = reader.devices())
        out.devices = *known;
    return out;
}

QLabel *labelFor(const QString &text, QWidget *buddy, QWidget *parent) {
    auto *label = new QLabel(text, parent);
    label->setBuddy(buddy);
    return label;
}
} // namespace

JointsPage::JointsPage(Session &session, QWidget *parent)
    : Page(session, parent)
    , m_journalPath(journal::Journal::defaultPath()) {
    m_table.setTemperatureUnit(session.temperatureUnit());
    m_view = new QTableView(this);
    auto *styled = new LevelStyleProxy(JointTableModel::LevelRole, JointTableModel::Verdict, this);
    styled->setSourceModel(&m_table);
    m_view->setModel(styled);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->setAlternatingRowColors(true);
    m_view->verticalHeader()->hide();
    m_view->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_view->setWordWrap(false);
    m_view->horizontalHeader()->setStretchLastSection(true);
    m_view->horizontalHeader()->setResizeContentsPrecision(kSizeColumnsFromRows);
    m_view->setToolTip(tr("Double-click a joint, or press Enter, to see it on the Charts page"));
    m_histogram = new RecoveryHistogramView(this);
    m_trend = new RecoveryTrendView(this);
    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *charts = new QWidget(this);
    auto *chartsLayout = new QHBoxLayout(charts);
    chartsLayout->setContentsMargins(0, 0, 0, 0);
    chartsLayout->addWidget(m_histogram, 1);
    chartsLayout->addWidget(m_trend, 1);
    auto *split = new QSplitter(Qt::Vertical, this);
    split->addWidget(m_view);
    split->addWidget(charts);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 1);
    split->setChildrenCollapsible(false);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(buildFilters());
    layout->addWidget(m_status);
    layout->addWidget(split, 1);

    m_chartsRefresh = new DeferredRefresh(*this, [this] { refreshCharts(); });
    m_widthsRefresh = new DeferredRefresh(*this, [this] { m_view->resizeColumnsToContents(); });
    connect(m_view, &QTableView::activated, this,
            [this](const QModelIndex &index) { openJoint(index.row()); });
    connect(&session.joints(), &JointWatcher::jointEnded, this, &JointsPage::onJointEnded);
    connect(&session, &Session::temperatureUnitChanged, this,
            [this] { m_table.setTemperatureUnit(m_session.temperatureUnit()); });
    connect(&session, &Session::devicesChanged, this, [this] { fillDevices({}); });
    reload();
}

QWidget *JointsPage::buildFilters() {
    auto *host = new QWidget(this);
    auto *flow = new FlowLayout(host);
    flow->setContentsMargins(0, 0, 0, 0);
    m_deviceBox = new QComboBox(host);
    m_deviceBox->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_deviceBox->addItem(tr("All devices"), QString());
    m_portBox = new QComboBox(host);
    m_portBox->addItem(tr("All ports"), 0);
    for (int port = 1; port <= kMaxPorts; ++port)
        m_portBox->addItem(tr("Port %1").arg(port), port);
    m_toolEdit = new QLineEdit(host);
    m_toolEdit->setPlaceholderText(tr("all tools"));
    m_toolEdit->setClearButtonEnabled(true);
    m_verdictBox = new QComboBox(host);
    m_verdictBox->addItem(tr("All verdicts"), -1);
    for (const JointVerdict v : kJointVerdicts)
        m_verdictBox->addItem(JointTableModel::verdictText(v), int(v));
    m_rangeBox = new QComboBox(host);
    for (const QString &range : {tr("Last hour"), tr("Last 24 hours"), tr("Last 7 days"),
                                 tr("Last 30 days"), tr("All times")})
        m_rangeBox->addItem(range);
    m_rangeBox->setCurrentIndex(kDefaultRange);
    m_workOrderEdit = new QLineEdit(host);
    m_workOrderEdit->setPlaceholderText(tr("all work orders"));
    m_workOrderEdit->setClearButtonEnabled(true);
    auto *reloadButton = new QPushButton(tr("Reload"), host);
    reloadButton->setToolTip(tr("Read the journal again"));
    m_export = new QPushButton(tr("Export CSV…"), host);
    m_export->setToolTip(tr("Save the listed joints as a CSV file"));

    const QList<QPair<QString, QWidget *>> fields = {
        {tr("Device"), m_deviceBox}, {tr("Port"), m_portBox},
        {tr("Tool"), m_toolEdit},    {tr("Verdict"), m_verdictBox},
        {tr("Time"), m_rangeBox},    {tr("Work order"), m_workOrderEdit}};
    for (const auto &[name, editor] : fields) {
        // A label stays beside its field when the row wraps.
        auto *pair = new QWidget(host);
        auto *row = new QHBoxLayout(pair);
        row->setContentsMargins(0, 0, 0, 0);
        row->addWidget(labelFor(name, editor, pair));
        row->addWidget(editor);
        flow->addWidget(pair);
    }
    flow->addWidget(reloadButton);
    flow->addWidget(m_export);

    for (QComboBox *box : {m_deviceBox, m_portBox, m_verdictBox, m_rangeBox})
        connect(box, &QComboBox::currentIndexChanged, this, &JointsPage::reload);
    for (QLineEdit *edit : {m_toolEdit, m_workOrderEdit}) {
        // Wide enough for the placeholder in every language and its clear button.
        edit->setMinimumWidth(edit->fontMetrics().horizontalAdvance(edit->placeholderText()) +
                              2 * edit->fontMetrics().height() + kEditPadding);
        connect(edit, &QLineEdit::editingFinished, this, &JointsPage::reload);
    }
    connect(reloadButton, &QPushButton::clicked, this, &JointsPage::reload);
    connect(m_export, &QPushButton::clicked, this, &JointsPage::chooseAndExport);
    return host;
}

void JointsPage::setJournalPath(const QString &path) {
    m_journalPath = path;
    reload();
}

journal::JointFilter JointsPage::filter() const {
    journal::JointFilter f;
    if (const QString key = m_deviceBox->currentData().toString(); !key.isEmpty())
        f.deviceKey = key;
    if (const int port = m_portBox->currentData().toInt(); port > 0)
        f.port = port;
    f.tool = textFilter(m_toolEdit);
    if (const int verdict = m_verdictBox->currentData().toInt(); verdict >= 0)
        f.verdict = JointVerdict(verdict);
    if (const int hours = kRangeHours[qMax(0, m_rangeBox->currentIndex())]; hours > 0)
        f.sinceMs = QDateTime::currentMSecsSinceEpoch() - hours * kHourMs;
    f.workOrder = textFilter(m_workOrderEdit);
    f.order = journal::Order::NewestFirst;
    return f;
}

void JointsPage::setDeviceFilter(const QString &deviceKey) {
    fillDevices({});
    m_deviceBox->setCurrentIndex(qMax(0, m_deviceBox->findData(deviceKey)));
}

void JointsPage::setPortFilter(int port) {
    m_portBox->setCurrentIndex(qMax(0, m_portBox->findData(port)));
}

void JointsPage::setToolFilter(const QString &tool) {
    m_toolEdit->setText(tool);
    reload();
}

void JointsPage::setVerdictFilter(std::optional<JointVerdict> verdict) {
    m_verdictBox->setCurrentIndex(verdict ? m_verdictBox->findData(int(*verdict)) : 0);
}

void JointsPage::setRangeFilter(int rangeIndex) {
    m_rangeBox->setCurrentIndex(rangeIndex);
}

void JointsPage::setWorkOrderFilter(const QString &workOrder) {
    m_workOrderEdit->setText(workOrder);
    reload();
}

void JointsPage::reload() {
    journal::JointFilter f = filter();
    f.limit = kHistoryLimit;
    QList<JointRow> rows;
    QList<DeviceIdentity> devices;
    QString problem;
    const bool hasJournal = !m_journalPath.isEmpty() && QFileInfo::exists(m_journalPath);
    if (hasJournal) {
        const auto read = readJournal(m_journalPath, f);
        if (read) {
            rows = read->rows;
            devices = read->devices;
        } else {
            problem = read.error();
        }
    }
    m_historyCut = rows.size() >= kHistoryLimit;
    // The journal's rows first: a joint in both keeps the journal's work order.
    for (const JointRow &live : std::as_const(m_live))
        if (matches(f, live))
            rows.append(live);
    m_table.reset(rows);
    m_view->resizeColumnsToContents();
    fillDevices(devices);
    m_chartsRefresh->request();
    m_journalProblem = problem;
    m_hasJournal = hasJournal;
    m_otherProblem = false;
    showCount();
}

void JointsPage::showCount() {
    QString text = tr("%n joint(s) listed.", nullptr, int(m_table.rowCount()));
    if (m_historyCut)
        text += QLatin1Char(' ') + tr("Only the newest %1 from the journal: narrow the filter "
                                      "to see older ones.")
                                       .arg(kHistoryLimit);
    if (!m_journalProblem.isEmpty())
        text = tr("The journal could not be read (%1): only this session's joints are listed.")
                   .arg(m_journalProblem) +
               QLatin1Char(' ') + text;
    else if (!m_hasJournal)
        text += QLatin1Char(' ') + tr("No journal yet: this session's joints only.");
    showStatus(text, !m_journalProblem.isEmpty());
}

void JointsPage::onJointEnded(const JointRecord &joint) {
    const JointRow row{joint, m_workOrder};
    m_live.append(row);
    if (m_live.size() > JointTableModel::kCapacity)
        m_live.removeFirst();
    if (!matches(filter(), row) || !m_table.add(row))
        return;
    if (m_deviceBox->findData(joint.device.key()) < 0)
        fillDevices({joint.device});
    // The first rows decide the widths, measured when the page is seen: a line whose ports each
    // make a joint every few seconds kept a hidden table measuring its rows for every one.
    m_widthsRefresh->request();
    m_chartsRefresh->request();
    // A failed export or chart stays in sight until the next reload; else the count follows.
    if (!m_otherProblem)
        showCount();
}

void JointsPage::fillDevices(const QList<DeviceIdentity> &fromJournal) {
    QMap<QString, QString> devices; // key → description, in key order
    for (const DeviceIdentity &d : fromJournal)
        devices.insert(d.key(), d.description());
    for (const DeviceModel *d : m_session.devices())
        devices.insert(d->identity().key(), d->identity().description());
    for (const JointRow &r : std::as_const(m_live))
        devices.insert(r.joint.device.key(), r.joint.device.description());
    const QSignalBlocker quiet(m_deviceBox);
    for (auto d = devices.cbegin(); d != devices.cend(); ++d)
        if (m_deviceBox->findData(d.key()) < 0)
            m_deviceBox->addItem(d.value(), d.key());
}

void JointsPage::setChartsPage(ChartsPage *charts) {
    m_charts = charts;
}

QString JointsPage::openJoint(int row) {
    if (row < 0 || row >= m_table.rowCount() || !m_charts)
        return {};
    const JointRecord &joint = m_table.row(row).joint;
    const QString why = m_charts->showMoment(joint.device, joint.startMs, joint.endMs);
    if (!why.isEmpty()) {
        m_otherProblem = true;
        showStatus(why, true);
        return why;
    }
    Q_EMIT chartsShown(m_charts);
    return {};
}

void JointsPage::refreshCharts() {
    m_histogram->setHistogram(recoveryHistogram(m_table.rows()));
    m_trend->setTrends(dailyRecoveryByTool(m_table.rows()));
}

void JointsPage::flushCharts() {
    m_chartsRefresh->flush();
}

QString JointsPage::statusText() const {
    return m_status->text();
}

void JointsPage::showStatus(const QString &text, bool problem) {
    m_status->setText(text);
    m_status->setStyleSheet(problem ? QStringLiteral("color: #c01c28; font-weight: bold;")
                                    : QString());
}

QString JointsPage::exportCsv(const QString &path) {
    const auto saved = base::io::saveAtomically(path, m_table.csv());
    if (!saved) {
        m_otherProblem = true;
        showStatus(saved.error(), true);
        return saved.error();
    }
    showStatus(tr("%n joint(s) written to %1.", nullptr, int(m_table.rowCount()))
                   .arg(QDir::toNativeSeparators(path)),
               false);
    return {};
}

void JointsPage::chooseAndExport() {
    const QString folder = startFolder();
    const QString name =
        QStringLiteral("joints-%1.csv")
            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")));
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export joints"), QDir(folder).filePath(name), tr("CSV file (*.csv)"));
    if (!path.isEmpty())
        exportCsv(path);
}

} // namespace tipscope::gui
