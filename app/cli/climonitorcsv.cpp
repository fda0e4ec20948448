#include "climonitorcsv.h"

#include "base/csv.h"
#include "base/elide.h"
#include "base/filenamepart.h"

#include <QCoreApplication>
#include <QFileInfo>

namespace tipscope::cli {

namespace {
struct MonitorCsvTr {
    Q_DECLARE_TR_FUNCTIONS(CliMonitor)
};
} // namespace

base::Outcome<std::shared_ptr<MonitorCsv>> MonitorCsv::create(const QString &path,
                                                              bool lineColumn) {
    std::shared_ptr<MonitorCsv> csv(new MonitorCsv(lineColumn));
    csv->m_file.setFileName(path);
    // Unbuffered: each row reaches the file when it is written, so a row that a full disk cuts
    // part way can be taken back whole (put()).
    if (!csv->m_file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Unbuffered))
        return base::failure(MonitorCsvTr::tr("tipscope-cli: cannot write %1: %2")
                                 .arg(base::elidedPath(path), csv->m_file.errorString()));
    return csv;
}

bool MonitorCsv::describe(const QString &line, const QString &device) {
    const QString header =
        m_lineColumn ? QStringLiteral("timestamp,line,port,tip_c,setpoint_c,power_pct,status\n")
                     : QStringLiteral("timestamp,port,tip_c,setpoint_c,power_pct,status\n");
    if (m_lineColumn) {
        // The column header once, at the top; each line's device as a comment when it starts.
        if (m_file.pos() == 0 && !put(header))
            return false;
        return put(QStringLiteral("# %1: %2\n").arg(line, device));
    }
    return put(QStringLiteral("# %1\n").arg(device) + header);
}

bool MonitorCsv::write(const QString &line, const QString &timestamp, int port,
                       const QString &fields) {
    const QString row = m_lineColumn
                            ? QStringLiteral("%1,%2,%3,%4\n")
                                  .arg(timestamp, base::csv::quoted(line))
                                  .arg(port)
                                  .arg(fields)
                            : QStringLiteral("%1,%2,%3\n").arg(timestamp).arg(port).arg(fields);
    return put(row);
}

bool MonitorCsv::put(const QString &text) {
    if (!m_error.isEmpty())
        return false;
    const QByteArray bytes = text.toUtf8();
    const qint64 before = m_file.pos();
    const qint64 first = m_file.write(bytes);
    // Qt reports a write cut short without its reason; writing the rest again gives it.
    const bool whole = first == bytes.size() ||
                       (first >= 0 && m_file.write(bytes.mid(first)) == bytes.size() - first);
    if (!whole) {
        m_error = m_file.errorString();
        // The file ends with the last row written whole, as a reader expects; a device that
        // cannot be cut (a pipe, /dev/full) has nothing to take back.
        if (m_file.size() > before)
            m_file.resize(before);
        m_file.close();
        return false;
    }
    return true;
}

QString MonitorCsv::fileFor(const QString &path, const QString &line) {
    const QFileInfo info(path);
    const QString suffix = info.suffix();
    const QString base = suffix.isEmpty() ? path : path.left(path.size() - suffix.size() - 1);
    return base + QLatin1Char('-') + base::io::fileNamePart(line) +
           (suffix.isEmpty() ? QString() : QLatin1Char('.') + suffix);
}

} // namespace tipscope::cli
