// A stored joint as other programs read it: one JSON object (the CLI's --json, and the payload
// MQTT subscribers get) and one CSV row. Field names carry their units; times are UTC in ISO 8601
// with milliseconds. The same names in both forms:
//     ts, end, id, device, line, address, model, software, port, tool, setpoint_c, lowest_c,
//     dip_k, recovery_ms, duration_ms, power_peak_pct, power_integral_pct_s, verdict,
//     work_order, board_serial, operator, start_uncertainty_ms, dip_uncertainty_k,
//     recovery_uncertainty_ms, recovery_bounded, band_k, max_recovery_ms, max_dip_k
// A joint that never recovered has an empty recovery_ms (null in JSON). lowest_c and dip_k are
// to a tenth; each *_uncertainty is the ± within which the true value lies, and recovery_bounded
// (true or false) says the readings could only bound the recovery (see model/joints/jointrecord.h).
// band_k, max_recovery_ms and max_dip_k are the limits the verdict was judged by, empty (null) for
// a joint journaled before the journal kept them.
//
// A stored event as one JSON object (the MQTT event payload, docs/mqtt.md, and the board record's
// events): ts, id, kind, severity, device, address, model, port, text, details, work_order,
// board_serial, operator.
#pragma once

#include "journaltypes.h"

#include <QJsonObject>

namespace tipscope::journal {

[[nodiscard]] QJsonObject jointJson(const StoredJoint &joint);
[[nodiscard]] QString jointCsvHeader();
[[nodiscard]] QString jointCsvRow(const StoredJoint &joint);
// One line for people, the same words in every language (the CLI's `joints`, the board record):
// "2026-12-02T09:41:03.120Z  DME-2C 01 P1 C245  350 °C  lowest 318.0 °C  dip 32.0 K  recovery
// 1.84 s  ok  WO-7"
[[nodiscard]] QString jointTextLine(const StoredJoint &joint);
[[nodiscard]] QJsonObject eventJson(const StoredEvent &event);
// "01", or "--" for a device without an address.
[[nodiscard]] QString addressText(const model::DeviceIdentity &device);
// "2026-12-02T09:41:03.120Z"
[[nodiscard]] QString utcText(qint64 msSinceEpoch);

} // namespace tipscope::journal
