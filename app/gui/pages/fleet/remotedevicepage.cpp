#include "pages/fleet/remotedevicepage.h"

#include "charts/chartwidget.h"

#include "model/chart/chartframe.h"
#include "model/joints/jointtable.h"
#include "plant/plantwatch.h"
#include "plant/remotehistory.h"
#include "plant/remotetile.h"

#include <QDateTime>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonObject>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QScrollBar>
#include <QTableWidget>
#include <QVBoxLayout>

namespace tipscope::gui {

namespace {
constexpr int kRefreshMs = 250;

QTableWidget *table(const QStringList &headers, QWidget *parent) {
    auto *t = new QTableWidget(0, int(headers.size()), parent);
    t->setHorizontalHeaderLabels(headers);
    t->setEditTriggers(QAbstractItemView::NoEditTriggers);
    t->setSelectionBehavior(QAbstractItemView::SelectRows);
    t->verticalHeader()->hide();
    t->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    t->horizontalHeader()->setStretchLastSection(true);
    return t;
}

void fill(QTableWidget *t, const QList<QStringList> &rows) {
    t->setRowCount(int(rows.size()));
    for (int r = 0; r < rows.size(); ++r)
        for (int c = 0; c < rows.at(r).size(); ++c) {
            auto *item = t->item(r, c);
            if (!item) {
                item = new QTableWidgetItem;
                t->setItem(r, c, item);
            }
            item->setText(rows.at(r).at(c));
        }
}

// Every row of a short table in view (a station has at most four ports): the chart below takes
// the room, not an empty table.
void fitRows(QTableWidget *t) {
    int height = t->horizontalHeader()->sizeHint().height() + 2 * t->frameWidth();
    for (int r = 0; r < t->rowCount(); ++r)
        height += t->verticalHeader()->sectionSize(r);
    if (t->horizontalScrollBar()->isVisible())
        height += t->horizontalScrollBar()->sizeHint().height();
    t->setFixedHeight(height);
}

QString number(const QJsonObject &o, const char *key, int decimals = 0) {
    const QJsonValue v = o.value(QLatin1String(key));
    return v.isDouble() ? QLocale().toString(v.toDouble(), 'f', decimals) : QStringLiteral("—");
}
} // namespace

RemoteDevicePage::RemoteDevicePage(const plant::PlantWatch &watch, QWidget *parent)
    : QWidget(parent)
    , m_watch(watch) {
    m_title = new QLabel(this);
    QFont bold = m_title->font();
    bold.setBold(true);
    bold.setPointSizeF(bold.pointSizeF() * 1.2);
    m_title->setFont(bold);
    m_title->setWordWrap(true);
    m_state = new QLabel(this);
    m_state->setWordWrap(true);
    m_ports =
        table({tr("Port"), tr("Tool"), tr("Tip"), tr("Setpoint"), tr("Power"), tr("Status")}, this);
    m_history = new plant::RemoteHistory(watch, this);
    m_chart = new ChartWidget(this);
    m_chart->setTitle(tr("Tip, setpoint and power, last 10 minutes"));
    m_chart->setTitleShown(false);
    m_chart->setAxisTitle(model::ChartAxis::Left, tr("Temperature (°C)"));
    m_chart->setAxisTitle(model::ChartAxis::Right, tr("Power (%)"));
    m_chart->setMinimumHeight(200);
    m_ports->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_alarms = new QLabel(this);
    m_alarms->setWordWrap(true);
    m_joints = table(
        {tr("Ended"), tr("Port"), tr("Tool"), tr("Verdict"), tr("Dip (K)"), tr("Recovery (s)")},
        this);
    auto *back = new QPushButton(tr("‹ Fleet overview"), this);
    connect(back, &QPushButton::clicked, this, &RemoteDevicePage::backRequested);
    auto *top = new QHBoxLayout;
    top->addWidget(m_title, 1);
    top->addWidget(back, 0, Qt::AlignTop);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(m_state);
    layout->addWidget(new QLabel(tr("Live values"), this));
    layout->addWidget(m_ports);
    layout->addWidget(new QLabel(tr("Tip, setpoint and power, last 10 minutes"), this));
    layout->addWidget(m_chart, 3);
    layout->addWidget(m_alarms);
    layout->addWidget(new QLabel(tr("Recent joints, newest first"), this));
    layout->addWidget(m_joints, 1);
    m_refresh.setSingleShot(true);
    m_refresh.setInterval(kRefreshMs);
    connect(&m_refresh, &QTimer::timeout, this, &RemoteDevicePage::refresh);
    connect(&watch, &plant::PlantWatch::deviceChanged, this, [this](const QString &root) {
        if (root == m_root && !m_refresh.isActive())
            m_refresh.start();
    });
}

void RemoteDevicePage::showDevice(const QString &root) {
    m_root = root;
    refresh();
}

void RemoteDevicePage::refresh() {
    const plant::RemoteDevice *d = m_watch.device(m_root);
    if (!d) {
        m_title->setText(tr("No such device on the plant's broker"));
        return;
    }
    const model::FleetTileState s = plant::remoteTileState(*d, QDateTime::currentMSecsSinceEpoch());
    m_title->setText(tr("%1 · %2 on %3 (%4)").arg(s.deviceName, s.model, s.lineName, d->site));
    const QString agent = d->status.value(QStringLiteral("agent")).toString();
    m_state->setText(
        s.lineUp
            ? tr("Read-only: published by %1 %2 through the plant's broker; current.")
                  .arg(agent, d->status.value(QStringLiteral("version")).toString())
            : tr("Read-only, not current: %1. The values are the last published.").arg(s.lineText));
    m_state->setStyleSheet(s.lineUp ? QString() : QStringLiteral("color: #b35c00;"));
    QList<QStringList> ports;
    for (const model::FleetPortState &p : s.ports)
        ports.append({QString::number(p.number), p.toolText, p.tipText, p.setpointText, p.powerText,
                      p.statusText});
    fill(m_ports, ports);
    fitRows(m_ports);
    m_ports->setEnabled(s.lineUp); // greyed: not current
    QStringList problems;
    for (const model::FleetProblem &problem : s.problems)
        problems.append(problem.text);
    m_alarms->setText(problems.isEmpty()
                          ? tr("No errors or alarms in force.")
                          : tr("In force: %1").arg(problems.join(QStringLiteral("; "))));
    QList<QStringList> joints;
    for (auto it = d->joints.crbegin(); it != d->joints.crend(); ++it) {
        const QJsonObject &j = *it;
        const auto verdict =
            model::jointVerdictFromName(j.value(QStringLiteral("verdict")).toString());
        const QDateTime end =
            QDateTime::fromString(j.value(QStringLiteral("end")).toString(), Qt::ISODateWithMs)
                .toLocalTime();
        const QJsonValue recovery = j.value(QStringLiteral("recovery_ms"));
        joints.append({QLocale().toString(end, QLocale::ShortFormat),
                       QString::number(j.value(QStringLiteral("port")).toInt()),
                       j.value(QStringLiteral("tool")).toString(),
                       verdict ? model::JointTableModel::verdictText(*verdict) : QString(),
                       number(j, "dip_k"),
                       recovery.isDouble() ? QLocale().toString(recovery.toDouble() / 1000, 'f', 2)
                                           : tr("never")});
    }
    fill(m_joints, joints);
    drawChart();
}

// The last minutes of every port, tip solid, setpoint dashed, power dotted on the right axis, a
// colour per port as on the local charts; a gap in what was received stays a gap.
void RemoteDevicePage::drawChart() {
    const QList<model::ChartChannel> channels = m_history->channels(m_root);
    const QList<model::ChartTrace> traces = plant::RemoteHistory::traces(channels);
    QStringList keys;
    for (const model::ChartChannel &c : channels)
        keys.append(c.key);
    if (const QString shown = keys.join(QLatin1Char(' ')); shown != m_chartChannels) {
        m_chartChannels = shown;
        QList<ChartSeriesStyle> series, legend;
        for (const model::ChartTrace &t : traces)
            series.append({t.name, t.color, t.style, t.format.axis});
        for (const model::ChartChannel &c : channels)
            legend.append(
                {c.title, model::portColor(c.port), Qt::SolidLine, model::ChartAxis::Left});
        for (int s = 0; s < traces.size() && s < 3; ++s)
            legend.append({model::traceName(traces.at(s).series, 0), QColor(0x60, 0x60, 0x60),
                           traces.at(s).style, traces.at(s).format.axis});
        m_chart->setSeries(series, legend);
    }
    // The agent's clock stamps the samples: a window behind it still shows the newest.
    qint64 t1 = QDateTime::currentMSecsSinceEpoch();
    for (const model::ChartChannel &c : channels)
        t1 = qMax(t1, m_history->telemetry().buffer(c.key)->lastTime() + 1);
    const qint64 t0 = t1 - kChartSpanMs;
    const model::ChartFrame frame =
        model::buildFrame(m_history->telemetry(), channels, traces, t0, t1, m_chart->plotWidth());
    const model::ValueSpan left = model::niceRange(frame.left, 10);
    m_chart->showData(ChartData{t0, t1, left.min, left.max, 0, 100, frame.points});
    m_chart->setEmptyText(frame.pointCount == 0 ? tr("No live values received yet") : QString());
}

QStringList RemoteDevicePage::lines() const {
    QStringList out{m_title->text(), m_state->text(), m_alarms->text()};
    for (const QTableWidget *t : {m_ports, m_joints})
        for (int r = 0; r < t->rowCount(); ++r) {
            QStringList cells;
            for (int c = 0; c < t->columnCount(); ++c)
                cells.append(t->item(r, c) ? t->item(r, c)->text() : QString());
            out.append(cells.join(QLatin1Char('|')));
        }
    return out;
}

} // namespace tipscope::gui
