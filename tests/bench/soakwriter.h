// WriteStream: the soak's stream of user writes with read-back, and the ledger that proves none
// was lost.
//
// It keeps up to `inFlight` writes going on a station's writable parameters, each through
// Parameter::setEdit() + apply() exactly as the settings editors do, with a new valid value each
// time (never the one the device is believed to hold, so every write changes something). Every
// write enters the ledger when issued and leaves it with the parameter's writeFinished(ok,
// reason): verified, or failed with a reason (classified for the figures). A write still open
// when the stream is drained is lost; a writeFinished nobody was waiting for is counted too, as
// it would mean a write reported twice.
//
// For the final comparison with the device, each code keeps its last verified value and the
// values of the writes that failed since: a failed write may or may not have reached the device
// (its answer may be what was lost), so the device may hold any of them, and nothing else.
#pragma once

#include <QElapsedTimer>
#include <QMap>
#include <QObject>
#include <QPointer>
#include <QRandomGenerator>
#include <QStringList>
#include <optional>

namespace tipscope::model {
class Parameter;
class StationModel;
} // namespace tipscope::model

namespace tipscope::bench {

struct WriteTally {
    qint64 issued = 0;
    qint64 verified = 0;
    qint64 failed = 0;
    qint64 refused = 0;             // setEdit() refused the value: nothing was sent (must stay 0)
    qint64 unsolicited = 0;         // writeFinished without a write of ours open (must stay 0)
    QMap<QString, qint64> failedBy; // reason class -> count
    QStringList examples;           // the first few failure reasons, verbatim
    QList<double> verifiedMs;       // apply() to writeFinished(true)
};

class WriteStream : public QObject {
    Q_OBJECT
public:
    enum class Verdict { Expected, FromFailedWrite, Unexpected };

    WriteStream(model::StationModel &station, const QList<QByteArray> &codes, quint32 seed,
                QObject *parent = nullptr);

    // What the device held before the first write (read by the caller).
    void setInitial(const QByteArray &code, qint64 value);
    void start(int inFlight);
    void stopIssuing() { m_issuing = false; }
    [[nodiscard]] int outstanding() const { return m_inFlight; }
    [[nodiscard]] const WriteTally &tally() const { return m_tally; }
    [[nodiscard]] QList<QByteArray> codes() const { return m_tracks.keys(); }
    // How `deviceValue`, read from the device at the end, compares with the ledger for `code`.
    [[nodiscard]] Verdict judge(const QByteArray &code, qint64 deviceValue) const;
    [[nodiscard]] QString expectationText(const QByteArray &code) const;
    // The reason reported for the failed write of `value` to `code` (FromFailedWrite verdicts).
    [[nodiscard]] QString failureReason(const QByteArray &code, qint64 value) const;

private:
    struct Track {
        QPointer<model::Parameter> parameter;
        std::optional<qint64> lastVerified;
        QList<QPair<qint64, QString>> failedSince; // value, reason
        bool busy = false;
        qint64 pendingValue = 0;
        qint64 startedMs = 0;
    };

    void issueNext();
    void scheduleNext();
    void onFinished(const QByteArray &code, bool ok, const QString &reason);
    [[nodiscard]] qint64 pickValue(const Track &t);
    [[nodiscard]] static QString classify(const QString &reason);

    QMap<QByteArray, Track> m_tracks;
    QRandomGenerator m_rng;
    QElapsedTimer m_clock;
    int m_inFlightTarget = 0;
    int m_inFlight = 0;
    bool m_issuing = false;
    WriteTally m_tally;
};

} // namespace tipscope::bench
