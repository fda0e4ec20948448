#include "model/analysis/measurementreport.h"

#include "model/analysis/measurements.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QLocale>
#include <QSet>

namespace tipscope::model {

namespace {
struct MeasurementReportTr {
    Q_DECLARE_TR_FUNCTIONS(MeasurementReport)
};

constexpr qsizetype kFactsPerLine = 3;
const QString kSep = QStringLiteral("; ");

QString clock(qint64 ms) {
    return QDateTime::fromMSecsSinceEpoch(ms).toString(QStringLiteral("HH:mm:ss"));
}

QString statsLine(const TelemetryBuffer &buffer, const QString &series,
                  const MeasurementRequest &r) {
    const SeriesFormat f = seriesFormat(series, r.unit);
    const TelemetryBuffer::Stats s = buffer.windowStats(buffer.seriesIndex(series), r.t0, r.t1);
    if (s.count == 0)
        return {};
    SeriesFormat mean = f;
    mean.decimals = f.decimals + 1;
    return MeasurementReportTr::tr("%1: min %2, max %3, mean %4")
        .arg(seriesTitle(series), f.format(f.toDisplay(s.min)), f.format(f.toDisplay(s.max)),
             mean.format(double(s.mean) * f.scale + f.offset));
}

QStringList heatUpLines(const PortMeasurements &m, const SeriesFormat &temp, int maxListed) {
    QStringList out;
    for (qsizetype i = m.heatUps.size() - 1; i >= 0 && out.size() < maxListed; --i) {
        const HeatUp &h = m.heatUps.at(i);
        const QString what =
            h.wake ? MeasurementReportTr::tr("wake") : MeasurementReportTr::tr("heat-up");
        const QString target = temp.format(temp.toDisplay(h.target));
        out.append(
            h.reachedMs
                ? MeasurementReportTr::tr("%1 at %2 to %3: %4")
                      .arg(what, clock(h.startMs), target, durationText(*h.reachedMs - h.startMs))
                : MeasurementReportTr::tr("%1 at %2 to %3: not reached in this window")
                      .arg(what, clock(h.startMs), target));
    }
    if (m.heatUps.size() > maxListed)
        out.append(MeasurementReportTr::tr("… %n more heat-up(s)", nullptr,
                                           int(m.heatUps.size() - maxListed)));
    return out;
}

QStringList recoveryLines(const PortMeasurements &m, const SeriesFormat &temp, int maxListed) {
    QStringList out;
    for (qsizetype i = m.recoveries.size() - 1; i >= 0 && out.size() < maxListed; --i) {
        const Recovery &r = m.recoveries.at(i);
        const QString lowest = temp.format(temp.toDisplay(r.lowest));
        out.append(
            r.recoveredMs
                ? MeasurementReportTr::tr("recovery at %1: %2 (dip to %3)")
                      .arg(clock(r.startMs), durationText(*r.recoveredMs - r.startMs), lowest)
                : MeasurementReportTr::tr("dip at %1 to %2: not recovered in this window")
                      .arg(clock(r.startMs), lowest));
    }
    if (m.recoveries.size() > maxListed)
        out.append(MeasurementReportTr::tr("… %n more recovery(s)", nullptr,
                                           int(m.recoveries.size() - maxListed)));
    return out;
}
} // namespace

QString durationText(qint64 ms) {
    const QLocale locale;
    if (ms < 60'000)
        return MeasurementReportTr::tr("%1 s").arg(locale.toString(double(ms) / 1000, 'f', 1));
    if (ms < 3600'000)
        return MeasurementReportTr::tr("%1 min %2 s")
            .arg(ms / 60'000)
            .arg(ms / 1000 % 60, 2, 10, QLatin1Char('0'));
    return MeasurementReportTr::tr("%1 h %2 min")
        .arg(ms / 3600'000)
        .arg(ms / 60'000 % 60, 2, 10, QLatin1Char('0'));
}

QString measurementReport(const Telemetry &telemetry, const QList<ChartChannel> &channels,
                          const MeasurementRequest &request) {
    QStringList lines;
    const SeriesFormat temp = seriesFormat(QStringLiteral("tip"), request.unit);
    QSet<QString> transformers; // station addresses whose transformer is already listed
    for (const ChartChannel &c : channels) {
        const TelemetryBuffer *buffer = telemetry.buffer(c.key);
        if (!buffer)
            continue;
        QStringList facts;
        for (const QString &series : c.series) {
            if (!seriesFormat(series, request.unit).plotted ||
                (isHardwareSeries(series) && !request.hardware))
                continue;
            if (series == QLatin1String("transformer")) { // as the chart draws it: once
                if (transformers.contains(c.address))
                    continue;
                transformers.insert(c.address);
            }
            if (const QString line = statsLine(*buffer, series, request); !line.isEmpty())
                facts.append(line);
        }
        if (facts.isEmpty()) {
            lines.append(MeasurementReportTr::tr("%1: no samples in this window").arg(c.title));
            continue;
        }
        // Three facts a line: with the transistor and transformer curves on, one line of five
        // would wrap mid-fact in the panel's width.
        lines.append(c.title + QStringLiteral(" — ") + facts.mid(0, kFactsPerLine).join(kSep));
        for (qsizetype i = kFactsPerLine; i < facts.size(); i += kFactsPerLine)
            lines.append(QStringLiteral("    ") + facts.mid(i, kFactsPerLine).join(kSep));
        if (c.isFeeder())
            continue;
        const PortMeasurements m =
            Measurements::measurePort(*buffer, request.t0, request.t1, request.toleranceWire);
        for (const QString &line :
             heatUpLines(m, temp, request.maxListed) + recoveryLines(m, temp, request.maxListed))
            lines.append(QStringLiteral("    ") + line);
    }
    return lines.join(QLatin1Char('\n'));
}

} // namespace tipscope::model
