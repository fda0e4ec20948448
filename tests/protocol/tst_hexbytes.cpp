// Hex text typed by a person (the console's raw frame field, tipscope-cli send) becomes bytes in
// every form people write it, and anything else is refused with the position of the first bad
// character; bytes are shown back as hex and as readable ASCII with the control bytes named.
#include "protocol/hexbytes.h"
#include "testmain.h"

#include <QTest>

namespace tst_hexbytes {

using namespace tipscope::protocol;

class TestHexBytes : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void everyWayPeopleWriteHexGivesTheSameBytes_data() {
        QTest::addColumn<QString>("text");
        QTest::newRow("spaced") << QStringLiteral("02 30 3a");
        QTest::newRow("packed") << QStringLiteral("02303A");
        QTest::newRow("0x and commas") << QStringLiteral("0x02,0x30,0x3A");
        QTest::newRow("0X, colons, tabs") << QStringLiteral("\t0X02:30:3a  ");
    }
    void everyWayPeopleWriteHexGivesTheSameBytes() {
        QFETCH(QString, text);
        const auto bytes = parseHexBytes(text);
        QVERIFY2(bytes.ok(), qPrintable(bytes.error()));
        QCOMPARE(bytes.value(), QByteArray("\x02\x30\x3a", 3));
    }

    void anythingElseIsRefusedWithWhereItWentWrong_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("why");
        QTest::newRow("not a digit")
            << QStringLiteral("02 3g") << QStringLiteral("'g' at position 5 is not a hex digit");
        QTest::newRow("half a byte before a space")
            << QStringLiteral("02 3 30")
            << QStringLiteral("odd number of hex digits before position 5");
        QTest::newRow("half a byte at the end")
            << QStringLiteral("02 303") << QStringLiteral("odd number of hex digits");
        QTest::newRow("nothing") << QStringLiteral("  , ") << QStringLiteral("no bytes given");
        QTest::newRow("a prefix alone") << QStringLiteral("0x") << QStringLiteral("no bytes given");
    }
    void anythingElseIsRefusedWithWhereItWentWrong() {
        QFETCH(QString, text);
        QFETCH(QString, why);
        const auto bytes = parseHexBytes(text);
        QVERIFY(!bytes.ok());
        QCOMPARE(bytes.error(), why);
    }

    void moreThanTheLimitIsRefusedTheLimitItselfIsTaken() {
        const QString atLimit = QStringLiteral("ab").repeated(kMaxHexInputBytes);
        const auto taken = parseHexBytes(atLimit);
        QVERIFY2(taken.ok(), qPrintable(taken.error()));
        QCOMPARE(taken.value().size(), kMaxHexInputBytes);
        const auto refused = parseHexBytes(atLimit + QStringLiteral("ab"));
        QVERIFY(!refused.ok());
        QCOMPARE(refused.error(), QStringLiteral("more than %1 bytes").arg(kMaxHexInputBytes));
    }

    void bytesAreShownAsHexAndAsReadableText() {
        const QByteArray frame("\x02"
                               "0001RSMN\x03\x3e\x1b\xff",
                               13);
        QCOMPARE(toHexText(frame), QStringLiteral("02 30 30 30 31 52 53 4D 4E 03 3E 1B FF"));
        QCOMPARE(toAsciiText(frame), QStringLiteral("<STX>0001RSMN<ETX>><1B><FF>"));
        QCOMPARE(parseHexBytes(toHexText(frame)).value(), frame);
        QCOMPARE(toHexText({}), QString());
    }
};

TIPSCOPE_TEST_GUILESS_MAIN(TestHexBytes)

} // namespace tst_hexbytes

#include "tst_hexbytes.moc"
