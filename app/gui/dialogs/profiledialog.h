// ProfileDialog: a profile against a device: the difference (device vs file) first, then a dry
// run that lists the exact frames, or the apply itself with progress, cancel, and a report of
// what changed and what failed. A profile of another family needs the "apply anyway" box.
// A profile that would break the device's limits (MIT <= STx <= MAT) says so at the top, with
// each broken limit, and cannot be applied until a comparison finds it consistent.
#pragma once

#include "model/profileapplier.h"

#include <QDialog>
#include <QPointer>

class QCheckBox;
class QLabel;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace tipscope::gui {

class ProfileDialog : public QDialog {
    Q_OBJECT
public:
    ProfileDialog(model::DeviceModel &device, const model::Profile &profile,
                  QWidget *parent = nullptr);

    void run(model::ProfileApplier::Mode mode);
    [[nodiscard]] QString reportText() const;
    [[nodiscard]] QString summaryText() const;
    [[nodiscard]] bool canApply() const;
    [[nodiscard]] int differenceRows() const;
    [[nodiscard]] bool isRunning() const { return m_applier != nullptr; }

private:
    void finished(const model::ApplyReport &report);
    void setBusy(bool busy);

    model::DeviceModel &m_device;
    model::Profile m_profile;
    QLabel *m_summary;
    QTableWidget *m_table;
    QPlainTextEdit *m_report;
    QProgressBar *m_progress;
    QCheckBox *m_force;
    QPushButton *m_compare;
    QPushButton *m_dryRun;
    QPushButton *m_apply;
    QPushButton *m_cancel;
    QPointer<model::ProfileApplier> m_applier;
    bool m_conflicts = false; // the last run found limits the profile would break
};

} // namespace tipscope::gui
