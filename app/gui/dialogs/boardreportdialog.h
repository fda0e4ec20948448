// BoardReportDialog: the "Board report…" of the File menu. Asks for a board serial (the work
// context's to begin with) and a file, and writes that board's record from the journal as the
// PDF `tipscope-cli board --pdf` writes (lib/journal/boardrecord.h, lib/report/boardpdf.h). A
// board the journal holds nothing of, or a file that cannot be written, is said in the dialog,
// which stays open with what was typed.
//
// The journal is read on a thread of its own: a plant's journal holds months of joints, and the
// window (its charts, the lines it polls) must not wait for the scan. The dialog says it is
// reading meanwhile; closing it then waits for the scan to end.
#pragma once

#include "journal/boardrecord.h"

#include <QDialog>
#include <QPointer>

class QLabel;
class QLineEdit;
class QPushButton;
class QThread;

namespace tipscope::gui {

class BoardReportDialog : public QDialog {
    Q_OBJECT
public:
    BoardReportDialog(QString journalPath, const QString &serial, QWidget *parent = nullptr);
    ~BoardReportDialog() override;

    // Reads the board of the serial field from the journal (on a thread of its own) and writes
    // its PDF at `path`; reportDone() says how it went.
    void writeReport(const QString &path);
    [[nodiscard]] bool isReading() const { return m_reader != nullptr; }
    // Asks where to write, then writes; closes once written, stays open when that fails.
    void accept() override;

Q_SIGNALS:
    // Empty: written. Otherwise why not, as the dialog shows it.
    void reportDone(const QString &problem);

private:
    void finishReport(const base::Outcome<journal::BoardRecord> &record, const QString &serial,
                      const QString &path);
    void showProblem(const QString &problem);
    void fitHeight();

    QString m_journalPath;
    QLineEdit *m_serial;
    QLabel *m_problem;
    QPushButton *m_write;
    QPointer<QThread> m_reader;
    bool m_closeWhenWritten = false;
};

} // namespace tipscope::gui
