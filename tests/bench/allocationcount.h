// How many times this process called operator new since it started: the C++ allocations of our
// code and of Qt's objects, events and slot objects (QString's and QByteArray's buffers come from
// malloc() directly and are not counted). Counted by replacing the global operator new in the
// benchmark's executable, which every library in the process then uses.
#pragma once

#include <QtGlobal>

namespace tipscope::bench {

[[nodiscard]] qint64 allocationsSoFar();

} // namespace tipscope::bench
