#include "boardreportdialog.h"

#include "journal/journalreader.h"
#include "model/workcontextjson.h"
#include "report/boardpdf.h"
#include "widgets/startfolder.h"

#include <QApplication>
#include <QDateTime>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

namespace tipscope::gui {

BoardReportDialog::BoardReportDialog(QString journalPath, const QString &serial, QWidget *parent)
    : QDialog(parent)
    , m_journalPath(std::move(journalPath)) {
    setWindowTitle(tr("Board report"));
    m_serial = new QLineEdit(serial, this);
    m_serial->setObjectName(QStringLiteral("boardSerial"));
    m_serial->setMaxLength(model::kMaxWorkContextChars);
    m_serial->setClearButtonEnabled(true);
    m_serial->setMinimumWidth(260);
    m_problem = new QLabel(this);
    m_problem->setObjectName(QStringLiteral("problem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #c62828;"));
    auto *note = new QLabel(tr("Every joint the journal keeps for the board, its result, its "
                               "tools' wear and the events while it was made, as a PDF to sign."),
                            this);
    note->setWordWrap(true);
    auto *form = new QFormLayout(this);
    form->addRow(note);
    form->addRow(tr("Board serial:"), m_serial);
    form->addRow(m_problem);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    buttons->addButton(tr("Write PDF…"), QDialogButtonBox::AcceptRole);
    connect(buttons, &QDialogButtonBox::accepted, this, &BoardReportDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

protocol::Outcome<void> BoardReportDialog::writeReport(const QString &path) const {
    const QString serial = m_serial->text().trimmed();
    if (serial.isEmpty())
        return protocol::failure(tr("Give the serial of a board."));
    journal::JournalReader reader;
    if (const auto opened = reader.open(m_journalPath); !opened)
        return opened;
    const auto record = journal::buildBoardRecord(reader, serial);
    if (!record)
        return protocol::failure(record.error());
    if (record->isEmpty())
        return protocol::failure(
            tr("The journal has no board %1: no joint or event carries that serial.").arg(serial));
    const report::BoardReportInfo info{QApplication::applicationVersion(), m_journalPath,
                                       QDateTime::currentMSecsSinceEpoch()};
    return report::writeBoardPdf(record.value(), info, path);
}

void BoardReportDialog::accept() {
    const QString serial = m_serial->text().trimmed();
    if (serial.isEmpty()) {
        m_problem->setText(tr("Give the serial of a board."));
        return;
    }
    QString fileName = serial + QStringLiteral(".pdf");
    fileName.replace(QLatin1Char('/'), QLatin1Char('_')); // a serial is not a folder
    const QString path = QFileDialog::getSaveFileName(this, tr("Board report"),
                                                      QDir(startFolder()).filePath(fileName),
                                                      tr("PDF documents (*.pdf)"));
    if (path.isEmpty())
        return;
    if (const auto written = writeReport(path); !written) {
        m_problem->setText(written.error());
        return;
    }
    QDialog::accept();
}

} // namespace tipscope::gui
