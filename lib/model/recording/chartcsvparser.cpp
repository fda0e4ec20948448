#include "model/recording/chartcsvparser.h"

#include "base/csv.h"
#include "base/elide.h"
#include "model/recording/chartcsv.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QRegularExpression>
#include <QStringDecoder>
#include <charconv>
#include <cstring>

namespace tipscope::model {

namespace {
struct ChartCsvParserTr {
    Q_DECLARE_TR_FUNCTIONS(ChartCsvReader)
};

// Bytes looked at for NUL before the first line: an image or an archive renamed .csv is called
// binary, rather than "not UTF-8" for its first line.
constexpr qsizetype kBinaryProbeBytes = 4096;
// A QString's and a map node's own cost beside its characters, for heldBytes().
constexpr qint64 kEntryOverhead = 96;

int digits(QByteArrayView s, qsizetype at, qsizetype count) {
    int v = 0;
    for (qsizetype i = at; i < at + count; ++i) {
        const char c = s[i];
        if (c < '0' || c > '9')
            return -1;
        v = v * 10 + (c - '0');
    }
    return v;
}

// Days from 1970-01-01 to y-m-d of the proleptic Gregorian calendar (H. Hinnant's algorithm).
qint64 daysFromCivil(int y, int m, int d) {
    y -= m <= 2;
    const qint64 era = (y >= 0 ? y : y - 399) / 400;
    const int yoe = int(y - era * 400);
    const int doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
    const int doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + doe - 719468;
}

// The writer's own form, "2026-01-01T12:00:00.250Z", read without QDateTime's general parser
// (most of a row's cost); anything else, or any field out of range, is left to QDateTime.
std::optional<qint64> fastTime(QByteArrayView s) {
    if (s.size() != 24 || s[4] != '-' || s[7] != '-' || s[10] != 'T' || s[13] != ':' ||
        s[16] != ':' || s[19] != '.' || s[23] != 'Z')
        return std::nullopt;
    const int y = digits(s, 0, 4), mo = digits(s, 5, 2), d = digits(s, 8, 2);
    const int h = digits(s, 11, 2), mi = digits(s, 14, 2), sec = digits(s, 17, 2);
    const int ms = digits(s, 20, 3);
    if (y < 1 || mo < 1 || mo > 12 || d < 1 || h < 0 || h > 23 || mi < 0 || mi > 59 || sec < 0 ||
        sec > 59 || ms < 0)
        return std::nullopt;
    static constexpr int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    const bool leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
    if (d > kDays[mo - 1] + (mo == 2 && leap ? 1 : 0))
        return std::nullopt;
    return ((daysFromCivil(y, mo, d) * 24 + h) * 60 + mi) * 60'000 + sec * 1000 + ms;
}

std::optional<qint64> timeOf(QByteArrayView cell) {
    const QByteArrayView trimmed = cell.trimmed();
    if (const auto fast = fastTime(trimmed))
        return fast;
    const QDateTime time = QDateTime::fromString(QString::fromUtf8(trimmed), Qt::ISODateWithMs);
    return time.isValid() ? std::optional<qint64>(time.toMSecsSinceEpoch()) : std::nullopt;
}

// A number as written in a recording: '.' as the decimal point whatever the locale, an exponent
// allowed, nothing else in the cell.
std::optional<double> number(QByteArrayView cell) {
    if (cell.startsWith('+'))
        cell = cell.sliced(1);
    double value = 0;
    const char *end = cell.data() + cell.size();
    const auto [stop, error] = std::from_chars(cell.data(), end, value);
    if (error != std::errc() || stop != end || cell.isEmpty())
        return std::nullopt;
    return value;
}

bool isAscii(QByteArrayView bytes) {
    for (const char c : bytes)
        if (static_cast<unsigned char>(c) >= 0x80)
            return false;
    return true;
}
} // namespace

ChartCsvParser::ChartCsvParser() = default;

bool ChartCsvParser::fail(const QString &message) {
    m_error = m_line > 0 ? ChartCsvParserTr::tr("line %1: %2").arg(m_line).arg(message) : message;
    return false;
}

bool ChartCsvParser::feed(const char *data, qsizetype size) {
    if (m_firstChunk && size > 0) {
        m_firstChunk = false;
        if (std::memchr(data, 0, size_t(qMin(size, kBinaryProbeBytes))))
            return fail(ChartCsvParserTr::tr("the file holds binary data, not CSV text"));
    }
    qsizetype start = 0;
    while (start < size) {
        const auto *newline =
            static_cast<const char *>(std::memchr(data + start, '\n', size_t(size - start)));
        if (!newline) {
            m_pending.append(data + start, size - start);
            if (m_pending.size() <= ChartCsvReader::kMaxLineBytes + 1)
                return true;
            ++m_line;
            return fail(
                ChartCsvParserTr::tr("the line is longer than %1 bytes (is this a chart CSV?)")
                    .arg(ChartCsvReader::kMaxLineBytes));
        }
        const qsizetype end = newline - data;
        bool ok = false;
        if (m_pending.isEmpty()) {
            ok = line(QByteArrayView(data + start, end - start));
        } else {
            const QByteArray whole = m_pending.append(data + start, end - start);
            m_pending = QByteArray();
            ok = line(whole);
        }
        if (!ok)
            return false;
        start = end + 1;
    }
    return true;
}

bool ChartCsvParser::line(QByteArrayView bytes) {
    ++m_line;
    while (bytes.endsWith('\r'))
        bytes.chop(1);
    if (bytes.size() > ChartCsvReader::kMaxLineBytes)
        return fail(ChartCsvParserTr::tr("the line is longer than %1 bytes (is this a chart CSV?)")
                        .arg(ChartCsvReader::kMaxLineBytes));
    if (m_line == 1 && bytes.startsWith("\xEF\xBB\xBF"))
        bytes = bytes.sliced(3); // the byte-order mark some spreadsheets write
    if (!bytes.isEmpty() && std::memchr(bytes.data(), 0, size_t(bytes.size())))
        return fail(ChartCsvParserTr::tr("the file holds binary data, not CSV text"));
    if (!isAscii(bytes)) {
        QStringDecoder utf8(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
        const QString checked = utf8.decode(bytes);
        if (utf8.hasError())
            return fail(
                ChartCsvParserTr::tr("the text is not UTF-8 (save the file as \"CSV UTF-8\")"));
    }
    if (bytes.startsWith('#')) {
        if (++m_comments > ChartCsvReader::kMaxCommentLines)
            return fail(ChartCsvParserTr::tr(
                            "more than %1 comment lines (\"#\"); a recording has a few, and "
                            "one per channel")
                            .arg(ChartCsvReader::kMaxCommentLines));
        comment(QString::fromUtf8(bytes));
        return true;
    }
    if (bytes.trimmed().isEmpty())
        return true;
    if (!base::csv::splitLine(bytes, m_cells))
        return fail(ChartCsvParserTr::tr("a quoted cell is not closed"));
    return m_haveHeader ? row(m_cells) : header(m_cells);
}

void ChartCsvParser::comment(const QString &text) {
    static const QRegularExpression channel(QStringLiteral("^# channel (\\w+): (.*)$"));
    if (text.startsWith(QLatin1String("# software: "))) {
        m_data.recording->software = text.mid(12).trimmed();
        return;
    }
    const auto m = channel.match(text);
    if (!m.hasMatch())
        return;
    for (const QString &field : m.captured(2).split(QStringLiteral("; "))) {
        const qsizetype eq = field.indexOf(QLatin1Char('='));
        if (eq <= 0)
            continue;
        m_meta[m.captured(1)].insert(field.left(eq), field.mid(eq + 1));
        m_metaBytes += 2 * (field.size() + m.capturedLength(1)) + 2 * kEntryOverhead;
    }
}

bool ChartCsvParser::header(const base::csv::Cells &cells) {
    static const QRegularExpression name(
        QStringLiteral("^(port(\\d+)|feeder) (\\w+)(?: \\[(.+)\\])?$"));
    if (cells.at(0) != QByteArrayView(chartcsv::kTimeColumn))
        return fail(
            ChartCsvParserTr::tr("the header row should start with \"time\" (is this a chart CSV "
                                 "written by TipScope?)"));
    if (cells.size() > ChartCsvReader::kMaxColumns)
        return fail(ChartCsvParserTr::tr("%1 columns; replay reads at most %2")
                        .arg(cells.size())
                        .arg(ChartCsvReader::kMaxColumns));
    QList<ChartChannel> &channels = m_data.recording->channels;
    for (qsizetype i = 1; i < cells.size(); ++i) {
        const QString cell = cells.text(i);
        if (cell == QLatin1String(chartcsv::kEventsColumn)) {
            m_eventColumns.append(int(m_columns.size()));
            m_columns.append(Column{});
            continue;
        }
        const auto m = name.match(cell);
        if (!m.hasMatch())
            return fail(
                ChartCsvParserTr::tr("column %1 \"%2\" is not \"port<n> <series> [unit]\" or "
                                     "\"feeder <series> [unit]\"")
                    .arg(i + 1)
                    .arg(base::elided(cell)));
        const QString id = m.captured(1);
        const QString series = m.captured(3);
        const QString unit = m.captured(4);
        SeriesFormat format = seriesFormat(series, TemperatureUnit::Celsius);
        if (unit == QStringLiteral("°F") && format.unit == QStringLiteral("°C")) {
            format = seriesFormat(series, TemperatureUnit::Fahrenheit);
            m_data.recording->temperatureUnit = TemperatureUnit::Fahrenheit;
        }
        if (unit != format.unit)
            return fail(ChartCsvParserTr::tr("column %1 \"%2\": the unit should be \"%3\"")
                            .arg(i + 1)
                            .arg(base::elided(cell), format.unit.isEmpty()
                                                         ? ChartCsvParserTr::tr("none")
                                                         : format.unit));
        qsizetype c = 0;
        while (c < channels.size() && channels.at(c).id != id)
            ++c;
        if (c == channels.size())
            addChannel(id, m.captured(2).toInt());
        if (channels[c].series.contains(series))
            return fail(ChartCsvParserTr::tr("column %1 \"%2\" appears twice")
                            .arg(i + 1)
                            .arg(base::elided(cell)));
        channels[c].series.append(series);
        m_channelColumns[c].append(int(m_columns.size()));
        m_columns.append(Column{int(c), format});
    }
    if (channels.isEmpty())
        return fail(ChartCsvParserTr::tr("the header names no series columns"));
    // Storage grows with the samples, so the capacity costs nothing until it is used.
    for (const ChartChannel &c : std::as_const(channels))
        m_data.buffers.emplace_back(c.series, ChartCsvReader::kMaxSamplesPerChannel);
    m_meta.clear(); // read into the channels
    m_metaBytes = 0;
    m_haveHeader = true;
    return true;
}

void ChartCsvParser::addChannel(const QString &id, int port) {
    ChartChannel channel;
    channel.id = channel.key = id;
    channel.port = port;
    channel.title = channel.isFeeder() ? ChartCsvParserTr::tr("Feeder")
                                       : ChartCsvParserTr::tr("Port %1").arg(channel.port);
    const auto meta = m_meta.value(id);
    channel.deviceModel = meta.value(QStringLiteral("device"));
    channel.address = meta.value(QStringLiteral("address"));
    channel.softwareVersion = meta.value(QStringLiteral("device software"));
    channel.tool = meta.value(QStringLiteral("tool"));
    bool ok = false;
    if (const int high = meta.value(QStringLiteral("high alarm °C")).toInt(&ok); ok)
        channel.highAlarm = high;
    if (const int low = meta.value(QStringLiteral("low alarm °C")).toInt(&ok); ok)
        channel.lowAlarm = low;
    m_data.recording->channels.append(channel);
    m_channelColumns.append(QList<int>());
}

bool ChartCsvParser::channelValues(int channel, const base::csv::Cells &cells, QList<qint32> &out,
                                   bool &present) {
    out.clear();
    int filled = 0;
    const QList<int> &columns = m_channelColumns.at(channel);
    for (int i : columns) {
        const QByteArrayView cell = cells.at(i + 1).trimmed();
        if (cell.isEmpty())
            continue;
        ++filled;
        const auto display = number(cell);
        const auto wire = display ? m_columns.at(i).format.toWire(*display) : std::nullopt;
        if (!wire)
            return fail(ChartCsvParserTr::tr("column %1: \"%2\" is not a number")
                            .arg(i + 2)
                            .arg(base::elided(QString::fromUtf8(cell))));
        out.append(*wire);
    }
    present = filled > 0;
    if (filled != 0 && filled != columns.size())
        return fail(ChartCsvParserTr::tr("%1 has values in some of its columns but not all")
                        .arg(m_data.recording->channels.at(channel).id));
    return true;
}

bool ChartCsvParser::row(const base::csv::Cells &cells) {
    if (cells.size() != m_columns.size() + 1)
        return fail(ChartCsvParserTr::tr("%1 cells, but the header has %2 columns")
                        .arg(cells.size())
                        .arg(m_columns.size() + 1));
    const auto ms = timeOf(cells.at(0));
    if (!ms)
        return fail(ChartCsvParserTr::tr("\"%1\" is not an ISO 8601 time")
                        .arg(base::elided(cells.text(0))));
    ChartRecording &out = *m_data.recording;
    if (out.rows > 0 && *ms < out.lastMs)
        return fail(ChartCsvParserTr::tr(
                        "the time %1 is earlier than the row before it (rows must be in time "
                        "order)")
                        .arg(cells.text(0)));
    for (int c = 0; c < int(m_data.buffers.size()); ++c) {
        bool present = false;
        if (!channelValues(c, cells, m_values, present))
            return false;
        if (!present)
            continue;
        TelemetryBuffer &buffer = m_data.buffers[size_t(c)];
        if (buffer.size() >= ChartCsvReader::kMaxSamplesPerChannel)
            return fail(ChartCsvParserTr::tr(
                            "%1 has more than %2 samples, more than replay holds; split the "
                            "file")
                            .arg(out.channels.at(c).id)
                            .arg(ChartCsvReader::kMaxSamplesPerChannel));
        buffer.append(*ms, m_values);
    }
    if (!events(*ms, cells))
        return false;
    out.firstMs = out.rows == 0 ? *ms : out.firstMs;
    out.lastMs = *ms;
    ++out.rows;
    return true;
}

bool ChartCsvParser::events(qint64 ms, const base::csv::Cells &cells) {
    for (int i : std::as_const(m_eventColumns)) {
        if (cells.at(i + 1).isEmpty())
            continue;
        const QString cell = cells.text(i + 1);
        if (gap(ms, cell))
            continue;
        const auto event = ChartEvent::fromCsvCell(ms, cell);
        if (!event)
            return fail(ChartCsvParserTr::tr("the event \"%1\" is not \"<channel> <kind>: <text>\"")
                            .arg(base::elided(cell)));
        m_data.recording->events.add(*event);
    }
    return true;
}

bool ChartCsvParser::gap(qint64 ms, const QString &cell) {
    // "port1 gap: line-down"
    const QString head = cell.section(QStringLiteral(": "), 0, 0);
    const auto cause = TelemetryGap::causeFromToken(cell.section(QStringLiteral(": "), 1));
    if (head.section(QLatin1Char(' '), 1) != QLatin1String(chartcsv::kGapKind) || !cause)
        return false;
    const QString id = head.section(QLatin1Char(' '), 0, 0);
    for (qsizetype c = 0; c < m_data.recording->channels.size(); ++c)
        if (m_data.recording->channels.at(c).id == id) {
            m_data.buffers[size_t(c)].markGap(ms, *cause);
            return true;
        }
    return false;
}

bool ChartCsvParser::finish() {
    if (!m_pending.isEmpty()) {
        QByteArray last = std::move(m_pending);
        m_pending = QByteArray();
        if (!line(std::move(last)))
            return false;
    }
    m_line = 0;
    if (!m_haveHeader)
        return fail(ChartCsvParserTr::tr("the file is empty or holds only comments"));
    if (m_data.recording->rows == 0)
        return fail(ChartCsvParserTr::tr("the file has a header but no rows"));
    return true;
}

qint64 ChartCsvParser::heldBytes() const {
    qint64 bytes = m_metaBytes + m_pending.capacity() + m_data.recording->events.memoryBytes();
    for (const TelemetryBuffer &b : m_data.buffers)
        bytes += b.memoryBytes();
    return bytes;
}

ChartRecordingData ChartCsvParser::take() {
    return std::move(m_data);
}

} // namespace tipscope::model
