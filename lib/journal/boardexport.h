// A board record (boardrecord.h) as other programs and people read it, beside the joint export it
// builds on (jointexport.h): the same joint fields, the same event fields, times in UTC.
//
// JSON, one object:
//     board_serial, result ("pass", "fail", "not judged", "no joints"), first, last,
//     work_orders, operators, verdicts {"ok": n, "slow recovery": n, "too deep": n,
//     "incomplete": n}, joints [jointJson], events [eventJson], tips [{device, model, address,
//     port, tool, joints, setpoints_c, since (null: no tool change in the journal),
//     history_joints, wear_window, baseline_recovery_ms, recent_recovery_ms (null: not enough
//     joints yet)}], profiles_before [eventJson], not_in_journal {limits, settings, curves: why},
//     software (the TipScope that wrote the record)
// CSV: the board's joints only, exactly as `tipscope-cli joints --csv` writes them (one header,
// one row a joint), so a spreadsheet made for one reads the other.
// Text: a few lines for people, with the same fixed English words in every language as
// `tipscope-cli joints` prints (the PDF, boardpdf.h, is the translated form).
#pragma once

#include "boardrecord.h"

#include <QJsonObject>

namespace tipscope::journal {

[[nodiscard]] QJsonObject boardJson(const BoardRecord &record, const QString &software);
[[nodiscard]] QString boardCsv(const BoardRecord &record);
[[nodiscard]] QString boardText(const BoardRecord &record, const QString &software);

// "+6 %": how much slower the recent median is than the baseline; empty without both.
[[nodiscard]] QString wearShareText(const BoardTip &tip);

} // namespace tipscope::journal
