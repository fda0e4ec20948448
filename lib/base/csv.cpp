#include "base/csv.h"

#include <cstring>

namespace tipscope::base::csv {

namespace {
// A line with quotes: each cell copied with its quotes removed (a quote opens a quoted part only
// at the start of a cell; inside one, two quotes are one).
bool splitQuoted(QByteArrayView line, QList<QByteArray> &copies) {
    QByteArray cell;
    bool quoted = false;
    for (qsizetype i = 0; i < line.size(); ++i) {
        const char c = line.at(i);
        if (quoted) {
            if (c != '"')
                cell.append(c);
            else if (i + 1 < line.size() && line.at(i + 1) == '"')
                cell.append(line.at(++i));
            else
                quoted = false;
        } else if (c == ',') {
            copies.append(cell);
            cell.clear();
        } else if (c == '"' && cell.isEmpty()) {
            quoted = true;
        } else {
            cell.append(c);
        }
    }
    copies.append(cell);
    return !quoted;
}
} // namespace

QString quoted(const QString &cell) {
    QString flat = cell;
    flat.replace(QLatin1Char('\n'), QLatin1Char(' ')).replace(QLatin1Char('\r'), QLatin1Char(' '));
    if (!flat.contains(QLatin1Char(',')) && !flat.contains(QLatin1Char('"')) &&
        flat.trimmed() == flat)
        return flat;
    flat.replace(QStringLiteral("\""), QStringLiteral("\"\""));
    return QLatin1Char('"') + flat + QLatin1Char('"');
}

bool splitLine(QByteArrayView line, Cells &cells) {
    cells.m_cells.clear();
    cells.m_copies.clear();
    if (line.isEmpty()) {
        cells.m_cells.append(line);
        return true;
    }
    if (std::memchr(line.data(), '"', size_t(line.size()))) {
        const bool closed = splitQuoted(line, cells.m_copies);
        for (const QByteArray &c : std::as_const(cells.m_copies))
            cells.m_cells.append(QByteArrayView(c));
        return closed;
    }
    qsizetype start = 0;
    for (;;) {
        const auto *comma = static_cast<const char *>(
            std::memchr(line.data() + start, ',', size_t(line.size() - start)));
        if (!comma) {
            cells.m_cells.append(line.sliced(start));
            return true;
        }
        const qsizetype end = comma - line.data();
        cells.m_cells.append(line.sliced(start, end - start));
        start = end + 1;
    }
}

} // namespace tipscope::base::csv
