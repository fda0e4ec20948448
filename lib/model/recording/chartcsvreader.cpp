#include "model/recording/chartcsvreader.h"

#include "model/io/csv.h"
#include "model/recording/chartcsv.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QStringDecoder>

namespace tipscope::model {

namespace {
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(ChartCsvReader)
};

struct Column {
    int channel = -1; // -1: the events column
    SeriesFormat format;
};

struct ChannelData {
    QList<qint64> times;
    QList<qint32> values; // row-major, one per series
};

class Parser {
public:
    std::unique_ptr<ChartRecording> run(QIODevice &device, QString *error);

private:
    bool fail(const QString &message) {
        m_error = m_line > 0 ? Tr::tr("line %1: %2").arg(m_line).arg(message) : message;
        return false;
    }
    bool readLine(QIODevice &device, QString &text, bool &done);
    void comment(const QString &text);
    bool header(const QStringList &cells);
    bool row(const QStringList &cells);
    bool channelValues(int channel, const QStringList &cells, QList<qint32> &out, bool &present);
    std::unique_ptr<ChartRecording> finish();

    int m_line = 0;
    QString m_error;
    QString m_software;
    QMap<QString, QMap<QString, QString>> m_meta; // channel id -> "# channel" fields
    QList<Column> m_columns;
    QList<ChartChannel> m_channels;
    QList<ChannelData> m_data;
    std::unique_ptr<ChartRecording> m_out = std::make_unique<ChartRecording>();
    bool m_haveHeader = false;
    qint64 m_lastTime = 0;
};

bool Parser::readLine(QIODevice &device, QString &text, bool &done) {
    QByteArray bytes = device.readLine(ChartCsvReader::kMaxLineBytes + 2);
    done = bytes.isEmpty() && device.atEnd();
    if (done)
        return true;
    ++m_line;
    if (bytes.size() > ChartCsvReader::kMaxLineBytes && !bytes.endsWith('\n'))
        return fail(Tr::tr("the line is longer than %1 bytes (is this a chart CSV?)")
                        .arg(ChartCsvReader::kMaxLineBytes));
    while (bytes.endsWith('\n') || bytes.endsWith('\r'))
        bytes.chop(1);
    if (m_line == 1 && bytes.startsWith("\xEF\xBB\xBF"))
        bytes.remove(0, 3); // the byte-order mark some spreadsheets write
    if (bytes.contains('\0'))
        return fail(Tr::tr("the file holds binary data, not CSV text"));
    QStringDecoder utf8(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
    text = utf8.decode(bytes);
    if (utf8.hasError())
        return fail(Tr::tr("the text is not UTF-8 (save the file as \"CSV UTF-8\")"));
    return true;
}

void Parser::comment(const QString &text) {
    static const QRegularExpression channel(QStringLiteral("^# channel (\\w+): (.*)$"));
    if (text.startsWith(QLatin1String("# software: "))) {
        m_software = text.mid(12).trimmed();
    } else if (const auto m = channel.match(text); m.hasMatch()) {
        for (const QString &field : m.captured(2).split(QStringLiteral("; "))) {
            const qsizetype eq = field.indexOf(QLatin1Char('='));
            if (eq > 0)
                m_meta[m.captured(1)].insert(field.left(eq), field.mid(eq + 1));
        }
    }
}

bool Parser::header(const QStringList &cells) {
    static const QRegularExpression name(
        QStringLiteral("^(port(\\d+)|feeder) (\\w+)(?: \\[(.+)\\])?$"));
    if (cells.first() != QLatin1String(chartcsv::kTimeColumn))
        return fail(Tr::tr("the header row should start with \"time\" (is this a chart CSV "
                           "written by TipScope?)"));
    if (cells.size() > ChartCsvReader::kMaxColumns)
        return fail(Tr::tr("%1 columns; replay reads at most %2")
                        .arg(cells.size())
                        .arg(ChartCsvReader::kMaxColumns));
    for (qsizetype i = 1; i < cells.size(); ++i) {
        const QString &cell = cells.at(i);
        if (cell == QLatin1String(chartcsv::kEventsColumn)) {
            m_columns.append(Column{});
            continue;
        }
        const auto m = name.match(cell);
        if (!m.hasMatch())
            return fail(Tr::tr("column %1 \"%2\" is not \"port<n> <series> [unit]\" or "
                               "\"feeder <series> [unit]\"")
                            .arg(i + 1)
                            .arg(cell));
        const QString id = m.captured(1);
        const QString series = m.captured(3);
        const QString unit = m.captured(4);
        SeriesFormat format = seriesFormat(series, TemperatureUnit::Celsius);
        if (unit == QStringLiteral("°F") && format.unit == QStringLiteral("°C"))
            format = seriesFormat(series, TemperatureUnit::Fahrenheit);
        if (unit != format.unit)
            return fail(Tr::tr("column %1 \"%2\": the unit should be \"%3\"")
                            .arg(i + 1)
                            .arg(cell, format.unit.isEmpty() ? Tr::tr("none") : format.unit));
        qsizetype c = 0;
        while (c < m_channels.size() && m_channels.at(c).id != id)
            ++c;
        if (c == m_channels.size()) {
            ChartChannel channel;
            channel.id = channel.key = id;
            channel.port = m.captured(2).toInt();
            channel.title =
                channel.isFeeder() ? Tr::tr("Feeder") : Tr::tr("Port %1").arg(channel.port);
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
            m_channels.append(channel);
            m_data.append(ChannelData());
        }
        if (m_channels[c].series.contains(series))
            return fail(Tr::tr("column %1 \"%2\" appears twice").arg(i + 1).arg(cell));
        m_channels[c].series.append(series);
        m_columns.append(Column{int(c), format});
    }
    if (m_channels.isEmpty())
        return fail(Tr::tr("the header names no series columns"));
    m_haveHeader = true;
    return true;
}

bool Parser::channelValues(int channel, const QStringList &cells, QList<qint32> &out,
                           bool &present) {
    out.clear();
    int filled = 0, total = 0;
    for (qsizetype i = 0; i < m_columns.size(); ++i) {
        if (m_columns.at(i).channel != channel)
            continue;
        ++total;
        const QString cell = cells.at(i + 1).trimmed();
        if (cell.isEmpty())
            continue;
        ++filled;
        bool ok = false;
        const double display = cell.toDouble(&ok); // C locale: '.' whatever the system's
        const auto wire = ok ? m_columns.at(i).format.toWire(display) : std::nullopt;
        if (!wire)
            return fail(Tr::tr("column %1: \"%2\" is not a number").arg(i + 2).arg(cell));
        out.append(*wire);
    }
    present = filled > 0;
    if (filled != 0 && filled != total)
        return fail(Tr::tr("%1 has values in some of its columns but not all")
                        .arg(m_channels.at(channel).id));
    return true;
}

bool Parser::row(const QStringList &cells) {
    if (cells.size() != m_columns.size() + 1)
        return fail(Tr::tr("%1 cells, but the header has %2 columns")
                        .arg(cells.size())
                        .arg(m_columns.size() + 1));
    const QDateTime time = QDateTime::fromString(cells.first().trimmed(), Qt::ISODateWithMs);
    if (!time.isValid())
        return fail(Tr::tr("\"%1\" is not an ISO 8601 time").arg(cells.first()));
    const qint64 ms = time.toMSecsSinceEpoch();
    if (m_out->rows > 0 && ms < m_lastTime)
        return fail(Tr::tr("the time %1 is earlier than the row before it (rows must be in time "
                           "order)")
                        .arg(cells.first()));
    QList<qint32> values;
    for (int c = 0; c < m_channels.size(); ++c) {
        bool present = false;
        if (!channelValues(c, cells, values, present))
            return false;
        if (!present)
            continue;
        if (m_data[c].times.size() >= ChartCsvReader::kMaxSamplesPerChannel)
            return fail(Tr::tr("%1 has more than %2 samples, more than replay holds; split the "
                               "file")
                            .arg(m_channels.at(c).id)
                            .arg(ChartCsvReader::kMaxSamplesPerChannel));
        m_data[c].times.append(ms);
        m_data[c].values.append(values);
    }
    for (qsizetype i = 0; i < m_columns.size(); ++i) {
        const QString cell = cells.at(i + 1);
        if (m_columns.at(i).channel >= 0 || cell.isEmpty())
            continue;
        const auto event = ChartEvent::fromCsvCell(ms, cell);
        if (!event)
            return fail(Tr::tr("the event \"%1\" is not \"<channel> <kind>: <text>\"").arg(cell));
        m_out->events.add(*event);
    }
    m_out->firstMs = m_out->rows == 0 ? ms : m_out->firstMs;
    m_out->lastMs = m_lastTime = ms;
    ++m_out->rows;
    return true;
}

std::unique_ptr<ChartRecording> Parser::finish() {
    m_out->telemetry = std::make_unique<Telemetry>();
    for (qsizetype c = 0; c < m_channels.size(); ++c) {
        const ChartChannel &channel = m_channels.at(c);
        const ChannelData &data = m_data.at(c);
        const qsizetype width = channel.series.size();
        m_out->telemetry->ensureBuffer(channel.key, channel.series,
                                       int(qMax<qsizetype>(1, data.times.size())));
        for (qsizetype i = 0; i < data.times.size(); ++i)
            m_out->telemetry->append(channel.key, data.times.at(i), &data.values.at(i * width),
                                     width);
    }
    m_out->channels = m_channels;
    m_out->software = m_software;
    return std::move(m_out);
}

std::unique_ptr<ChartRecording> Parser::run(QIODevice &device, QString *error) {
    // An image or an archive renamed .csv: say so, rather than "not UTF-8" of its first line.
    if (device.peek(4096).contains('\0')) {
        *error = Tr::tr("the file holds binary data, not CSV text");
        return nullptr;
    }
    QStringList cells;
    for (;;) {
        QString text;
        bool done = false;
        bool ok = readLine(device, text, done);
        if (done)
            break;
        if (ok && text.startsWith(QLatin1Char('#'))) {
            comment(text);
            continue;
        }
        if (ok && text.trimmed().isEmpty())
            continue;
        if (ok && !csv::splitLine(text, cells))
            ok = fail(Tr::tr("a quoted cell is not closed"));
        if (ok)
            ok = m_haveHeader ? row(cells) : header(cells);
        if (!ok) {
            *error = m_error;
            return nullptr;
        }
    }
    m_line = 0;
    if (!m_haveHeader || m_out->rows == 0) {
        *error = m_haveHeader ? Tr::tr("the file has a header but no rows")
                              : Tr::tr("the file is empty or holds only comments");
        return nullptr;
    }
    return finish();
}
} // namespace

std::unique_ptr<ChartRecording> ChartCsvReader::read(QIODevice &device, QString *error) {
    QString ignored;
    return Parser().run(device, error ? error : &ignored);
}

std::unique_ptr<ChartRecording> ChartCsvReader::readFile(const QString &path, QString *error) {
    QString why;
    const QString name = QFileInfo(path).fileName();
    QFile file(path);
    std::unique_ptr<ChartRecording> result;
    if (file.size() > kMaxFileBytes)
        why = Tr::tr("the file is %1 MB; replay reads files up to %2 MB")
                  .arg(file.size() >> 20)
                  .arg(kMaxFileBytes >> 20);
    else if (!file.open(QIODevice::ReadOnly))
        why = file.errorString();
    else
        result = read(file, &why);
    if (!result && error)
        *error = name + QStringLiteral(", ") + why;
    return result;
}

} // namespace tipscope::model
