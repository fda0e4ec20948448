// The work context as JSON, the one shape every file that holds one uses (the context file beside
// the journal, each line of a workspace):
//     {"work_order": "WO-1234", "board_serial": "SN-0042", "operator": "ana"}
// A missing field is empty; a field that is not text is refused with its name. Text is trimmed.
#pragma once

#include "model/workcontext.h"

#include "protocol/outcome.h"

#include <QJsonObject>

namespace tipscope::model {

[[nodiscard]] QJsonObject workContextToJson(const WorkContext &context);
[[nodiscard]] protocol::Outcome<WorkContext> workContextFromJson(const QJsonObject &json);

} // namespace tipscope::model
