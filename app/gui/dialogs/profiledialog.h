// ProfileDialog: a profile against a device: the difference (device vs file) first, then a dry
// run that lists the exact frames, or the apply itself with progress, cancel, and a report of
// what changed and what failed. Every setting is named with its tool and port.
//
// The table is always there: a refused profile (another family, broken limits) still shows what
// it would change, greyed. A profile of another family needs the "apply anyway" box, and ticking
// it compares again; the settings the device does not take are rows of their own, each with
// why, and counted in the summary. After an apply each row shows the value the device reported
// back and the outcome. A profile that would break the device's limits (MIT <= STx <= MAT) says
// so at the top, with each broken limit, and cannot be applied until a comparison finds it
// consistent.
#pragma once

#include "model/profiles/profileapplier.h"

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
    // A cell of the table as shown: column 0 setting, 1 device now, 2 profile, 3 note.
    [[nodiscard]] QString cellText(int row, int column) const;
    [[nodiscard]] bool isTableGreyed() const { return m_greyed; }
    void setForce(bool force);
    [[nodiscard]] bool isRunning() const { return m_applier != nullptr; }

private:
    void finished(const model::ApplyReport &report);
    void fillTable(const model::ApplyReport &report);
    void addRow(const QStringList &cells, bool greyed);
    void setBusy(bool busy);
    [[nodiscard]] QString summaryFor(const model::ApplyReport &report) const;

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
    bool m_greyed = false;    // the last run refused the profile: its table is what it would do
};

} // namespace tipscope::gui
