// The board record as a document a quality engineer signs: a PDF (A4) in the user interface
// language, made from boardHtml() by QTextDocument and QPdfWriter, for `tipscope-cli board --pdf`
// and the GUI's board report alike.
//
// What it shows: a header with the board, its overall result from the joints' verdicts, when it
// was made, under which work orders and by whom; a table of every joint (time, station, port,
// tool, operator, work order, setpoint, dip, recovery, verdict, each with how sure it is); the
// worst joints; each tip with its wear; the last profile applied before the board and the changes
// during it; the faults and other events while it was made; a plain list of what the journal
// does not hold (the limits each joint was judged by, the station's settings as they stood, the
// readings a curve would need, so the worst joints are listed, not drawn); the TipScope version;
// lines to sign. A board of a few dozen joints fits one page; the joint table of a larger one
// runs on over the next pages.
//
// Laying text out needs fonts, and Qt gives fonts only to a QGuiApplication: writeBoardPdf()
// refuses to run without one (a command-line program makes one on the offscreen platform).
#pragma once

#include "base/outcome.h"
#include "journal/boardrecord.h"

#include <QString>

namespace tipscope::report {

struct BoardReportInfo {
    QString software;     // the TipScope version that writes the record
    QString journal;      // the journal file it was read from
    qint64 writtenMs = 0; // when
};

// The record as rich text (the subset QTextDocument reads), in the user interface language.
[[nodiscard]] QString boardHtml(const journal::BoardRecord &record, const BoardReportInfo &info);
// Writes the PDF at `path`, whole or not at all.
[[nodiscard]] base::Outcome<void> writeBoardPdf(const journal::BoardRecord &record,
                                                const BoardReportInfo &info, const QString &path);

} // namespace tipscope::report
