// The board report in the window: File offers it; the dialog writes the PDF of a board the
// journal holds, and says so, writing nothing, for a serial it holds nothing of or none at all.
#include "dialogs/boardreportdialog.h"
#include "journalfixture.h"
#include "mainwindow.h"
#include "screencheck.h"
#include "testmain.h"

#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

namespace tst_boardreportdialog {

using namespace tipscope;
using namespace tipscope::gui;
using namespace tipscope::testing;

class TestBoardReportDialog : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void theFileMenuOffersTheBoardReport();
    void aBoardTheJournalHoldsIsWrittenAsAPdf();
    void anUnknownOrMissingSerialIsSaidAndNothingWritten_data();
    void anUnknownOrMissingSerialIsSaidAndNothingWritten();
    void aDialogClosedWhileReadingWritesNothing();

private:
    QTemporaryDir m_dir;
    QString m_journal;
};

void TestBoardReportDialog::initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("TipScopeTests"));
    QVERIFY(m_dir.isValid());
    m_journal = m_dir.filePath(QStringLiteral("journal.sqlite"));
    QVERIFY(writeSampleBoard(m_journal).written);
}

void TestBoardReportDialog::theFileMenuOffersTheBoardReport() {
    MainWindow w;
    QStringList texts;
    for (QAction *menu : w.menuBar()->actions())
        if (menu->menu())
            for (QAction *action : menu->menu()->actions())
                texts.append(action->text());
    QVERIFY2(texts.contains(QStringLiteral("&Board report…")), qPrintable(texts.join(", ")));
}

void TestBoardReportDialog::aBoardTheJournalHoldsIsWrittenAsAPdf() {
    BoardReportDialog dialog(m_journal, QStringLiteral("SN-42"));
    QCOMPARE(dialog.findChild<QLineEdit *>(QStringLiteral("boardSerial"))->text(),
             QStringLiteral("SN-42"));
    const QString pdf = m_dir.filePath(QStringLiteral("SN-42.pdf"));
    QSignalSpy done(&dialog, &BoardReportDialog::reportDone);
    dialog.writeReport(pdf);
    // The journal is read on a thread of its own: meanwhile the dialog says so, and takes no
    // second request.
    QVERIFY(dialog.isReading());
    QVERIFY(!dialog.findChild<QLineEdit *>(QStringLiteral("boardSerial"))->isEnabled());
    QVERIFY2(dialog.findChild<QLabel *>(QStringLiteral("problem"))
                 ->text()
                 .startsWith(QStringLiteral("Reading the journal for board SN-42")),
             qPrintable(dialog.findChild<QLabel *>(QStringLiteral("problem"))->text()));
    QVERIFY(done.wait(20000));
    QCOMPARE(done.count(), 1);
    QCOMPARE(done.first().first().toString(), QString());
    QVERIFY(!dialog.isReading());
    QVERIFY(dialog.findChild<QLineEdit *>(QStringLiteral("boardSerial"))->isEnabled());
    QFile file(pdf);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QVERIFY(file.read(5) == "%PDF-");
}

void TestBoardReportDialog::anUnknownOrMissingSerialIsSaidAndNothingWritten_data() {
    QTest::addColumn<QString>("serial");
    QTest::addColumn<QString>("message");
    QTest::newRow("unknown") << QStringLiteral("SN-404")
                             << QStringLiteral("The journal has no board SN-404");
    QTest::newRow("none") << QStringLiteral("  ") << QStringLiteral("Give the serial of a board.");
}

void TestBoardReportDialog::anUnknownOrMissingSerialIsSaidAndNothingWritten() {
    QFETCH(QString, serial);
    QFETCH(QString, message);
    BoardReportDialog dialog(m_journal, serial);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    const QString pdf = m_dir.filePath(QStringLiteral("unknown.pdf"));
    QSignalSpy done(&dialog, &BoardReportDialog::reportDone);
    dialog.writeReport(pdf);
    QVERIFY(done.count() == 1 || done.wait(20000));
    const QString said = done.first().first().toString();
    QVERIFY2(said.contains(message), qPrintable(said));
    // Said where the eye is: in the dialog, which stays open with what was typed.
    QCOMPARE(dialog.findChild<QLabel *>(QStringLiteral("problem"))->text(), said);
    QVERIFY(!QFile::exists(pdf));
    // The dialog grows to show it whole, and what it said before.
    QTest::qWait(100);
    const QStringList cut = screenProblems(dialog);
    QVERIFY2(cut.isEmpty(), qPrintable(cut.join(QLatin1Char('\n'))));
}

// Closed while the journal is read: it waits for the scan, drops its result and writes nothing.
void TestBoardReportDialog::aDialogClosedWhileReadingWritesNothing() {
    const QString pdf = m_dir.filePath(QStringLiteral("closed.pdf"));
    {
        BoardReportDialog dialog(m_journal, QStringLiteral("SN-42"));
        dialog.writeReport(pdf);
        QVERIFY(dialog.isReading());
    }
    QCoreApplication::processEvents(); // what the scan's end posted, to a dialog now gone
    QVERIFY(!QFile::exists(pdf));
}

TIPSCOPE_TEST_MAIN(TestBoardReportDialog)

} // namespace tst_boardreportdialog
#include "tst_boardreportdialog.moc"
