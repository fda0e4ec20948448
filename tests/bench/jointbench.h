// runJointBench: how well the joint detector finds and measures joints, for `tipscope-bench
// joints`. A synthetic port works at 350 °C and makes --joints N joints (default 500, seeded by
// --seed S): dips of 15-100 K that fall over 150-500 ms and recover exponentially with a time
// constant of 0.3-2 s, interleaved with what must not count (a heat-up from cold every 40
// joints, a sleep and wake every 25, ±--noise K (default 0.5, the station's rounding) on every
// reading before it is rounded to whole degrees). The readings come at a
// poll period with ±30 % jitter, as a loaded line delivers them. For each period it prints:
//   joints.<period>ms.precision        detected joints that match a true one (start within 1 s)
//   joints.<period>ms.recall           true joints detected
//   joints.<period>ms.recovery_error_p50_ms, ..._p95_ms
//                                      |measured − true recovery time| over the matched joints
// Periods: 100 ms (a port polled alone at full rate) and 300 ms (four busy ports at 19200 baud),
// side by side. With --wire it measures through the wire instead (jointwirebench.h). A benchmark:
// it asserts nothing.
#pragma once

#include <QStringList>

namespace tipscope::bench {

int runJointBench(const QStringList &args);

} // namespace tipscope::bench
