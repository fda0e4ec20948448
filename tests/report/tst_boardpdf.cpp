// The board record as a document to sign: its text holds the board, the result, every joint
// with how sure it is, the worst joints listed (no curve drawn: the journal has no readings),
// what the journal does not hold, the software and lines to sign; the PDF of a small board is one
// page, that of a large one runs on; a file that cannot be written is refused whole; the document
// speaks the user interface language.
#include "journalfixture.h"
#include "testmain.h"

#include "i18n/translations.h"
#include "report/boardpdf.h"

#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

namespace tst_boardpdf {

using namespace tipscope;
using namespace tipscope::testing;

namespace {
int pdfPages(const QString &path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return -1;
    const QByteArray bytes = file.readAll();
    if (!bytes.startsWith("%PDF-"))
        return -1;
    // Each page object says "/Type /Page"; the page tree says "/Type /Pages".
    return int(bytes.count("/Type /Page") - bytes.count("/Type /Pages"));
}
} // namespace

class TestBoardPdf : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void theDocumentHoldsTheBoardItsResultAndEveryJoint();
    void itSaysWhatTheJournalDoesNotHoldInsteadOfDrawingIt();
    void jointsJudgedByDifferentLimitsShowThemEach();
    void aSmallBoardIsOnePage();
    void aLargeBoardRunsOnOverPages();
    void aFileThatCannotBeWrittenIsRefused();
    void theDocumentIsInTheInterfaceLanguage(); // last: it leaves German installed

private:
    QTemporaryDir m_dir;
    journal::BoardRecord m_record;
    report::BoardReportInfo m_info;
};

void TestBoardPdf::initTestCase() {
    const QString path = m_dir.filePath(QStringLiteral("journal.sqlite"));
    const auto record = writeAndReadSampleBoard(path);
    QVERIFY2(record, qPrintable(record.error()));
    m_record = record.value();
    m_info = {QStringLiteral("9.9.9"), path, kT0 + 86'400'000};
}

void TestBoardPdf::theDocumentHoldsTheBoardItsResultAndEveryJoint() {
    const QString html = report::boardHtml(m_record, m_info);
    QVERIFY(html.contains(QStringLiteral("Board record: SN-42")));
    QVERIFY(html.contains(QStringLiteral("FAIL: joints outside their limits")));
    QVERIFY(html.contains(QStringLiteral("Work order: WO-7")));
    // One numbered row per joint, each with its dip's uncertainty.
    for (int i = 1; i <= m_record.joints.size(); ++i)
        QVERIFY2(html.contains(QRegularExpression(QStringLiteral("<tr><td[^>]*>%1</td>").arg(i))),
                 qPrintable(html));
    QCOMPARE(html.count(QStringLiteral("± 0.5")),
             m_record.joints.size() + 3); // the table and the three worst
    QVERIFY(html.contains(QStringLiteral("(bounded)")));
    // One set of limits for the board: said once, under the table.
    QVERIFY(html.contains(QStringLiteral("Judged by: a dip of at most 80 K, back within 5 K of "
                                         "the setpoint in at most 5.0 s.")));
    QVERIFY(!html.contains(QStringLiteral("Limits (dip, recovery)")));
    QVERIFY(html.contains(QStringLiteral("E-PT1: tip sensor open")));
    QVERIFY(html.contains(QStringLiteral("profile 0123456789ab applied")));
    QVERIFY(html.contains(QStringLiteral("(+30 %)")));
    QVERIFY(html.contains(QStringLiteral("Written by TipScope 9.9.9")));
    QVERIFY(html.contains(QStringLiteral("Checked by:")));
}

void TestBoardPdf::itSaysWhatTheJournalDoesNotHoldInsteadOfDrawingIt() {
    const QString html = report::boardHtml(m_record, m_info);
    QVERIFY(html.contains(QStringLiteral("No curves: the journal keeps each joint's figures")));
    // One joint of the sample board was journaled before the journal kept limits.
    QVERIFY(html.contains(QStringLiteral("The limits 1 of the 6 joints were judged by: they were "
                                         "journaled before the journal kept them")));
    QVERIFY(!html.contains(QStringLiteral("<img")));
}

void TestBoardPdf::jointsJudgedByDifferentLimitsShowThemEach() {
    journal::BoardRecord record = m_record;
    record.joints[2].record.limits = model::JudgedLimits{5, 3000, 60};
    const QString html = report::boardHtml(record, m_info);
    QVERIFY(html.contains(QStringLiteral("Limits (dip, recovery)")));
    QCOMPARE(html.count(QStringLiteral("≤ 80 K, ≤ 5.0 s")), record.joints.size() - 2);
    QCOMPARE(html.count(QStringLiteral("≤ 60 K, ≤ 3.0 s")), 1);
    QVERIFY(!html.contains(QStringLiteral("Judged by:")));
}

void TestBoardPdf::aSmallBoardIsOnePage() {
    const QString path = m_dir.filePath(QStringLiteral("small.pdf"));
    const auto written = report::writeBoardPdf(m_record, m_info, path);
    QVERIFY2(written, qPrintable(written.error()));
    QCOMPARE(pdfPages(path), 1);
}

void TestBoardPdf::aLargeBoardRunsOnOverPages() {
    journal::BoardRecord large = m_record;
    for (int i = 0; i < 200; ++i) {
        journal::StoredJoint j = m_record.joints.at(i % m_record.joints.size());
        j.id = 1000 + i;
        j.record.startMs += 60'000 + i * 1000;
        large.joints.append(j);
    }
    const QString path = m_dir.filePath(QStringLiteral("large.pdf"));
    const auto written = report::writeBoardPdf(large, m_info, path);
    QVERIFY2(written, qPrintable(written.error()));
    QVERIFY2(pdfPages(path) > 1, qPrintable(QString::number(pdfPages(path))));
}

void TestBoardPdf::aFileThatCannotBeWrittenIsRefused() {
    const QString path = m_dir.filePath(QStringLiteral("no/such/folder/board.pdf"));
    const auto written = report::writeBoardPdf(m_record, m_info, path);
    QVERIFY(!written);
    QVERIFY2(written.error().contains(QStringLiteral("cannot write")), qPrintable(written.error()));
    QVERIFY(!QFile::exists(path));
}

void TestBoardPdf::theDocumentIsInTheInterfaceLanguage() {
    QVERIFY(report::boardHtml(m_record, m_info).contains(QStringLiteral("slow recovery")));
    QCOMPARE(i18n::installTranslators(*QCoreApplication::instance(), QStringLiteral("de")),
             QStringLiteral("de"));
    const QString german = report::boardHtml(m_record, m_info);
    // The joint table's words, as the Joints page says them.
    QVERIFY2(german.contains(QStringLiteral("langsame Erholung")), qPrintable(german));
    QVERIFY(german.contains(QStringLiteral(">Bewertung</th>")));
    const QString pdf = m_dir.filePath(QStringLiteral("de.pdf"));
    const auto written = report::writeBoardPdf(m_record, m_info, pdf);
    QVERIFY2(written, qPrintable(written.error()));
    QCOMPARE(pdfPages(pdf), 1);
}

TIPSCOPE_TEST_MAIN(TestBoardPdf)

} // namespace tst_boardpdf
#include "tst_boardpdf.moc"
