// Bad input in the console's hex field and `tipscope-cli send`: parseHexBytes() with malformed,
// empty, huge and non-UTF-8 text. A refusal always names the problem (and where it is, when it is
// a character); an accepted text gives exactly the bytes typed. The console widget only shows
// the message and sends nothing when parsing fails (tests/app/tst_consolepage.cpp), and
// tst_badcli proves the same for `send` on a real wire, so the parser is the whole story here.
#include "protocol/hexbytes.h"
#include "testmain.h"

#include <QTest>

namespace tst_badhex {

using namespace tipscope::protocol;

class TestBadHex : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void refusedWithTheReason_data();
    void refusedWithTheReason();
    void separatorsAndPrefixesAreAccepted_data();
    void separatorsAndPrefixesAreAccepted();
    void exactlyTheLimitIsAcceptedOneMoreIsNot();
    void hugeInputIsRefusedWithoutGrowingWithIt();
    void nonUtf8BytesBecomeReplacementCharactersAndAreRefused();
};

void TestBadHex::refusedWithTheReason_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("reason");
    QTest::newRow("empty") << ""
                           << "no bytes";
    QTest::newRow("blank") << " \t\n "
                           << "no bytes";
    QTest::newRow("separators only") << ", : ,,"
                                     << "no bytes";
    QTest::newRow("prefix only") << "0x"
                                 << "no bytes";
    QTest::newRow("odd digits") << "02 3"
                                << "odd number";
    QTest::newRow("odd before separator") << "023 0"
                                          << "odd number";
    QTest::newRow("letter g") << "02 3G"
                              << "position 5";
    QTest::newRow("minus sign") << "-02"
                                << "position 1";
    QTest::newRow("prefix in a byte") << "00x1"
                                      << "position 3";
    QTest::newRow("semicolon") << "02;03"
                               << "position 3";
    QTest::newRow("fullwidth digits") << QStringLiteral("\uff10\uff12") << "position 1";
    QTest::newRow("arabic digits") << QStringLiteral("\u0660\u0662") << "position 1";
    QTest::newRow("emoji") << QStringLiteral("02 \U0001F600") << "position 4";
    QTest::newRow("NUL character") << QString(QChar(0)) + QStringLiteral("2") << "position 1";
}

void TestBadHex::refusedWithTheReason() {
    QFETCH(QString, text);
    QFETCH(QString, reason);
    const auto bytes = parseHexBytes(text);
    QVERIFY(!bytes.ok());
    QVERIFY2(bytes.error().contains(reason), qPrintable(bytes.error()));
}

void TestBadHex::separatorsAndPrefixesAreAccepted_data() {
    QTest::addColumn<QString>("text");
    QTest::newRow("spaced") << "02 30 30 30 31 57 4D 41 54 30 30 33 37 35 03 3E";
    QTest::newRow("packed lower") << "0230303031574d41543030333735033e";
    QTest::newRow("prefixed") << "0x02,0x30,0x30,0x30,0x31,0x57,0x4D,0x41,0x54,0x30,0x30,0x33,"
                                 "0x37,0x35,0x03,0x3E";
    QTest::newRow("colons and tabs") << "02:30:30:30:31\t57:4D:41:54:30:30:33:37:35:03:3E\n";
    QTest::newRow("no-break spaces") << QStringLiteral("02\u00a030303031574D41543030333735033E");
}

void TestBadHex::separatorsAndPrefixesAreAccepted() {
    QFETCH(QString, text);
    // The guide's worked frame W MAT 00375 from 00 to 01, whatever the separators.
    const auto bytes = parseHexBytes(text);
    QVERIFY2(bytes.ok(), qPrintable(bytes.error()));
    QCOMPARE(bytes.value(), QByteArray::fromHex("0230303031574D41543030333735033E"));
}

void TestBadHex::exactlyTheLimitIsAcceptedOneMoreIsNot() {
    QCOMPARE(parseHexBytes(QString(kMaxHexInputBytes * 2, QLatin1Char('a')))->size(),
             kMaxHexInputBytes);
    const auto tooMany = parseHexBytes(QString((kMaxHexInputBytes + 1) * 2, QLatin1Char('a')));
    QVERIFY(!tooMany.ok());
    QVERIFY2(tooMany.error().contains(QStringLiteral("more than %1 bytes").arg(kMaxHexInputBytes)),
             qPrintable(tooMany.error()));
}

void TestBadHex::hugeInputIsRefusedWithoutGrowingWithIt() {
    // 100 kB of valid hex, then 100 kB of separators with one bad character at the very end.
    const auto digits = parseHexBytes(QString(100 * 1024, QLatin1Char('0')));
    QVERIFY(!digits.ok());
    QVERIFY2(digits.error().contains(QStringLiteral("more than")), qPrintable(digits.error()));
    QVERIFY(digits.error().size() < 100);
    const QString spaces = QString(100 * 1024, QLatin1Char(' ')) + QLatin1Char('z');
    const auto bad = parseHexBytes(spaces);
    QVERIFY(!bad.ok());
    QVERIFY2(bad.error().contains(QStringLiteral("position %1").arg(100 * 1024 + 1)),
             qPrintable(bad.error()));
}

void TestBadHex::nonUtf8BytesBecomeReplacementCharactersAndAreRefused() {
    // What a console field or an argv holds after decoding bytes that are not UTF-8.
    for (const QByteArray &raw : {QByteArray("02 \xff 03"), QByteArray("\xc3\x28"),
                                  QByteArray("02\xed\xa0\x80"), QByteArray("\x80")}) {
        const auto bytes = parseHexBytes(QString::fromUtf8(raw));
        QVERIFY2(!bytes.ok(), raw.toHex().constData());
        QVERIFY2(bytes.error().contains(QStringLiteral("not a hex digit")),
                 qPrintable(bytes.error()));
    }
}

TIPSCOPE_TEST_GUILESS_MAIN(TestBadHex)

} // namespace tst_badhex
#include "tst_badhex.moc"
