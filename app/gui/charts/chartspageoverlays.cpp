// ChartsPage's overlays and read-outs: event markers and alarm bands of a pane, the crosshair
// readout, and the measurement panel.
#include "chartspage.h"

#include "chartwidget.h"
#include "model/analysis/measurementreport.h"
#include "model/chart/chartframe.h"
#include "readoutpanel.h"

#include <QDateTime>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QScrollBar>
#include <QToolButton>
#include <QVBoxLayout>
#include <cmath>
#include <limits>

namespace tipscope::gui {

using namespace tipscope::model;

namespace {
QColor eventColor(const ChartEvent &e) {
    switch (e.kind) {
    case Event::Kind::Status:
        return QColor(0x54, 0x6E, 0x7A);
    case Event::Kind::Alarm:
        return QColor(0xEF, 0x6C, 0x00);
    case Event::Kind::Write:
        return QColor(0x2E, 0x7D, 0x32);
    default:
        return e.severity == Event::Severity::Info ? QColor(0x8D, 0x6E, 0x63)
                                                   : QColor(0xC6, 0x28, 0x28);
    }
}
} // namespace

QList<ChartMarker> ChartsPage::markersFor(const Pane &pane) const {
    QList<ChartMarker> out;
    const QList<ChartChannel> &cs = shownChannels();
    for (const ChartEvent &e : events().between(m_viewport.start(), m_viewport.end())) {
        for (int index : pane.channels) {
            if (!e.concerns(cs.at(index)))
                continue;
            const QString where =
                e.scope.startsWith(QLatin1Char('@')) ? tr("device") : cs.at(index).title;
            out.append({e.timeMs, eventColor(e),
                        tr("%1 · %2 · %3: %4")
                            .arg(QDateTime::fromMSecsSinceEpoch(e.timeMs).toString(
                                     QStringLiteral("HH:mm:ss.zzz")),
                                 where, Event::kindTitle(e.kind), e.text)});
            break;
        }
    }
    return out;
}

QList<ChartBand> ChartsPage::bandsFor(const Pane &pane) const {
    // Equal limits of several ports make one band, labelled with every port it is for.
    QMap<qint32, QStringList> highs, lows;
    for (int index : pane.channels) {
        ChartChannel c = shownChannels().at(index);
        if (c.isFeeder())
            continue;
        if (!m_replay) { // live limits change as the settings are read or written
            if (StationModel *st = m_session.station(); st && st->port(c.port)) {
                const auto read = [](Parameter *p) {
                    return p && p->number() ? std::optional<qint32>(qint32(*p->number()))
                                            : std::nullopt;
                };
                c.highAlarm = read(st->port(c.port)->parameter(protocol::Role::HighAlarm));
                c.lowAlarm = read(st->port(c.port)->parameter(protocol::Role::LowAlarm));
            }
        }
        const QString who = pane.channels.size() > 1 ? tr("P%1").arg(c.port) : QString();
        if (c.highAlarm)
            highs[*c.highAlarm].append(who);
        if (c.lowAlarm)
            lows[*c.lowAlarm].append(who);
    }
    const SeriesFormat f = seriesFormat(QStringLiteral("tip"), m_session.temperatureUnit());
    const double inf = std::numeric_limits<double>::infinity();
    QList<ChartBand> out;
    const auto label = [&f](const QString &what, qint32 wire, const QStringList &ports) {
        const QString text = what + QLatin1Char(' ') + f.format(f.toDisplay(wire));
        const QString who = ports.join(QLatin1Char(' ')).trimmed();
        return who.isEmpty() ? text : text + QStringLiteral(" (") + who + QLatin1Char(')');
    };
    for (auto it = highs.cbegin(); it != highs.cend(); ++it)
        out.append({ChartAxis::Left, f.toDisplay(it.key()), inf, QColor(0xC6, 0x28, 0x28),
                    label(tr("High alarm"), it.key(), it.value()), true});
    for (auto it = lows.cbegin(); it != lows.cend(); ++it)
        out.append({ChartAxis::Left, -inf, f.toDisplay(it.key()), QColor(0x15, 0x65, 0xC0),
                    label(tr("Low alarm"), it.key(), it.value()), false});
    return out;
}

// The readout has a place of its own under the panes, as high as its width needs for every
// cell, so hovering never moves the plots (readoutpanel.h).
void ChartsPage::buildReadout(QVBoxLayout *layout) {
    m_readout = new ReadoutPanel(this);
    m_readout->setObjectName(QStringLiteral("chartReadout"));
    m_readout->setAccessibleName(tr("Values under the cursor"));
    layout->addWidget(m_readout);
}

// What the readout must make room for: every pane's cells with each value at its widest.
void ChartsPage::updateReadoutTemplate() {
    QStringList cells;
    for (const Pane &pane : std::as_const(m_panes)) {
        QList<ReadoutValue> widest;
        for (int i = 0; i < pane.traces.size(); ++i)
            widest.append({i, true, 0, 0, -888.8});
        cells.append(readoutCells(pane.traces, widest));
    }
    m_readout->setTemplate(cells);
}

// The measurements sit under a header that folds them away; until someone folds or unfolds
// them, they are shown only where the page is tall enough to keep the plots roomy.
void ChartsPage::buildMeasurements(QVBoxLayout *layout) {
    auto *header = new QHBoxLayout;
    m_measureToggle = new QToolButton(this);
    m_measureToggle->setObjectName(QStringLiteral("measurementsToggle"));
    m_measureToggle->setText(tr("&Measurements"));
    m_measureToggle->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_measureToggle->setCheckable(true);
    m_measureToggle->setAutoRaise(true);
    m_measureToggle->setToolTip(tr("Heat-ups, recoveries and min/max/mean of the visible window"));
    connect(m_measureToggle, &QToolButton::clicked, this, [this](bool on) {
        m_measureChosen = true;
        showMeasurements(on);
    });
    auto *toleranceLabel = new QLabel(tr("Heat-up and recovery &band ±"), this);
    m_tolerance = new QDoubleSpinBox(this);
    m_tolerance->setObjectName(QStringLiteral("toleranceSpin"));
    m_tolerance->setAccessibleName(tr("Tolerance band around the setpoint"));
    m_tolerance->setRange(1, 50);
    m_tolerance->setDecimals(0);
    m_tolerance->setValue(5);
    toleranceLabel->setBuddy(m_tolerance);
    header->addWidget(m_measureToggle);
    header->addSpacing(12);
    header->addWidget(toleranceLabel);
    header->addWidget(m_tolerance);
    header->addStretch(1);
    layout->addLayout(header);
    m_measurements = new QPlainTextEdit(this);
    m_measurements->setObjectName(QStringLiteral("measurementText"));
    m_measurements->setAccessibleName(tr("Measurements of the visible window"));
    m_measurements->setReadOnly(true);
    m_measurements->setMaximumHeight(fontMetrics().lineSpacing() * 7);
    layout->addWidget(m_measurements);
    showMeasurements(true);
}

void ChartsPage::showMeasurements(bool shown) {
    m_measureToggle->setChecked(shown);
    m_measureToggle->setArrowType(shown ? Qt::DownArrow : Qt::RightArrow);
    m_measurements->setVisible(shown);
    if (shown)
        updateMeasurements();
}

bool ChartsPage::measurementsShown() const {
    return m_measureToggle->isChecked();
}

void ChartsPage::resizeEvent(QResizeEvent *event) {
    Page::resizeEvent(event);
    if (!m_measureChosen)
        showMeasurements(height() >= kMeasurementsFromHeight);
}

void ChartsPage::onHover(qint64 timeMs) {
    m_hover = timeMs;
    QStringList station, feeder;
    for (const Pane &pane : std::as_const(m_panes)) {
        pane.widget->setCrosshair(timeMs);
        const QStringList cells = readoutCells(
            pane.traces, readoutAt(shownTelemetry(), shownChannels(), pane.traces, timeMs));
        (shownChannels().at(pane.channels.first()).isFeeder() ? feeder : station).append(cells);
    }
    m_readout->showValues(readoutTimeText(timeMs), station + feeder);
}

void ChartsPage::onLeave() {
    m_hover.reset();
    for (const Pane &pane : std::as_const(m_panes))
        pane.widget->setCrosshair(std::nullopt);
    m_readout->showHint(
        {tr("Point at a chart to read every series at that instant."),
         tr("Wheel: zoom · drag: pan · Shift+drag: zoom to a range · double-click: reset.")});
}

QString ChartsPage::readoutText() const {
    return m_readout->text();
}

QString ChartsPage::measurementText() const {
    return m_measurements->toPlainText();
}

void ChartsPage::setTolerance(double display) {
    m_tolerance->setValue(display);
}

void ChartsPage::updateMeasurements() {
    MeasurementRequest r;
    r.t0 = m_viewport.start();
    r.t1 = m_viewport.end();
    r.unit = m_session.temperatureUnit();
    r.hardware = m_hardware->isChecked();
    // The band is a temperature difference: no 32 °F offset.
    const double scale = seriesFormat(QStringLiteral("tip"), r.unit).scale;
    r.toleranceWire = qMax(1, int(std::lround(m_tolerance->value() / scale)));
    // Unchanged text is not set again: that would relayout and repaint the panel every second.
    const QString text = measurementReport(shownTelemetry(), shownChannels(), r);
    if (text == m_measurements->toPlainText())
        return;
    // Where the reader had scrolled to stays in view: a following chart updates this every
    // second, and jumping back to the top each time made the lower ports unreadable.
    QScrollBar *bar = m_measurements->verticalScrollBar();
    const int scrolled = bar->value();
    m_measurements->setPlainText(text);
    bar->setValue(qMin(scrolled, bar->maximum()));
}

} // namespace tipscope::gui
