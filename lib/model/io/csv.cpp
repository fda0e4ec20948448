#include "model/io/csv.h"

namespace tipscope::model::csv {

QString quoted(const QString &cell) {
    QString flat = cell;
    flat.replace(QLatin1Char('\n'), QLatin1Char(' ')).replace(QLatin1Char('\r'), QLatin1Char(' '));
    if (!flat.contains(QLatin1Char(',')) && !flat.contains(QLatin1Char('"')) &&
        flat.trimmed() == flat)
        return flat;
    flat.replace(QStringLiteral("\""), QStringLiteral("\"\""));
    return QLatin1Char('"') + flat + QLatin1Char('"');
}

bool splitLine(const QString &line, QStringList &cells) {
    cells.clear();
    QString cell;
    bool quoted = false;
    for (qsizetype i = 0; i < line.size(); ++i) {
        const QChar c = line.at(i);
        if (quoted) {
            if (c != QLatin1Char('"'))
                cell.append(c);
            else if (i + 1 < line.size() && line.at(i + 1) == QLatin1Char('"'))
                cell.append(line.at(++i));
            else
                quoted = false;
        } else if (c == QLatin1Char(',')) {
            cells.append(cell);
            cell.clear();
        } else if (c == QLatin1Char('"') && cell.isEmpty()) {
            quoted = true;
        } else {
            cell.append(c);
        }
    }
    cells.append(cell);
    return !quoted;
}

} // namespace tipscope::model::csv
