// BoardReportDialog: the "Board report…" of the File menu. Asks for a board serial (the work
// context's to begin with) and a file, and writes that board's record from the journal as the
// PDF `tipscope-cli board --pdf` writes (lib/journal/boardrecord.h, lib/report/boardpdf.h). A
// board the journal holds nothing of, or a file that cannot be written, is said in the dialog,
// which stays open with what was typed.
#pragma once

#include "protocol/outcome.h"

#include <QDialog>

class QLabel;
class QLineEdit;

namespace tipscope::gui {

class BoardReportDialog : public QDialog {
    Q_OBJECT
public:
    BoardReportDialog(QString journalPath, const QString &serial, QWidget *parent = nullptr);

    // Reads the board of the serial field from the journal and writes its PDF at `path`.
    [[nodiscard]] protocol::Outcome<void> writeReport(const QString &path) const;
    // Asks where to write, then writes; stays open when that fails.
    void accept() override;

private:
    QString m_journalPath;
    QLineEdit *m_serial;
    QLabel *m_problem;
};

} // namespace tipscope::gui
