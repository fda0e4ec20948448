// The work context as JSON, the one shape every file that holds one uses (the context file beside
// the journal, each line of a workspace):
//     {"work_order": "WO-1234", "board_serial": "SN-0042", "operator": "ana"}
// A missing field is empty; a field that is not text is refused with its name. Text is trimmed.
// Each field is stamped on every joint, event and MQTT payload until it changes, so its length is
// bounded and a control character (an ANSI escape that would rewrite a terminal) is refused, in
// a file as in a command.
#pragma once

#include "model/context/workcontext.h"

#include "base/outcome.h"

#include <QJsonObject>

namespace tipscope::model {

inline constexpr int kMaxWorkContextChars = 64;

// Empty, or why `context` cannot be kept: the field, and its length or the character refused.
[[nodiscard]] QString workContextProblem(const WorkContext &context);

[[nodiscard]] QJsonObject workContextToJson(const WorkContext &context);
[[nodiscard]] base::Outcome<WorkContext> workContextFromJson(const QJsonObject &json);

} // namespace tipscope::model
