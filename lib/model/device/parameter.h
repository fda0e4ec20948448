// Parameter: one value of a device, built from the catalog, never hand-written per command.
//
// It holds the value as last read, a pending edit, and a state (Unknown, Reading, InSync, Edited,
// Writing, Failed with the reason). There are two write paths, as in QGroundControl's Fact:
// setEdit() + apply() is a person's edit, validated before anything reaches the wire, written,
// and proved by a read-back (WriteProof, only then InSync); deviceReported() is the device's own
// value from a poll and only updates what is shown.
// Limits that depend on the device (the selected temperature between MIT and MAT) follow the
// current values of the limiting parameters.
#pragma once

#include "displayunits.h"

#include "link/requestqueue.h"

#include <QDateTime>
#include <QObject>
#include <QPointer>

namespace tipscope::model {

class DeviceModel;

class Parameter : public QObject {
    Q_OBJECT
public:
    enum class State { Unknown, Reading, InSync, Edited, Writing, Failed };
    Q_ENUM(State)

    // `read` and `write` are the catalog's views of this code in each direction (either may be
    // null, not both); they must outlive the parameter (the builtin catalog does).
    Parameter(DeviceModel &device, std::optional<protocol::ResolvedCommand> read,
              std::optional<protocol::ResolvedCommand> write, QObject *parent = nullptr);

    [[nodiscard]] QByteArray code() const { return spec().code; }
    [[nodiscard]] const protocol::ResolvedCommand &spec() const;
    [[nodiscard]] const protocol::CommandSpec &meta() const { return *spec().spec; }
    // The catalog's name and description in the user interface language, for people; meta()
    // has them in English for data (CSV columns, the support report's JSON).
    [[nodiscard]] QString label() const { return protocol::catalogText(meta().name); }
    [[nodiscard]] QString description() const { return protocol::catalogText(meta().description); }
    [[nodiscard]] bool isReadable() const { return m_read.has_value(); }
    [[nodiscard]] bool isWritable() const { return m_write.has_value(); }
    [[nodiscard]] DeviceModel &device() const { return m_device; }

    [[nodiscard]] std::optional<protocol::Value> value() const { return m_value; }
    [[nodiscard]] std::optional<qint64> number() const;
    [[nodiscard]] QByteArray rawValue() const { return m_raw; }
    [[nodiscard]] std::optional<qint64> edit() const { return m_edit; }
    [[nodiscard]] State state() const { return m_state; }
    [[nodiscard]] QString failure() const { return m_failure; }
    // A value read and the line still up: what the device holds now, as far as polling can
    // tell. Otherwise the value (if any) is only what was read at lastUpdate().
    [[nodiscard]] bool isCurrent() const;
    // Local time; invalid before the first reading.
    [[nodiscard]] QDateTime lastUpdate() const {
        return m_lastUpdateMs < 0 ? QDateTime() : QDateTime::fromMSecsSinceEpoch(m_lastUpdateMs);
    }
    [[nodiscard]] double achievedRateHz() const { return m_rateHz; }
    // The device refused the last read (a NAK: a station without this reading, or one that cannot
    // give it now): why, in words; empty once a read succeeds. The value, if any, is from before.
    [[nodiscard]] QString refusal() const { return m_refusal; }
    [[nodiscard]] bool isRefused() const { return !m_refusal.isEmpty(); }
    // The last read got no usable answer (refused, unanswered, unreadable).
    [[nodiscard]] bool lastReadFailed() const { return m_lastReadFailed; }

    // Effective limits in wire units, tightened by the limiting parameters' current values.
    [[nodiscard]] qint64 minimum() const;
    [[nodiscard]] qint64 maximum() const;
    void setLimitParameters(Parameter *lower, Parameter *upper);
    // Empty when `wire` may be written now; otherwise what is allowed, in display units.
    [[nodiscard]] QString validate(qint64 wire) const;
    [[nodiscard]] QString allowedText() const;

    [[nodiscard]] QString displayText() const; // the value as people read it
    QString setEdit(qint64 wire);              // error text, or empty when accepted
    QString setEditText(const QString &text);  // the same from what a person typed
    void revert();

    // Reads the value now. The returned reply is owned by the parameter.
    link::Reply *refresh(link::Priority priority = link::Priority::UserRead);
    // Writes the pending edit and reads it back. Returns the write's id, which the one
    // writeFinished() that tells its outcome carries (always after apply() has returned); 0 when
    // nothing was started: no edit is pending (setEdit() of the value the device holds leaves
    // none) or a write of this parameter is still running.
    quint64 apply();
    // The value the device reported (a poll or a read-back); never written back. `ageMs`: how
    // long before now the device took it (link::Reply::answerAgeUs).
    void deviceReported(const QByteArray &data, double ageMs = 0);
    // The age the last reported value had when it was reported: an updated() handler that
    // stamps a sample stamps it at now − this, the instant the value describes.
    [[nodiscard]] double reportedAgeMs() const { return m_reportedAgeMs; }
    // For volatile values (W-STx, the feeder's mode, speed, length): false after TipScope wrote
    // a new value until W-NVS saved it. What the device held before TipScope came cannot be known.
    [[nodiscard]] bool isSavedToMemory() const;
    void markSaved();
    // The line is back (DeviceModel::setLineUp): a write that failed because the line was down
    // or lost is no longer an error; its edit stays, to apply again, and the value is read anew.
    void lineRestored();

Q_SIGNALS:
    void valueChanged();
    void updated();        // every reading, changed or not (telemetry samples)
    void readFailed();     // a reading got no usable answer (a gap in the telemetry)
    void refusalChanged(); // isRefused() turned on or off
    void stateChanged();
    void editChanged();
    void writeFinished(bool ok, const QString &reason, quint64 writeId);

private:
    void setState(State s, const QString &failure = {});
    // `again`: the first read-back differed and this is the one more read that decides.
    void readBack(const QByteArray &written, quint64 id);
    void succeed(quint64 id);
    // `byLine`: the line was down, so the failure ends when it is back (Session clears it).
    void fail(const QString &reason, quint64 id, bool byLine = false);

    DeviceModel &m_device;
    std::optional<protocol::ResolvedCommand> m_read;
    std::optional<protocol::ResolvedCommand> m_write;
    std::optional<protocol::Value> m_value;
    double m_reportedAgeMs = 0;
    QByteArray m_raw;
    std::optional<qint64> m_edit;
    quint64 m_runningWrite = 0; // the id of the write under way, 0 when none
    bool m_unsavedWrite = false;
    State m_state = State::Unknown;
    QString m_failure;
    bool m_failedByLine = false; // the failure is the line's, not the device's or the value's
    QString m_refusal;
    bool m_lastReadFailed = false;
    qint64 m_lastUpdateMs = -1;
    double m_rateHz = 0;
    QPointer<Parameter> m_lower, m_upper;
};

} // namespace tipscope::model
