// CSV cells as TipScope writes and reads them (RFC 4180, one record per line).
//
// quoted() turns any text into one cell a spreadsheet reads back unchanged: a cell holding a
// comma, a double quote or spaces at either end is put in double quotes with its quotes doubled.
// Line breaks become spaces, so every record stays one line and a line-based reader (replay)
// needs no state across lines. splitLine() is the inverse for one line of UTF-8: the cells with
// their quotes removed, as views into the line where they need no unquoting (most cells of a
// recording), so reading a row allocates next to nothing.
#pragma once

#include <QByteArrayView>
#include <QList>
#include <QString>
#include <QVarLengthArray>

namespace tipscope::base::csv {

[[nodiscard]] QString quoted(const QString &cell);

// The cells of one line. A cell is a view into the line, or into a copy kept here when it had
// quotes to remove: valid while the line lives and until the next splitLine() into this object.
class Cells {
public:
    [[nodiscard]] qsizetype size() const { return m_cells.size(); }
    [[nodiscard]] QByteArrayView at(qsizetype i) const { return m_cells.at(i); }
    [[nodiscard]] QString text(qsizetype i) const { return QString::fromUtf8(m_cells.at(i)); }

private:
    friend bool splitLine(QByteArrayView line, Cells &cells);
    QVarLengthArray<QByteArrayView, 64> m_cells;
    QList<QByteArray> m_copies;
};

// False when a quoted cell is not closed.
[[nodiscard]] bool splitLine(QByteArrayView line, Cells &cells);

} // namespace tipscope::base::csv
