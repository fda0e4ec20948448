#include "model/recording/chartcsv.h"

#include "base/csv.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QFileDevice>
#include <QIODevice>
#include <cmath>

namespace tipscope::model {

namespace {
struct ChartCsvTr {
    Q_DECLARE_TR_FUNCTIONS(ChartCsv)
};

// An export reads this much of the history at a time.
constexpr qint64 kSliceMs = 10 * 60'000;

// Exact and fast for the common formats (°C, per mille as %, tenths of a mm): the wire integer
// with a decimal point put in, instead of a round trip through a double.
QString formatValue(qint32 wire, const SeriesFormat &f) {
    const double unit = std::pow(10.0, -f.decimals);
    if (f.offset == 0 && std::abs(f.scale - unit) < 1e-12 && f.decimals <= 3) {
        if (f.decimals == 0)
            return QString::number(wire);
        const qint64 divisor = qint64(std::llround(std::pow(10.0, f.decimals)));
        const qint64 magnitude = std::abs(qint64(wire));
        return QStringLiteral("%1%2.%3")
            .arg(wire < 0 ? QStringLiteral("-") : QString())
            .arg(magnitude / divisor)
            .arg(magnitude % divisor, f.decimals, 10, QLatin1Char('0'));
    }
    return QString::number(f.toDisplay(wire), 'f', f.decimals);
}

QString channelLine(const ChartChannel &c) {
    QStringList parts = {QStringLiteral("device=") + c.deviceModel,
                         QStringLiteral("address=") + c.address,
                         QStringLiteral("device software=") + c.softwareVersion};
    parts.append(c.isFeeder() ? QStringLiteral("feeder")
                              : QStringLiteral("port=%1; tool=%2").arg(c.port).arg(c.tool));
    // Limits in wire units (°C) whatever the columns' unit, so they read back exactly.
    if (c.highAlarm)
        parts.append(QStringLiteral("high alarm °C=%1").arg(*c.highAlarm));
    if (c.lowAlarm)
        parts.append(QStringLiteral("low alarm °C=%1").arg(*c.lowAlarm));
    return QStringLiteral("# channel %1: %2").arg(c.id, parts.join(QStringLiteral("; ")));
}
} // namespace

QString chartcsv::columnName(const QString &channelId, const QString &series,
                             const SeriesFormat &format) {
    const QString name = channelId + QLatin1Char(' ') + series;
    return format.unit.isEmpty() ? name
                                 : name + QStringLiteral(" [") + format.unit + QLatin1Char(']');
}

QString chartcsv::timeText(qint64 ms) {
    return QDateTime::fromMSecsSinceEpoch(ms, Qt::UTC).toString(Qt::ISODateWithMs);
}

ChartCsvWriter::ChartCsvWriter(QIODevice &device, const QList<ChartChannel> &channels,
                               TemperatureUnit unit)
    : m_device(device)
    , m_out(&device)
    , m_channels(channels) {
    for (const ChartChannel &c : channels) {
        QList<SeriesFormat> formats;
        for (const QString &s : c.series)
            formats.append(seriesFormat(s, unit));
        m_formats.append(formats);
    }
}

bool ChartCsvWriter::writeHeader(const QString &softwareVersion) {
    m_out << chartcsv::kMagic << '\n'
          << "# software: TipScope " << softwareVersion << '\n'
          << "# created: " << chartcsv::timeText(QDateTime::currentMSecsSinceEpoch()) << '\n'
          << "# time: ISO 8601, UTC, milliseconds; values in the units named in the column "
             "headers; an empty cell: no sample of that channel at that time\n"
          << "# status: the station's R-PSx number (units: working 0, stand 1, sleep 2, "
             "hibernation 3; tens: cooling)\n";
    for (const ChartChannel &c : std::as_const(m_channels))
        m_out << channelLine(c) << '\n';
    QStringList columns = {QLatin1String(chartcsv::kTimeColumn)};
    for (qsizetype i = 0; i < m_channels.size(); ++i)
        for (qsizetype s = 0; s < m_channels.at(i).series.size(); ++s)
            columns.append(chartcsv::columnName(m_channels.at(i).id, m_channels.at(i).series.at(s),
                                                m_formats.at(i).at(s)));
    columns.append(QLatin1String(chartcsv::kEventsColumn));
    m_out << columns.join(QLatin1Char(',')) << '\n';
    m_out.flush();
    return m_out.status() == QTextStream::Ok;
}

std::optional<qint64> ChartCsvWriter::fullRateFrom(const Telemetry &telemetry,
                                                   const QList<ChartChannel> &channels, qint64 t0) {
    std::optional<qint64> from;
    for (const ChartChannel &c : channels) {
        const TelemetryBuffer *buffer = telemetry.buffer(c.key);
        if (buffer && buffer->summaryCount() > 0 && t0 < buffer->fullRateFrom())
            from = qMax(from.value_or(buffer->fullRateFrom()), buffer->fullRateFrom());
    }
    return from;
}

ChannelRows ChartCsvWriter::collect(const Telemetry &telemetry, const ChartChannel &channel,
                                    qint64 t0, qint64 t1) {
    ChannelRows rows;
    const TelemetryBuffer *buffer = telemetry.buffer(channel.key);
    if (!buffer)
        return rows;
    QList<QList<TelemetryBuffer::Sample>> bySeries;
    for (int s = 0; s < buffer->seriesCount(); ++s)
        bySeries.append(buffer->samples(s, t0, t1));
    for (const TelemetryGap &g : buffer->gaps().within(t0, t1))
        if (g.startMs >= t0)
            rows.gaps.append(g);
    const qsizetype count = bySeries.isEmpty() ? 0 : bySeries.first().size();
    rows.times.reserve(count);
    rows.values.reserve(count);
    for (qsizetype i = 0; i < count; ++i) {
        rows.times.append(bySeries.first().at(i).timeMs);
        QList<qint32> values;
        values.reserve(bySeries.size());
        for (const auto &series : std::as_const(bySeries))
            values.append(series.at(i).value);
        rows.values.append(values);
    }
    return rows;
}

bool ChartCsvWriter::writeWindow(const Telemetry &telemetry, const ChartEvents &events, qint64 t0,
                                 qint64 t1) {
    for (qint64 from = t0; from < t1; from += kSliceMs) {
        const qint64 to = qMin(t1, from + kSliceMs);
        QList<ChannelRows> rows;
        for (const ChartChannel &c : std::as_const(m_channels))
            rows.append(collect(telemetry, c, from, to));
        if (!writeRows(rows, events.between(from, to)))
            return false;
    }
    return true;
}

bool ChartCsvWriter::writeRows(const QList<ChannelRows> &rows, const QList<ChartEvent> &events) {
    // Events and gaps share the events column; in time order, one a row.
    QList<QPair<qint64, QString>> notes;
    for (const ChartEvent &e : events)
        notes.append({e.timeMs, e.toCsvCell()});
    for (qsizetype c = 0; c < rows.size(); ++c)
        for (const TelemetryGap &g : rows.at(c).gaps)
            notes.append({g.startMs, m_channels.at(c).id + QLatin1Char(' ') +
                                         QLatin1String(chartcsv::kGapKind) + QStringLiteral(": ") +
                                         TelemetryGap::causeToken(g.cause)});
    std::stable_sort(notes.begin(), notes.end(),
                     [](const auto &a, const auto &b) { return a.first < b.first; });
    QList<qsizetype> next(rows.size(), 0);
    qsizetype nextEvent = 0;
    QList<const QList<qint32> *> cells(rows.size(), nullptr);
    for (;;) {
        // The earliest pending instant over every channel and the events: one row.
        std::optional<qint64> time;
        for (qsizetype c = 0; c < rows.size(); ++c)
            if (next.at(c) < rows.at(c).times.size())
                time = qMin(time.value_or(rows.at(c).times.at(next.at(c))),
                            rows.at(c).times.at(next.at(c)));
        if (nextEvent < notes.size())
            time = qMin(time.value_or(notes.at(nextEvent).first), notes.at(nextEvent).first);
        if (!time)
            break;
        for (qsizetype c = 0; c < rows.size(); ++c) {
            const bool here =
                next.at(c) < rows.at(c).times.size() && rows.at(c).times.at(next.at(c)) == *time;
            cells[c] = here ? &rows.at(c).values.at(next[c]++) : nullptr;
        }
        QString event;
        if (nextEvent < notes.size() && notes.at(nextEvent).first == *time)
            event = notes.at(nextEvent++).second;
        writeRow(*time, cells, event);
    }
    m_out.flush();
    return m_out.status() == QTextStream::Ok;
}

void ChartCsvWriter::writeRow(qint64 timeMs, const QList<const QList<qint32> *> &cells,
                              const QString &event) {
    m_out << chartcsv::timeText(timeMs);
    for (qsizetype c = 0; c < cells.size(); ++c) {
        const qsizetype width = m_formats.at(c).size();
        for (qsizetype s = 0; s < width; ++s) {
            m_out << ',';
            if (cells.at(c) && s < cells.at(c)->size())
                m_out << formatValue(cells.at(c)->at(s), m_formats.at(c).at(s));
        }
    }
    m_out << ',' << base::csv::quoted(event) << '\n';
    ++m_rows;
}

QString ChartCsvWriter::errorString() const {
    if (m_out.status() == QTextStream::Ok)
        return {};
    // A write the file system cut short (a full disk, a file size limit) leaves Qt no reason.
    const auto *file = qobject_cast<const QFileDevice *>(&m_device);
    if (file && file->error() == QFileDevice::NoError)
        return ChartCsvTr::tr(
            "the file could not be written whole: the disk is full or the file reached its size "
            "limit");
    const QString why = m_device.errorString();
    return why.isEmpty() ? ChartCsvTr::tr("the file could not be written") : why;
}

} // namespace tipscope::model
