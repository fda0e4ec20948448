// CSV cells as TipScope writes and reads them (RFC 4180, one record per line).
//
// quoted() turns any text into one cell a spreadsheet reads back unchanged: a cell holding a
// comma, a double quote or spaces at either end is put in double quotes with its quotes doubled.
// Line breaks become spaces, so every record stays one line and a line-based reader (replay)
// needs no state across lines. splitLine() is the inverse for one line: the cells with their
// quotes removed.
#pragma once

#include <QStringList>

namespace tipscope::model::csv {

[[nodiscard]] QString quoted(const QString &cell);
// `cells` is reused between lines to spare allocations; false when a quote is left open.
[[nodiscard]] bool splitLine(const QString &line, QStringList &cells);

} // namespace tipscope::model::csv
