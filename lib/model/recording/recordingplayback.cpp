#include "model/recording/recordingplayback.h"

#include "model/live/telemetryrecorder.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QTimer>

namespace tipscope::model {

namespace {
struct RecordingPlaybackTr {
    Q_DECLARE_TR_FUNCTIONS(RecordingPlayback)
};

// "01" as the recording writes a bus address; empty for a device that answers without one.
std::optional<int> recordedAddress(const QString &text) {
    bool ok = false;
    const int address = text.toInt(&ok);
    return ok ? std::optional<int>(address) : std::nullopt;
}
} // namespace

RecordingPlayback *RecordingPlayback::start(Session &session) {
    return new RecordingPlayback(session);
}

RecordingPlayback::RecordingPlayback(Session &session)
    : QObject(&session)
    , m_session(session) {
    connect(&m_loader, &RecordingLoader::finished, this, &RecordingPlayback::onLoaded);
    m_loader.start(session.settings().recordingPath);
}

void RecordingPlayback::onLoaded(const QString &error) {
    const QFileInfo file(m_session.settings().recordingPath);
    if (!error.isEmpty()) {
        end(Session::State::Failed, RecordingPlaybackTr::tr("the recording %1 cannot be played: %2")
                                        .arg(file.fileName(), error));
        return;
    }
    m_recording = m_loader.takeRecording();
    const QString line = m_session.playbackLine();
    const double powerScale = seriesFormat(QStringLiteral("power"), TemperatureUnit::Celsius).scale;
    for (const ChartChannel &channel : std::as_const(m_recording->channels)) {
        const TelemetryBuffer *source = m_recording->telemetry->buffer(channel.key);
        // Joints are found in the tip's curve: a channel without one has nothing to play.
        if (channel.isFeeder() || !source || source->seriesIndex(QStringLiteral("tip")) < 0)
            continue;
        const DeviceIdentity device{line, recordedAddress(channel.address), channel.deviceModel,
                                    channel.softwareVersion};
        const TelemetryKey key = TelemetryRecorder::keyOf(device, channel.port);
        m_session.telemetry().ensureBuffer(key, source->seriesNames());
        m_session.joints().watch(
            this, key, {device, channel.port, [tool = channel.tool] { return tool; }, powerScale});
        m_ports.push_back({key, source});
    }
    if (m_ports.empty()) {
        end(Session::State::Failed,
            RecordingPlaybackTr::tr("the recording %1 holds no station port to play")
                .arg(file.fileName()));
        return;
    }
    m_playedUntilMs = m_recording->firstMs;
    m_session.setPlaybackState(
        Session::State::Connected,
        RecordingPlaybackTr::tr("playing the recording %1").arg(file.fileName()));
    QTimer::singleShot(0, this, &RecordingPlayback::playSome);
}

// One stretch of every port, each sample with all its series and each recorded gap before it.
void RecordingPlayback::playSome() {
    const qint64 from = m_playedUntilMs;
    const qint64 to = qMin(from + kStretchMs, m_recording->lastMs + 1);
    Telemetry &telemetry = m_session.telemetry();
    for (const Port &port : m_ports) {
        QList<QList<TelemetrySample>> series;
        for (int s = 0; s < port.source->seriesCount(); ++s)
            series.append(port.source->samples(s, from, to));
        QList<TelemetryGap> gaps;
        for (const TelemetryGap &gap : port.source->gaps().within(from, to))
            if (gap.startMs >= from)
                gaps.append(gap);
        qsizetype nextGap = 0;
        QList<qint32> values(series.size());
        const QList<TelemetrySample> &times = series.constFirst();
        for (qsizetype i = 0; i < times.size(); ++i) {
            const qint64 t = times.at(i).timeMs;
            while (nextGap < gaps.size() && gaps.at(nextGap).startMs <= t) {
                telemetry.markGap(port.key, gaps.at(nextGap).startMs, gaps.at(nextGap).cause);
                ++nextGap;
            }
            for (qsizetype s = 0; s < series.size(); ++s)
                values[s] = series.at(s).value(i).value;
            if (telemetry.append(port.key, t, values) == AppendResult::Accepted)
                ++m_played;
        }
        for (; nextGap < gaps.size(); ++nextGap)
            telemetry.markGap(port.key, gaps.at(nextGap).startMs, gaps.at(nextGap).cause);
    }
    telemetry.notifyNow();
    m_playedUntilMs = to;
    if (to > m_recording->lastMs) {
        end(Session::State::Disconnected,
            RecordingPlaybackTr::tr("the recording %1 played: %n sample(s)", nullptr,
                                    int(qMin<qint64>(m_played, INT_MAX)))
                .arg(QFileInfo(m_session.settings().recordingPath).fileName()));
        return;
    }
    QTimer::singleShot(0, this, &RecordingPlayback::playSome);
}

void RecordingPlayback::end(Session::State state, const QString &text) {
    // Nothing after the last sample was recorded: a joint still in progress is incomplete.
    m_session.joints().unwatch(this);
    m_session.setPlaybackState(state, text);
    Q_EMIT finished();
}

} // namespace tipscope::model
