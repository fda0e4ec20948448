// ChartsPage's overlays and read-outs: event markers and alarm bands of a pane, the crosshair
// readout, and the measurement panel.
#include "chartspage.h"

#include "chartwidget.h"
#include "model/analysis/measurementreport.h"
#include "model/chart/chartframe.h"

#include <QDateTime>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPlainTextEdit>
#include <QToolButton>
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

void ChartsPage::onHover(qint64 timeMs) {
    m_hover = timeMs;
    QStringList lines;
    for (const Pane &pane : std::as_const(m_panes)) {
        pane.widget->setCrosshair(timeMs);
        lines.append(gui::readoutText(
            pane.traces, readoutAt(shownTelemetry(), shownChannels(), pane.traces, timeMs),
            timeMs));
    }
    m_readout->setText(lines.join(QLatin1Char('\n')));
}

void ChartsPage::onLeave() {
    m_hover.reset();
    for (const Pane &pane : std::as_const(m_panes))
        pane.widget->setCrosshair(std::nullopt);
    m_readout->setText(tr("Point at a chart to read every series at that instant. Wheel: zoom · "
                          "drag: pan · Shift+drag: zoom to a range · double-click: reset."));
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
    if (text != m_measurements->toPlainText())
        m_measurements->setPlainText(text);
}

} // namespace tipscope::gui
