// The board report in the window: File offers it; the dialog writes the PDF of a board the
// journal holds, and says so, writing nothing, for a serial it holds nothing of or none at all.
#include "dialogs/boardreportdialog.h"
#include "journalfixture.h"
#include "mainwindow.h"
#include "testmain.h"

#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
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
    const auto written = dialog.writeReport(pdf);
    QVERIFY2(written, qPrintable(written.error()));
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
    const QString pdf = m_dir.filePath(QStringLiteral("unknown.pdf"));
    const auto written = dialog.writeReport(pdf);
    QVERIFY(!written);
    QVERIFY2(written.error().contains(message), qPrintable(written.error()));
    QVERIFY(!QFile::exists(pdf));
}

TIPSCOPE_TEST_MAIN(TestBoardReportDialog)

} // namespace tst_boardreportdialog
#include "tst_boardreportdialog.moc"
