// WriteStream: the soak's stream of user writes with read-back, the ledger that proves none was
// lost or reported twice, and the shadow of what the device may hold.
//
// It keeps up to `inFlight` writes going on a station's writable parameters, each through
// Parameter::setEdit() + apply() exactly as the settings editors do, with a new valid value each
// time (never the one the device is believed to hold, nor the one shown, which would leave no edit
// to write). Every write enters the ledger under the id apply() returns and leaves it with the
// writeFinished() carrying that id: verified, or failed with a reason (classified for the
// figures). A write still open when the stream is drained is lost; a finish of an id already
// finished is a write reported twice; a finish of an id never issued is unsolicited.
//
// The shadow: each code keeps its last verified value and the values of the writes that failed
// since (a failed write may or may not have reached the device; its answer may be what was lost),
// so the device may hold any of them, and nothing else. After every write ends, before the next
// write of that code, the device itself is asked (DeviceProbe, past the line and its faults):
// after a verified write it must hold exactly that value, after a failed one a value the shadow
// allows. judge() makes the same comparison for the final check.
#pragma once

#include <QElapsedTimer>
#include <QMap>
#include <QObject>
#include <QPointer>
#include <QRandomGenerator>
#include <QSet>
#include <QStringList>
#include <functional>
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
    qint64 refused = 0;          // setEdit() refused the value: nothing was sent (must stay 0)
    qint64 notStarted = 0;       // apply() started nothing although an edit was set (must stay 0)
    qint64 unsolicited = 0;      // a finish with an id never issued (must stay 0)
    qint64 reportedTwice = 0;    // a second finish of one id (must stay 0)
    qint64 deviceChecks = 0;     // the device looked at after a write ended
    qint64 deviceMismatches = 0; // ... holding what the shadow does not allow (must stay 0)
    QMap<QString, qint64> failedBy; // reason class -> count
    QStringList examples;           // the first few failure reasons, verbatim
    QStringList mismatches;         // the first few device mismatches
    QList<double> verifiedMs;       // apply() to writeFinished(true)
};

class WriteStream : public QObject {
    Q_OBJECT
public:
    enum class Verdict { Expected, FromFailedWrite, Unexpected };
    // Asks the device what it holds for `code`, past the line; `done` gets nullopt when it cannot.
    using DeviceProbe = std::function<void(const QByteArray &code,
                                           const std::function<void(std::optional<qint64>)> &done)>;

    WriteStream(model::StationModel &station, const QList<QByteArray> &codes, quint32 seed,
                DeviceProbe probe, QObject *parent = nullptr);

    // What the device held before the first write.
    void setInitial(const QByteArray &code, qint64 value);
    void start(int inFlight);
    void stopIssuing() { m_issuing = false; }
    // Writes issued and not finished: lost, once the stream has been drained.
    [[nodiscard]] int outstanding() const { return int(m_open.size()); }
    // Writes and device checks still under way.
    [[nodiscard]] int busy() const { return m_inFlight; }
    [[nodiscard]] const WriteTally &tally() const { return m_tally; }
    [[nodiscard]] QList<QByteArray> codes() const { return m_tracks.keys(); }
    // How `deviceValue`, read from the device at the end, compares with the shadow of `code`.
    [[nodiscard]] Verdict judge(const QByteArray &code, qint64 deviceValue) const;
    [[nodiscard]] QString expectationText(const QByteArray &code) const;
    // The reason reported for the failed write of `value` to `code` (FromFailedWrite verdicts).
    [[nodiscard]] QString failureReason(const QByteArray &code, qint64 value) const;

private:
    struct Track {
        QPointer<model::Parameter> parameter;
        std::optional<qint64> lastVerified;
        QList<QPair<qint64, QString>> failedSince; // value, reason
        bool busy = false;                         // a write or its device check under way
    };
    struct OpenWrite {
        QByteArray code;
        qint64 value = 0;
        qint64 startedMs = 0;
    };

    void issueNext();
    void scheduleNext();
    void onFinished(bool ok, const QString &reason, quint64 id);
    void checkDevice(const QByteArray &code, std::optional<qint64> exactly);
    void checked(const QByteArray &code, std::optional<qint64> exactly, std::optional<qint64> held);
    [[nodiscard]] qint64 pickValue(const Track &t);
    [[nodiscard]] static QString classify(const QString &reason);

    QMap<QByteArray, Track> m_tracks;
    QMap<quint64, OpenWrite> m_open;
    QSet<quint64> m_finished;
    DeviceProbe m_probe;
    QRandomGenerator m_rng;
    QElapsedTimer m_clock;
    int m_inFlightTarget = 0;
    int m_inFlight = 0;
    bool m_issuing = false;
    WriteTally m_tally;
};

} // namespace tipscope::bench
