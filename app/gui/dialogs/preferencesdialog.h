// PreferencesDialog: temperature unit, poll rates, answer timeout and retries, how much chart
// history is kept (for devices found from then on), language (on the next start), and how long
// the journal keeps records. The theme follows the desktop's; nothing to choose. The retention is
// not one of this program's settings: it lives in the journal file, shared by every program that
// keeps it, so it comes and goes beside AppSettings.
#pragma once

#include "model/appsettings.h"

#include <QDialog>

class QComboBox;
class QSpinBox;

namespace tipscope::gui {

class PreferencesDialog : public QDialog {
    Q_OBJECT
public:
    PreferencesDialog(const model::AppSettings &settings, int journalRetentionDays,
                      QWidget *parent = nullptr);
    [[nodiscard]] model::AppSettings result() const;
    [[nodiscard]] int journalRetentionDays() const;

private:
    model::AppSettings m_base;
    QComboBox *m_unit;
    QSpinBox *m_live;
    QSpinBox *m_status;
    QSpinBox *m_counters;
    QSpinBox *m_turnaround;
    QSpinBox *m_retries;
    QSpinBox *m_fullRate;
    QSpinBox *m_history;
    QComboBox *m_language;
    QSpinBox *m_retention;
};

} // namespace tipscope::gui
