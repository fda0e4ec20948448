// ProfileApplier: reads a device's current values, compares them with a profile, and (unless
// asked only for the difference or a dry run) writes what differs, one value at a time, each
// proved by its read-back before the next is sent.
//
// Before the first write the whole profile is checked against itself and the device's current
// values (profilelimits.h: MIT <= STx <= MAT on every port): a profile that would break a limit
// is refused whole, nothing written, and the report's `conflicts` say why; a diff lists them
// too. A profile that passes is written in an order that keeps every limit after each write,
// and each write is still validated against the device's state when it is sent.
// The report says what changed, what was already right, what failed and why; a dry run lists
// the exact frames that would be sent. A profile of another family is refused unless forced,
// and then only the settings the device has are applied; the others are skipped, each with its
// name and why. A refused profile is still compared (the settings both have), so people see
// what it would have changed; if the device has none of its settings, it is refused at once.
// Cancel stops before the next write. An apply that ran is one event in the device's event log
// (kind ProfileApply), with the profile's SHA-256 and every change in its details, for the
// journal.
#pragma once

#include "profile.h"

#include <QObject>
#include <QPointer>
#include <QSet>

namespace tipscope::model {

class DeviceModel;

struct ApplyItem {
    QByteArray code;
    QString name;
    QString before;
    QString after;
    bool ok = false;
    QString reason;
};

// A setting of a profile that the device does not take: "HD1", "Tip adjust, port 1", and why.
struct SkippedSetting {
    QByteArray code;
    QString name;
    QString reason;
};

struct ApplyReport {
    bool refused = false; // nothing was written; `reason` says why
    QString reason;
    bool dryRun = false;
    bool diffOnly = false;
    bool cancelled = false;
    QList<ProfileDifference> differences;
    QList<ApplyItem> written;      // one per difference attempted
    QStringList frames;            // dry run: "02 30 ... (00→01 W ST1 00350)"
    QList<SkippedSetting> skipped; // another family's profile: entries the device does not take
    QStringList conflicts;         // limits the profile would break (see profilelimits.h)
    int unchanged = 0;
    [[nodiscard]] int failedCount() const;
    [[nodiscard]] bool ok() const {
        return !refused && !cancelled && conflicts.isEmpty() && failedCount() == 0;
    }
    [[nodiscard]] QString text() const; // for people, one line per item
    [[nodiscard]] QStringList skippedCodes() const;
    // Why the conflicts refuse the profile, the conflicts one a line; empty without conflicts.
    [[nodiscard]] QString conflictReason() const;
};

class ProfileApplier : public QObject {
    Q_OBJECT
public:
    enum class Mode { Diff, DryRun, Apply };

    ProfileApplier(DeviceModel &device, const Profile &profile, Mode mode, bool force = false,
                   QObject *parent = nullptr);
    void start();
    void cancel() { m_cancelled = true; }
    [[nodiscard]] const ApplyReport &report() const { return m_report; }

Q_SIGNALS:
    void progress(int done, int total, const QString &what);
    void finished(const tipscope::model::ApplyReport &report);

private:
    void keepSharedSettings();
    [[nodiscard]] QString skippedName(const QByteArray &code) const;
    void refuse(const QString &reason);
    void readAll();
    void compare();
    void listFrames();
    void writeNext();
    void finish();
    void logApply();
    [[nodiscard]] QByteArray profileValue(const QByteArray &code) const;

    DeviceModel &m_device;
    Profile m_profile;
    Mode m_mode;
    bool m_force;
    bool m_cancelled = false;
    QString m_refuseAfterCompare; // another family's profile, not forced: compared, never written
    int m_pendingReads = 0;
    QSet<QByteArray> m_unread; // codes whose read for this run failed
    QList<QByteArray> m_toWrite;
    int m_next = 0;
    ApplyReport m_report;
};

} // namespace tipscope::model
