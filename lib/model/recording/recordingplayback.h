// RecordingPlayback: a chart recording played as a line, so that a recorded stream of samples
// goes the one way a wire's samples go: into the session's telemetry, through its joint watcher
// (judged by the line's limits) and on to whatever keeps or publishes the session's joints (the
// journal, MQTT, CFX). The window, tipscope-cli and tipscope-agent open such a line from a
// workspace ("recording" as the line's connection) and so find the same joints in the same
// samples; a plant can also replay a customer's recording through its whole chain.
//
// Each station port of the recording becomes a history under the identity the recording names
// (its device model, address and software, on the line "recording <absolute path>"), played as
// fast as the event loop allows, a stretch at a time; the recording's gaps stay gaps. The tool is
// the one the recording names for the port. A feeder's curve is not played: nothing is found in
// it. When every sample is played, a joint still in progress is ended as incomplete (nothing
// after it was recorded) and the session is Disconnected with what was played; a file that cannot
// be read leaves it Failed with the reader's reason. The recording's own event column (rests,
// sleep) is not replayed as events.
//
// The playback is a child of its session and ends with it.
#pragma once

#include "model/recording/recordingloader.h"
#include "model/session.h"

#include <QObject>
#include <memory>

namespace tipscope::model {

class RecordingPlayback : public QObject {
    Q_OBJECT
public:
    // The stretch of the recording played in one turn of the event loop: 6,000 samples a port
    // at 10 Hz, so a day of a 4-port station is played in seconds and the window stays
    // responsive meanwhile.
    static constexpr qint64 kStretchMs = 10 * 60 * 1000;

    // Starts playing session.settings().recordingPath into `session`.
    static RecordingPlayback *start(Session &session);

Q_SIGNALS:
    void finished();

private:
    struct Port {
        TelemetryKey key;                        // in the session's telemetry
        const TelemetryBuffer *source = nullptr; // in the recording's
    };

    explicit RecordingPlayback(Session &session);
    void onLoaded(const QString &error);
    void playSome();
    void end(Session::State state, const QString &text);

    Session &m_session;
    RecordingLoader m_loader;
    std::unique_ptr<ChartRecording> m_recording;
    std::vector<Port> m_ports;
    qint64 m_playedUntilMs = 0; // [first, m_playedUntilMs) of every port is played
    qint64 m_played = 0;        // samples, for the line's state once played
};

} // namespace tipscope::model
