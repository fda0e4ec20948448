// JointLimitsDialog: the limits every joint is judged by: the defaults (longest recovery, deepest
// dip, tip wear share) and rules for a port, a tool or both, the most specific of which wins.
// What is typed is checked as it is typed; a rule that cannot be used is named under the table
// and OK waits until it is fixed. OK saves the shared limits file (tipscope-cli limits reads the
// same), or says in the dialog why it could not.
#pragma once

#include "model/joints/jointlimitrules.h"

#include <QDialog>

class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTableWidget;

namespace tipscope::gui {

class JointLimitsDialog : public QDialog {
    Q_OBJECT
public:
    JointLimitsDialog(const model::JointLimitRules &rules, const QString &path,
                      QWidget *parent = nullptr);

    // The limits as the dialog holds them, or the first thing wrong with them.
    [[nodiscard]] base::Outcome<model::JointLimitRules> limits() const;
    void accept() override;
    void addRule(const model::JointLimitRule &rule);

private:
    void check();

    QString m_path;
    QDoubleSpinBox *m_recovery;
    QSpinBox *m_dip;
    QSpinBox *m_wear;
    QTableWidget *m_rules;
    QLabel *m_problem;
    QPushButton *m_ok;
};

} // namespace tipscope::gui
