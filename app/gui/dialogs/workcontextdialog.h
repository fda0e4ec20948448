// WorkContextDialog: the work order, board serial and operator stamped on every joint and event
// from now on, written to the context file every TipScope program follows. A file that cannot be
// written is said in the dialog, which stays open with what was typed.
#pragma once

#include "journal/workcontextfile.h"

#include <QDialog>

class QLabel;
class QLineEdit;

namespace tipscope::gui {

class WorkContextDialog : public QDialog {
    Q_OBJECT
public:
    WorkContextDialog(journal::WorkContextFollower &context, QWidget *parent = nullptr);

    void accept() override;

private:
    journal::WorkContextFollower &m_context;
    QLineEdit *m_workOrder;
    QLineEdit *m_serial;
    QLineEdit *m_operator;
    QLabel *m_problem;
};

} // namespace tipscope::gui
