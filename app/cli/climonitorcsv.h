// MonitorCsv: the file `tipscope-cli monitor --csv FILE` writes as it goes, one row per port and
// cycle: "timestamp,port,tip_c,setpoint_c,power_pct,status", under a comment naming the station.
//
// With a workspace, each line writes a file of its own by default (FILE with the line's name
// before the extension: plant.csv → plant-cell-3.csv, see fileFor()); with --csv-one-file every
// line writes into one file that has a `line` column after the timestamp.
#pragma once

#include "base/outcome.h"

#include <QFile>
#include <QString>
#include <memory>

namespace tipscope::cli {

class MonitorCsv {
public:
    // Creates (truncates) `path`; with `lineColumn`, rows carry the line's name.
    [[nodiscard]] static base::Outcome<std::shared_ptr<MonitorCsv>> create(const QString &path,
                                                                           bool lineColumn);

    // A comment row naming the device a line monitors ("# cell-3: 01 DME-2C DME 9996780").
    [[nodiscard]] bool describe(const QString &line, const QString &device);
    // One port's reading; `line` is ignored without the line column. False when the row could
    // not be written whole (a full disk): errorText() says why, and nothing more is written.
    [[nodiscard]] bool write(const QString &line, const QString &timestamp, int port,
                             const QString &fields);
    [[nodiscard]] QString path() const { return m_file.fileName(); }
    [[nodiscard]] QString errorText() const { return m_error; }

    // "plant.csv" for line "cell-3" is "plant-cell-3.csv"; a name without extension gets the
    // line's name at its end. The line's name is made safe first (base::io::fileNamePart()): the
    // file is in the folder of `path`, whatever the workspace names the line.
    [[nodiscard]] static QString fileFor(const QString &path, const QString &line);

private:
    MonitorCsv(bool lineColumn)
        : m_lineColumn(lineColumn) {}
    bool put(const QString &text);

    QFile m_file;
    QString m_error;
    bool m_lineColumn = false;
};

} // namespace tipscope::cli
