#include "chartspage.h"

#include "chartwidget.h"
#include "model/chart/chartframe.h"
#include "model/recording/chartcsvreader.h"
#include "model/recording/chartrecorder.h"
#include "model/recording/recordingloader.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPlainTextEdit>
#include <QScrollArea>
#include <QToolButton>
#include <QVBoxLayout>
#include <cmath>

namespace tipscope::gui {

using namespace tipscope::model;

namespace {
constexpr int kMeasureFollowingMs = 1000; // measurements read more than a redraw: at most 1/s
constexpr int kMeasureSettleMs = 250;     // after a zoom or pan, once the gestures pause
} // namespace

ChartsPage::ChartsPage(Session &session, QWidget *parent)
    : Page(session, parent)
    , m_loader(new RecordingLoader(this))
    , m_recorder(new ChartRecorder(session.telemetry(), this)) {
    setAccessibleName(tr("Charts"));
    auto *layout = new QVBoxLayout(this);
    buildToolbar(layout);
    // Panes scroll rather than grow the window when one per port does not fit.
    auto *scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_panesHost = new QWidget(scroll);
    scroll->setWidget(m_panesHost);
    m_panesLayout = new QVBoxLayout(m_panesHost);
    m_panesLayout->setContentsMargins(0, 0, 0, 0);
    m_panesLayout->setSpacing(2);
    layout->addWidget(scroll, 1);
    buildReadout(layout);
    buildMeasurements(layout);

    m_redrawTimer.setSingleShot(true);
    m_measureTimer.setSingleShot(true);
    connect(&m_redrawTimer, &QTimer::timeout, this, &ChartsPage::redraw);
    connect(&m_measureTimer, &QTimer::timeout, this, &ChartsPage::updateMeasurements);
    connect(m_tolerance, &QDoubleSpinBox::valueChanged, this, &ChartsPage::updateMeasurements);
    connect(&m_viewport, &ChartViewport::changed, this, &ChartsPage::scheduleRedraw);
    connect(&session.telemetry(), &Telemetry::samplesAdded, this, &ChartsPage::onSamplesAdded);
    connect(&session, &Session::devicesChanged, this, &ChartsPage::refreshLiveChannels);
    connect(&session, &Session::temperatureUnitChanged, this, &ChartsPage::rebuildPanes);
    connect(&session.eventLog(), &EventLog::appended, this, [this](const Event &e) {
        if (const auto added = m_liveEvents.addFromLog(e, m_liveChannels))
            m_recorder->addEvent(*added);
        if (!isReplay())
            scheduleRedraw();
    });
    connect(&session.eventLog(), &EventLog::cleared, this, [this] { m_liveEvents.clear(); });
    refreshLiveChannels();
    for (const Event &e : session.eventLog().events())
        m_liveEvents.addFromLog(e, m_liveChannels);
    onLeave();
}

// The session may be gone already (the main window destroys it before its pages): touch nothing
// of it here. The recorder notices on its own.
ChartsPage::~ChartsPage() = default;

QSet<int> ChartsPage::visiblePorts() const {
    QSet<int> ports;
    for (const ChartChannel &c : m_liveChannels)
        if (!c.isFeeder())
            ports.insert(c.port);
    return ports;
}

void ChartsPage::setActive(bool active) {
    Page::setActive(active);
    if (active) {
        onSamplesAdded();
        scheduleRedraw();
    } else {
        m_redrawTimer.stop();
        m_measureTimer.stop();
    }
}

const Telemetry &ChartsPage::shownTelemetry() const {
    return m_replay ? *m_replay->telemetry : m_session.telemetry();
}

const QList<ChartChannel> &ChartsPage::shownChannels() const {
    return m_replay ? m_replay->channels : m_liveChannels;
}

const ChartEvents &ChartsPage::events() const {
    return m_replay ? m_replay->events : m_liveEvents;
}

QList<ChartWidget *> ChartsPage::panes() const {
    QList<ChartWidget *> out;
    for (const Pane &p : m_panes)
        out.append(p.widget);
    return out;
}

QList<ChartTrace> ChartsPage::traces(int pane) const {
    return m_panes.value(pane).traces;
}

void ChartsPage::refreshLiveChannels() {
    m_liveChannels = sessionChannels(m_session);
    if (m_source)
        updateSourceLabel();
    if (!isReplay())
        rebuildPanes();
}

void ChartsPage::setPaneLayout(Layout layout) {
    m_layout = layout;
    m_layoutBox->setCurrentIndex(layout == Layout::Overlaid ? 0 : 1);
    rebuildPanes();
}

void ChartsPage::rebuildPanes() {
    for (const Pane &p : std::as_const(m_panes))
        delete p.widget;
    m_panes.clear();
    const QList<ChartChannel> &cs = shownChannels();
    QList<int> ports;
    for (int i = 0; i < cs.size(); ++i) {
        if (cs.at(i).isFeeder())
            continue;
        if (m_layout == Layout::PerPort)
            m_panes.append(Pane{nullptr, {i}, {}});
        else
            ports.append(i);
    }
    if (!ports.isEmpty())
        m_panes.prepend(Pane{nullptr, ports, {}});
    for (int i = 0; i < cs.size(); ++i)
        if (cs.at(i).isFeeder())
            m_panes.append(Pane{nullptr, {i}, {}});

    const SeriesFormat temp = seriesFormat(QStringLiteral("tip"), m_session.temperatureUnit());
    m_tolerance->setSuffix(QLatin1Char(' ') + temp.unit);
    for (Pane &pane : m_panes) {
        const ChartChannel &first = cs.at(pane.channels.first());
        pane.traces =
            tracesFor(cs, pane.channels, m_session.temperatureUnit(), m_hardware->isChecked());
        // The source line above names the devices: on screen the title is only the pane's
        // accessible name, and its row goes to the plot.
        pane.widget = createPaneWidget(pane, m_layout == Layout::Overlaid, m_panesHost);
        pane.widget->setTitleShown(false);
        pane.widget->setMinimumHeight(first.isFeeder() ? 120 : 170);
        // Until the first redraw the pane shows the page's window (a hover reads real times).
        pane.widget->setTimeRange(m_viewport.start(), m_viewport.end());
        connectPane(pane.widget);
        m_panesLayout->addWidget(pane.widget, first.isFeeder() ? kFeederStretch : kStationStretch);
    }
    updateReadoutTemplate();
    scheduleRedraw();
}

ChartWidget *ChartsPage::createPaneWidget(const Pane &pane, bool roomy, QWidget *parent) const {
    const QList<ChartChannel> &cs = shownChannels();
    const ChartChannel &first = cs.at(pane.channels.first());
    auto *widget = new ChartWidget(parent);
    QList<ChartSeriesStyle> styles;
    for (const ChartTrace &t : std::as_const(pane.traces))
        styles.append({first.isFeeder() ? tr("%1 (%2)").arg(t.name, t.format.unit) : t.name,
                       t.color, t.style, t.format.axis});
    widget->setSeries(styles, overlaidLegend(cs, pane));
    const QString device = tr("%1 at %2").arg(first.deviceModel, first.address);
    if (first.isFeeder()) {
        // A short pane: the units go in the legend, rotated axis titles would not fit.
        widget->setTitle(tr("%1 — feeder").arg(device));
        return widget;
    }
    widget->setTitle(pane.channels.size() > 1
                         ? tr("%1 — all ports").arg(device)
                         : tr("%1 — %2 %3").arg(device, first.title, first.tool));
    // A pane per port is short: the bare units fit beside it, the words would not.
    const QString unit = seriesFormat(QStringLiteral("tip"), m_session.temperatureUnit()).unit;
    widget->setAxisTitle(ChartAxis::Left, roomy ? tr("Temperature (%1)").arg(unit) : unit);
    widget->setAxisTitle(ChartAxis::Right, roomy ? tr("Power (%)") : tr("%"));
    widget->setCompact(!roomy);
    return widget;
}

void ChartsPage::connectPane(ChartWidget *w) {
    connect(w, &ChartWidget::hovered, this, &ChartsPage::onHover);
    connect(w, &ChartWidget::left, this, &ChartsPage::onLeave);
    connect(w, &ChartWidget::zoomRequested, &m_viewport, &ChartViewport::zoom);
    connect(w, &ChartWidget::panRequested, &m_viewport, &ChartViewport::pan);
    connect(w, &ChartWidget::rangeSelected, &m_viewport, &ChartViewport::showRange);
    connect(w, &ChartWidget::resetRequested, this, &ChartsPage::resetView);
    connect(w, &ChartWidget::plotResized, this, [this] {
        alignPlots(panes());
        scheduleRedraw();
    });
}

void ChartsPage::resetView() {
    if (!m_replay) {
        m_viewport.reset();
        return;
    }
    // The whole recording, or its last day when it is longer than the longest window.
    const qint64 end = m_replay->lastMs + 1;
    m_viewport.showRange(qMax(m_replay->firstMs, end - ChartViewport::kMaxWindowMs), end);
}

void ChartsPage::onSamplesAdded() {
    if (isReplay())
        return;
    std::optional<qint64> first, last;
    for (const ChartChannel &c : std::as_const(m_liveChannels)) {
        const TelemetryBuffer *b = m_session.telemetry().buffer(c.key);
        if (!b || b->isEmpty())
            continue;
        first = qMin(first.value_or(b->firstTime()), b->firstTime());
        last = qMax(last.value_or(b->lastTime()), b->lastTime());
    }
    if (!first)
        return;
    m_viewport.setDataRange(*first, *last);
    // While the first minutes fill the view the window stands still, and the new samples are in
    // it: they are drawn without the window moving.
    if (*last >= m_viewport.start() && *last < m_viewport.end())
        scheduleRedraw();
}

void ChartsPage::scheduleRedraw() {
    if (!m_active || m_redrawTimer.isActive())
        return;
    qint64 gapMs = 1000 / kMaxRedrawsPerSecond;
    // Following, a redraw before the window moved by a pixel column shows next to nothing new.
    if (m_viewport.isFollowing() && !isReplay() && !m_panes.isEmpty())
        gapMs = qBound<qint64>(gapMs, m_viewport.windowMs() / m_panes.first().widget->plotWidth(),
                               1000);
    const qint64 since = m_sinceRedraw.isValid() ? m_sinceRedraw.elapsed() : gapMs;
    m_redrawTimer.start(int(qMax<qint64>(0, gapMs - since)));
}

void ChartsPage::redrawNow() {
    m_redrawTimer.stop();
    onSamplesAdded();
    redraw();
}

void ChartsPage::redraw() {
    m_sinceRedraw.restart();
    ++m_redraws;
    for (Pane &pane : m_panes)
        drawPane(pane);
    if (m_hover)
        onHover(*m_hover);
    showWindowLength();
    if (!m_measureTimer.isActive())
        m_measureTimer.start(m_viewport.isFollowing() ? kMeasureFollowingMs : kMeasureSettleMs);
}

// Ports overlaid: a solid line in each port's colour, then a grey line per kind of value in its
// dash ("P1 tip", "P1 setpoint"... for every port would not fit above the plot). Empty for a
// pane of one channel, whose legend names each curve.
QList<ChartSeriesStyle> ChartsPage::overlaidLegend(const QList<ChartChannel> &cs,
                                                   const Pane &pane) {
    QList<ChartSeriesStyle> legend;
    if (pane.channels.size() < 2)
        return legend;
    for (int c : pane.channels)
        legend.append({cs.at(c).title, portColor(cs.at(c).port), Qt::SolidLine, ChartAxis::Left});
    QStringList kinds;
    for (const ChartTrace &t : pane.traces) {
        if (kinds.contains(t.series))
            continue;
        kinds.append(t.series);
        legend.append({traceName(t.series, 0), QColor(0x60, 0x60, 0x60), t.style, t.format.axis});
    }
    return legend;
}

void ChartsPage::drawPane(Pane &pane) {
    ChartWidget *w = pane.widget;
    const qint64 t0 = m_viewport.start(), t1 = m_viewport.end();
    const ChartFrame frame =
        buildFrame(shownTelemetry(), shownChannels(), pane.traces, t0, t1, w->plotWidth());
    // The range follows the curves; an alarm limit is a shaded band, and widening the range to
    // show a far one would flatten the curves a person is reading.
    const bool feeder = shownChannels().at(pane.channels.first()).isFeeder();
    const ValueSpan l = niceRange(frame.left, feeder ? 1 : 10);
    const ValueSpan r = feeder ? niceRange(frame.right, 1) : ValueSpan{0, 100, true};
    w->showData(ChartData{t0, t1, l.min, l.max, r.min, r.max, frame.points});
    w->setBands(bandsFor(pane));
    w->setMarkers(markersFor(pane));
    w->setEmptyText(frame.pointCount == 0 ? tr("No samples in this window") : QString());
}

} // namespace tipscope::gui
