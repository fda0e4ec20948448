// The one CSV helper: every text comes back from its cell unchanged (line breaks aside, which
// become spaces so a record stays one line), and only cells that need quotes get them.
#include "base/csv.h"
#include "testmain.h"

#include <QTest>

namespace tst_csv {

using namespace tipscope::base;

class TestCsv : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aCellReadsBackAsItsText_data();
    void aCellReadsBackAsItsText();
    void anOpenQuoteIsRefused();
};

void TestCsv::aCellReadsBackAsItsText_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("cell");
    QTest::addColumn<QString>("readBack");
    QTest::newRow("plain") << "Working"
                           << "Working"
                           << "Working";
    QTest::newRow("empty") << ""
                           << ""
                           << "";
    QTest::newRow("comma") << "DME-4C, port 1"
                           << "\"DME-4C, port 1\""
                           << "DME-4C, port 1";
    QTest::newRow("quotes") << "ST1 = \"350\""
                            << "\"ST1 = \"\"350\"\"\""
                            << "ST1 = \"350\"";
    QTest::newRow("spaces at the ends") << " 350 "
                                        << "\" 350 \""
                                        << " 350 ";
    QTest::newRow("line breaks") << "two\nlines\r\nend"
                                 << "two lines  end"
                                 << "two lines  end";
    QTest::newRow("unicode") << "Working → Stand °C"
                             << "Working → Stand °C"
                             << "Working → Stand °C";
}

void TestCsv::aCellReadsBackAsItsText() {
    QFETCH(QString, text);
    QFETCH(QString, cell);
    QFETCH(QString, readBack);
    const QString written = csv::quoted(text);
    QCOMPARE(written, cell);
    const QByteArray line = "a," + written.toUtf8() + ",b";
    csv::Cells cells;
    QVERIFY(csv::splitLine(line, cells));
    QCOMPARE(cells.size(), 3);
    QCOMPARE(cells.text(0), QStringLiteral("a"));
    QCOMPARE(cells.text(1), readBack);
    QCOMPARE(cells.text(2), QStringLiteral("b"));
}

void TestCsv::anOpenQuoteIsRefused() {
    csv::Cells cells;
    QVERIFY(!csv::splitLine("a,\"b,c", cells));
    QVERIFY(csv::splitLine("a,b\"c", cells)); // a quote inside a cell is text
    QCOMPARE(cells.text(1), QStringLiteral("b\"c"));
    QVERIFY(csv::splitLine("", cells));
    QCOMPARE(cells.size(), 1);
    QVERIFY(csv::splitLine(",,", cells));
    QCOMPARE(cells.size(), 3);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestCsv)

} // namespace tst_csv
#include "tst_csv.moc"
