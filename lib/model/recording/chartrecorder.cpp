#include "model/recording/chartrecorder.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <limits>

namespace tipscope::model {

namespace {
struct ChartRecorderTr {
    Q_DECLARE_TR_FUNCTIONS(ChartRecorder)
};
} // namespace

ChartRecorder::ChartRecorder(Telemetry &telemetry, QObject *parent)
    : QObject(parent)
    , m_telemetry(&telemetry) {
    connect(&telemetry, &Telemetry::samplesAdded, this, [this] {
        if (isRecording())
            flush();
    });
}

ChartRecorder::~ChartRecorder() {
    stop();
}

QString ChartRecorder::start(const QString &path, const QList<ChartChannel> &channels,
                             TemperatureUnit unit, const QString &softwareVersion) {
    stop();
    if (channels.isEmpty())
        return ChartRecorderTr::tr("nothing to record: no station or feeder is connected");
    m_file.setFileName(path);
    // Unbuffered: a batch reaches the file when the writer flushes it, so a batch that a full
    // disk cuts part way can be taken back to the last row written whole (flush()).
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Unbuffered))
        return m_file.errorString();
    m_channels = channels;
    m_writer = std::make_unique<ChartCsvWriter>(m_file, channels, unit);
    m_cursors.clear();
    m_pendingEvents.clear();
    m_lastWrittenMs = 0;
    // From now on: the samples already held are not part of the recording.
    for (const ChartChannel &c : channels) {
        Cursor cursor;
        if (const auto *buffer = m_telemetry->buffer(c.key); buffer && !buffer->isEmpty()) {
            cursor.time = buffer->lastTime();
            cursor.doneAtTime = buffer->samples(0, cursor.time, cursor.time + 1).size();
            m_lastWrittenMs = qMax(m_lastWrittenMs, cursor.time);
        }
        m_cursors.append(cursor);
    }
    if (!m_writer->writeHeader(softwareVersion)) {
        const QString why = m_writer->errorString();
        stop();
        // Half a header is no recording: nothing is left rather than a file replay refuses.
        if (QFileInfo(path).isFile())
            QFile::remove(path);
        return why;
    }
    m_wholeBytes = m_file.size();
    m_wholeRows = 0;
    return {};
}

void ChartRecorder::stop() {
    if (!m_writer)
        return;
    flush();
    if (m_writer)
        m_rows = m_writer->rowsWritten();
    m_writer.reset();
    m_file.close();
}

void ChartRecorder::addEvent(const ChartEvent &event) {
    if (isRecording())
        m_pendingEvents.append(event);
}

void ChartRecorder::flush() {
    if (!m_writer)
        return;
    if (!m_telemetry) { // the session went first (application exit): keep what is written
        m_rows = m_writer->rowsWritten();
        m_writer.reset();
        m_file.close();
        return;
    }
    QList<ChannelRows> rows;
    for (qsizetype c = 0; c < m_channels.size(); ++c) {
        Cursor &cursor = m_cursors[c];
        ChannelRows r = ChartCsvWriter::collect(*m_telemetry, m_channels.at(c), cursor.time,
                                                std::numeric_limits<qint64>::max());
        // A gap stays in the window until the next sample: write it once, never before rows
        // already in the file.
        r.gaps.removeIf([&](const TelemetryGap &g) { return g.startMs <= cursor.gapsUntil; });
        for (TelemetryGap &g : r.gaps) {
            cursor.gapsUntil = g.startMs;
            g.startMs = qMax(g.startMs, m_lastWrittenMs);
        }
        const qsizetype skip = qMin(cursor.doneAtTime, r.times.size());
        r.times.remove(0, skip);
        r.values.remove(0, skip);
        if (!r.times.isEmpty()) {
            const qint64 last = r.times.last();
            const qsizetype atLast =
                r.times.size() -
                (std::lower_bound(r.times.cbegin(), r.times.cend(), last) - r.times.cbegin());
            cursor.doneAtTime = (last == cursor.time ? cursor.doneAtTime : 0) + atLast;
            cursor.time = last;
        }
        rows.append(r);
    }
    // An event stamped a little before rows already written goes in at the current end.
    for (ChartEvent &e : m_pendingEvents)
        e.timeMs = qMax(e.timeMs, m_lastWrittenMs);
    std::stable_sort(m_pendingEvents.begin(), m_pendingEvents.end(),
                     [](const ChartEvent &a, const ChartEvent &b) { return a.timeMs < b.timeMs; });
    const bool ok = m_writer->writeRows(rows, m_pendingEvents);
    for (const ChannelRows &r : std::as_const(rows))
        if (!r.times.isEmpty())
            m_lastWrittenMs = qMax(m_lastWrittenMs, r.times.last());
    if (!m_pendingEvents.isEmpty())
        m_lastWrittenMs = qMax(m_lastWrittenMs, m_pendingEvents.last().timeMs);
    m_pendingEvents.clear();
    if (ok) {
        m_wholeBytes = m_file.size();
        m_wholeRows = m_writer->rowsWritten();
        return;
    }
    const QString why = m_writer->errorString();
    m_writer.reset();
    // The file ends with the last batch written whole: a reader never meets half a row.
    if (m_file.size() > m_wholeBytes)
        m_file.resize(m_wholeBytes);
    m_rows = m_wholeRows;
    m_file.close();
    Q_EMIT failed(why);
}

} // namespace tipscope::model
