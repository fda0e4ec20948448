// ProfileApplier: reads a device's current values, compares them with a profile, and (unless
// asked only for the difference or a dry run) writes what differs, one value at a time, each
// proved by its read-back before the next is sent, so limits that depend on each other (MIT,
// MAT, then the selected temperatures) are always checked against the device's real state.
// The report says what changed, what was already right, what failed and why; a dry run lists
// the exact frames that would be sent. A profile of another family is refused unless forced,
// and then only the settings the device has are applied. Cancel stops before the next write.
#pragma once

#include "profile.h"

#include <QObject>
#include <QPointer>

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

struct ApplyReport {
    bool refused = false; // nothing was written; `reason` says why
    QString reason;
    bool dryRun = false;
    bool diffOnly = false;
    bool cancelled = false;
    QList<ProfileDifference> differences;
    QList<ApplyItem> written; // one per difference attempted
    QStringList frames;       // dry run: "02 30 ... (00→01 W ST1 00350)"
    QStringList skipped;      // forced profiles: entries the device does not have
    int unchanged = 0;
    [[nodiscard]] int failedCount() const;
    [[nodiscard]] bool ok() const { return !refused && !cancelled && failedCount() == 0; }
    [[nodiscard]] QString text() const; // for people, one line per item
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
    void readAll();
    void compare();
    void writeNext();
    void finish();
    [[nodiscard]] QList<QByteArray> writeOrder() const;

    DeviceModel &m_device;
    Profile m_profile;
    Mode m_mode;
    bool m_force;
    bool m_cancelled = false;
    int m_pendingReads = 0;
    QList<QByteArray> m_toWrite;
    int m_next = 0;
    ApplyReport m_report;
};

} // namespace tipscope::model
