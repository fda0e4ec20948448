// Data-field formats: numbers, ss.cc delays, the disabled sentinel, hex counters, text.
#include "protocol/datafield.h"
#include "testmain.h"

#include <QTest>

namespace tst_datafield {

using namespace tipscope::protocol;

class TestDataField : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void numbersArePaddedToFiveWithSignFirst_data();
    void numbersArePaddedToFiveWithSignFirst();
    void numbersOutsideTheFieldAreRefused();
    void malformedNumbersDoNotParse_data();
    void malformedNumbersDoNotParse();
    void delaysAreSecondsDotHundredths();
    void malformedDelaysDoNotParse();
    void hexCountersAcceptTheGuidesLengthsWithOrWithoutPrefix();
    void textMayBeShorterOrLongerThanFive();
};

void TestDataField::numbersArePaddedToFiveWithSignFirst_data() {
    QTest::addColumn<int>("value");
    QTest::addColumn<QByteArray>("field");
    QTest::newRow("375") << 375 << QByteArray("00375");
    QTest::newRow("-50") << -50 << QByteArray("-0050");
    QTest::newRow("0") << 0 << QByteArray("00000");
    QTest::newRow("disabled") << kDisabled << QByteArray("99999");
    QTest::newRow("min") << -9999 << QByteArray("-9999");
}

void TestDataField::numbersArePaddedToFiveWithSignFirst() {
    QFETCH(int, value);
    QFETCH(QByteArray, field);
    QCOMPARE(encodeNumber(value).value(), field);
    QCOMPARE(parseNumber(field).value(), value);
}

void TestDataField::numbersOutsideTheFieldAreRefused() {
    QVERIFY(!encodeNumber(100000));
    QVERIFY(!encodeNumber(-10000));
}

void TestDataField::malformedNumbersDoNotParse_data() {
    QTest::addColumn<QByteArray>("field");
    for (const char *s :
         {"", "0375", "003750", "-", "--050", "0-050", "00 75", "+0050", "1e300", "0x375"})
        QTest::newRow(s) << QByteArray(s);
}

void TestDataField::malformedNumbersDoNotParse() {
    QFETCH(QByteArray, field);
    QVERIFY(!parseNumber(field));
}

void TestDataField::delaysAreSecondsDotHundredths() {
    QCOMPARE(encodeDelay(160).value(), QByteArray("01.60"));
    QCOMPARE(encodeDelay(10).value(), QByteArray("00.10"));
    QCOMPARE(encodeDelay(9999).value(), QByteArray("99.99"));
    QCOMPARE(parseDelay("01.60").value(), 160);
    QCOMPARE(parseDelay("00.10").value(), 10);
    QVERIFY(!encodeDelay(10000));
    QVERIFY(!encodeDelay(-1));
}

void TestDataField::malformedDelaysDoNotParse() {
    for (const char *s : {"0160", "1.60", "01,60", "01.6", "aa.bb", "01.600", "-1.60"})
        QVERIFY2(!parseDelay(s), s);
}

void TestDataField::hexCountersAcceptTheGuidesLengthsWithOrWithoutPrefix() {
    QCOMPARE(parseHex("0x000000003E8").value(), quint64(1000));
    QCOMPARE(parseHex("000003E8").value(), quint64(1000));
    QCOMPARE(parseHex("3e8").value(), quint64(1000));
    QCOMPARE(encodeHex(1000), QByteArray("000003E8"));
    QVERIFY(!parseHex(""));
    QVERIFY(!parseHex("0x"));
    QVERIFY(!parseHex("12G4"));
    QVERIFY(!parseHex(QByteArray(17, 'F')));
}

void TestDataField::textMayBeShorterOrLongerThanFive() {
    QCOMPARE(parseText("DDR").value(), QStringLiteral("DDR"));
    QCOMPARE(parseText("9996780").value(), QStringLiteral("9996780"));
    QCOMPARE(parseText("").value(), QString());
    QVERIFY(!parseText(QByteArray("DM\x01", 3)));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestDataField)

} // namespace tst_datafield
#include "tst_datafield.moc"
