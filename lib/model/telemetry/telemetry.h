// Telemetry: the sample histories of every port and feeder, one TelemetryBuffer per key (a
// device's identity and its channel, TelemetryKey below), and a bounded-rate notice that samples
// arrived.
//
// Live buffers are tiered (TelemetryTiers): a day of a fleet fits in memory. setTiers() sets how
// for the buffers made after it; a buffer keeps the tiers it was made with.
//
// Writers (the port and feeder models) call ensureBuffer() once with the series they record,
// then append() each reading; every write goes through Telemetry so that it can tell views.
// Views read the buffers through buffer() and redraw on samplesAdded(), which is coalesced by a
// timer: it comes at most maxSignalsPerSecond() times a second (20 by default) and at most one
// interval after the first sample it reports, however fast samples arrive. Refused samples (out
// of order, wrong value count, unknown key) do not trigger it.
//
// Telemetry owns the buffers; a buffer lives as long as the Telemetry object, so references
// from ensureBuffer() and buffer() stay valid. Not thread-safe: use it from its own thread.
#pragma once

#include "model/telemetry/telemetrybuffer.h"

#include <QObject>
#include <QTimer>
#include <map>

namespace tipscope::model {

// What a history is kept under: the device's identity (DeviceIdentity::key(): line, address,
// model and software) and the channel, "cell-1|01|DME-2C|9996780|port2" or "...|feeder"
// (TelemetryRecorder::keyOf()), so one device's history never mixes with another's; a replay
// uses the recording's channel ids. Code that stores or passes a key names this type, so that
// keying histories differently changes this definition and what builds keys, not every reader.
using TelemetryKey = QString;

class Telemetry : public QObject {
    Q_OBJECT
public:
    static constexpr int kDefaultMaxSignalsPerSecond = 20;

    explicit Telemetry(QObject *parent = nullptr);

    // The buffer of `key`, created with `series` and tiers() if it does not exist yet. An
    // existing buffer keeps its series and tiers (a different request is logged).
    const TelemetryBuffer &ensureBuffer(const TelemetryKey &key, const QStringList &series);
    // As above, a single tier of `capacity` samples.
    const TelemetryBuffer &ensureBuffer(const TelemetryKey &key, const QStringList &series,
                                        int capacity);
    // For the buffers made from now on.
    void setTiers(const TelemetryTiers &tiers) { m_tiers = tiers; }
    [[nodiscard]] const TelemetryTiers &tiers() const { return m_tiers; }
    // Installs a buffer filled elsewhere (a replay reads its file on another thread into plain
    // buffers); false, and the buffer dropped, when `key` already has one.
    bool adoptBuffer(const TelemetryKey &key, TelemetryBuffer &&buffer);
    // nullptr when no buffer of that key exists.
    [[nodiscard]] const TelemetryBuffer *buffer(const TelemetryKey &key) const;
    // Sorted.
    [[nodiscard]] QList<TelemetryKey> keys() const;

    AppendResult append(const TelemetryKey &key, qint64 timeMs, const qint32 *values,
                        qsizetype count);
    AppendResult append(const TelemetryKey &key, qint64 timeMs,
                        std::initializer_list<qint32> values) {
        return append(key, timeMs, values.begin(), qsizetype(values.size()));
    }
    AppendResult append(const TelemetryKey &key, qint64 timeMs, const QList<qint32> &values) {
        return append(key, timeMs, values.constData(), values.size());
    }

    // The history of `key` has a gap from `timeMs` until its next sample
    // (TelemetryBuffer::markGap); views are told as for samples. False for an unknown key.
    bool markGap(const TelemetryKey &key, qint64 timeMs, TelemetryGap::Cause cause);

    // samplesAdded() now for what was appended since the last one, rather than at the timer: a
    // playback appends a recording's hours in a few turns of the event loop, and its readers
    // must see each stretch before the full-rate tier folds it.
    void notifyNow();

    // Clamped to 1..1000.
    void setMaxSignalsPerSecond(int rate);
    [[nodiscard]] int maxSignalsPerSecond() const { return m_maxSignalsPerSecond; }

Q_SIGNALS:
    // `keys` (sorted) are the buffers that accepted samples since the previous emission.
    void samplesAdded(const QList<TelemetryKey> &keys);

private:
    struct Entry {
        explicit Entry(TelemetryBuffer b)
            : buffer(std::move(b)) {}
        TelemetryBuffer buffer;
        bool changed = false;
    };

    void emitSamplesAdded();
    const TelemetryBuffer &ensureBuffer(const TelemetryKey &key, const QStringList &series,
                                        const TelemetryTiers &tiers);

    // std::map: nodes never move, so handed-out buffer references stay valid.
    std::map<TelemetryKey, Entry> m_entries;
    QTimer m_coalesceTimer;
    int m_maxSignalsPerSecond = kDefaultMaxSignalsPerSecond;
    TelemetryTiers m_tiers;
};

} // namespace tipscope::model
