#include "boardreportdialog.h"

#include "journal/journalreader.h"
#include "model/context/workcontextjson.h"
#include "report/boardpdf.h"
#include "widgets/startfolder.h"

#include <QApplication>
#include <QDateTime>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFormLayout>
#include <QLabel>
#include <QLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QThread>
#include <memory>

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
    auto *note = new QLabel(tr("Every joint the journal keeps for the board, its result, its "
                               "tools' wear and the events while it was made, as a PDF to sign."),
                            this);
    note->setWordWrap(true);
    auto *form = new QFormLayout(this);
    form->addRow(note);
    form->addRow(tr("Board serial:"), m_serial);
    form->addRow(m_problem);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    m_write = buttons->addButton(tr("Write PDF…"), QDialogButtonBox::AcceptRole);
    connect(buttons, &QDialogButtonBox::accepted, this, &BoardReportDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

BoardReportDialog::~BoardReportDialog() {
    if (!m_reader)
        return;
    // Its result is dropped: nobody waits for it any more.
    m_reader->wait();
    delete m_reader.data();
}

void BoardReportDialog::writeReport(const QString &path) {
    const QString serial = m_serial->text().trimmed();
    if (serial.isEmpty())
        return showProblem(tr("Give the serial of a board."));
    if (m_reader)
        return;
    // What the thread builds, handed back on this one once it ended.
    auto record = std::make_shared<base::Outcome<journal::BoardRecord>>(base::failure(QString()));
    m_reader = QThread::create([record, journalPath = m_journalPath, serial] {
        journal::JournalReader reader;
        if (const auto opened = reader.open(journalPath); !opened)
            *record = base::failure(opened.error());
        else
            *record = journal::buildBoardRecord(reader, serial);
    });
    connect(m_reader, &QThread::finished, this, [this, record, serial, path] {
        m_reader->deleteLater();
        m_reader = nullptr;
        finishReport(*record, serial, path);
    });
    m_write->setEnabled(false);
    m_serial->setEnabled(false);
    m_problem->setStyleSheet(QString());
    m_problem->setText(tr("Reading the journal for board %1…").arg(serial));
    fitHeight();
    m_reader->start();
}

void BoardReportDialog::finishReport(const base::Outcome<journal::BoardRecord> &record,
                                     const QString &serial, const QString &path) {
    m_write->setEnabled(true);
    m_serial->setEnabled(true);
    if (!record)
        return showProblem(record.error());
    if (record->isEmpty())
        return showProblem(
            tr("The journal has no board %1: no joint or event carries that serial.").arg(serial));
    const report::BoardReportInfo info{QApplication::applicationVersion(), m_journalPath,
                                       QDateTime::currentMSecsSinceEpoch()};
    if (const auto written = report::writeBoardPdf(record.value(), info, path); !written)
        return showProblem(written.error());
    m_problem->clear();
    Q_EMIT reportDone(QString());
    if (std::exchange(m_closeWhenWritten, false))
        QDialog::accept();
}

// A layout squeezes its wrapped labels into the window it has rather than grow the window: a
// message of two lines cut the text above it. The dialog grows to show both whole.
void BoardReportDialog::fitHeight() {
    layout()->activate();
    if (const int needed = layout()->totalHeightForWidth(width()); needed > height())
        resize(width(), needed);
}

void BoardReportDialog::showProblem(const QString &problem) {
    m_closeWhenWritten = false;
    m_problem->setStyleSheet(QStringLiteral("color: #c62828;"));
    m_problem->setText(problem);
    fitHeight();
    Q_EMIT reportDone(problem);
}

void BoardReportDialog::accept() {
    const QString serial = m_serial->text().trimmed();
    if (serial.isEmpty())
        return showProblem(tr("Give the serial of a board."));
    if (m_reader)
        return;
    QString fileName = serial + QStringLiteral(".pdf");
    fileName.replace(QLatin1Char('/'), QLatin1Char('_')); // a serial is not a folder
    const QString path = QFileDialog::getSaveFileName(this, tr("Board report"),
                                                      QDir(startFolder()).filePath(fileName),
                                                      tr("PDF documents (*.pdf)"));
    if (path.isEmpty())
        return;
    m_closeWhenWritten = true;
    writeReport(path);
}

} // namespace tipscope::gui
