// tipscope-cli measure FILE [--json]: the heat-ups, wakes and recoveries of a recording, read by
// the replay's reader and found by the Charts page's measurements (band ±5 °C, the page's
// default), one line each in time order, in the recording's temperature unit.
#include "clicommands.h"

#include "model/analysis/portevents.h"
#include "model/recording/chartcsv.h"
#include "model/recording/chartcsvreader.h"

#include "base/elide.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <sys/stat.h>

namespace tipscope::cli {

using namespace tipscope::model;

namespace {

struct CliMeasureTr {
    Q_DECLARE_TR_FUNCTIONS(CliMeasure)
};

constexpr qint32 kToleranceWire = 5; // °C, as the Charts page starts

QString seconds(qint64 ms) {
    return QString::number(double(ms) / 1000, 'f', 1);
}

// "port1 recovery 2026-01-01T10:00:08.100Z 1.4 s setpoint 350 °C lowest 302 °C"; the duration
// is "-" when the recording ended first.
QString line(const PortEvent &e, const SeriesFormat &temp) {
    const auto value = [&temp](qint32 wire) {
        return QString::number(temp.toDisplay(wire), 'f', temp.decimals) + QLatin1Char(' ') +
               temp.unit;
    };
    QString text = QStringLiteral("%1 %2 %3 %4 setpoint %5")
                       .arg(e.channel, PortEvent::kindToken(e.kind), chartcsv::timeText(e.startMs),
                            e.endMs ? seconds(*e.endMs - e.startMs) + QStringLiteral(" s")
                                    : QStringLiteral("-"),
                            value(e.target));
    if (e.lowest)
        text += QStringLiteral(" lowest ") + value(*e.lowest);
    return text;
}

QJsonObject json(const PortEvent &e, const SeriesFormat &temp) {
    const auto value = [&temp](qint32 wire) { return temp.toDisplay(wire); };
    QJsonObject o{{QStringLiteral("channel"), e.channel},
                  {QStringLiteral("port"), e.port},
                  {QStringLiteral("kind"), PortEvent::kindToken(e.kind)},
                  {QStringLiteral("start"), chartcsv::timeText(e.startMs)},
                  {QStringLiteral("durationS"),
                   e.endMs ? QJsonValue(double(*e.endMs - e.startMs) / 1000) : QJsonValue()},
                  {QStringLiteral("setpoint"), value(e.target)},
                  {QStringLiteral("unit"), temp.unit}};
    if (e.lowest)
        o.insert(QStringLiteral("lowest"), value(*e.lowest));
    return o;
}

} // namespace

int runMeasure(const CliOptions &o, QTextStream &out, QTextStream &err) {
    if (o.args.size() != 1) {
        err << CliMeasureTr::tr(
                   "tipscope-cli: measure takes one FILE, a recording (record, or the Charts "
                   "page's Record or CSV export)")
            << Qt::endl;
        return kUsage;
    }
    // A FIFO is read as long as its writer writes, and waited for until one comes: said, so
    // that a measure with nobody writing is not taken for a hang.
    struct stat st {};
    if (::stat(QFile::encodeName(o.args.first()).constData(), &st) == 0 && S_ISFIFO(st.st_mode))
        err << "# "
            << CliMeasureTr::tr("%1 is a FIFO: waiting for what is written into it (Ctrl-C stops)")
                   .arg(base::elidedPath(o.args.first()))
            << Qt::endl;
    const auto read = ChartCsvReader::readFile(o.args.first());
    if (!read) {
        err << "tipscope-cli: " << read.error() << Qt::endl;
        return kRefused;
    }
    const ChartRecording *recording = read->get();
    const SeriesFormat temp = seriesFormat(QStringLiteral("tip"), recording->temperatureUnit);
    const QList<PortEvent> events =
        portEvents(*recording->telemetry, recording->channels, recording->firstMs,
                   recording->lastMs + 1, kToleranceWire);
    if (o.flags.contains(QStringLiteral("json"))) {
        QJsonArray array;
        for (const PortEvent &e : events)
            array.append(json(e, temp));
        out << QJsonDocument(array).toJson(QJsonDocument::Indented);
        return kOk;
    }
    for (const PortEvent &e : events)
        out << line(e, temp) << '\n';
    out.flush();
    return kOk;
}

} // namespace tipscope::cli
