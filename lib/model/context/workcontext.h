// WorkContext: what the line is working on, stamped on every joint and event until it changes.
// Any field may be empty (nobody said). Compared field by field.
#pragma once

#include <QString>

namespace tipscope::model {

struct WorkContext {
    QString workOrder;
    QString boardSerial;
    QString operatorName;

    [[nodiscard]] bool isEmpty() const {
        return workOrder.isEmpty() && boardSerial.isEmpty() && operatorName.isEmpty();
    }
    friend bool operator==(const WorkContext &a, const WorkContext &b) {
        return a.workOrder == b.workOrder && a.boardSerial == b.boardSerial &&
               a.operatorName == b.operatorName;
    }
    friend bool operator!=(const WorkContext &a, const WorkContext &b) { return !(a == b); }
};

} // namespace tipscope::model
