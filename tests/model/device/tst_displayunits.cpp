// Display units: what people read and type, to and from the wire. °C and °F (an adjust converts
// as a difference, without the 32), per mille as per cent, tenths of a millimetre as millimetres,
// "ss.cc" delays as seconds, special values by name; typed numbers in the user's locale or with a
// point, the unit after them or not; and nothing written that was not typed: a value between two
// the wire can hold is refused, naming both.
#include "model/device/displayunits.h"
#include "testmain.h"

#include <QTest>

namespace tst_displayunits {

using namespace tipscope::model;
using namespace tipscope::protocol;

namespace {
ResolvedCommand command(const QString &family, const QByteArray &code) {
    const auto cmd = Catalog::builtin().resolve(family, code, Direction::Write);
    if (!cmd)
        qFatal("%s has no %s", qPrintable(family), code.constData());
    return *cmd;
}
} // namespace

class TestDisplayUnits : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { QLocale::setDefault(QLocale::c()); }
    void cleanupTestCase() { QLocale::setDefault(QLocale::system()); }
    void valuesReadInTheirDisplayUnits_data();
    void valuesReadInTheirDisplayUnits();
    void typedValuesBecomeTheWiresValue_data();
    void typedValuesBecomeTheWiresValue();
    void whatTheWireCannotHoldIsRefusedWithWhatItCan_data();
    void whatTheWireCannotHoldIsRefusedWithWhatItCan();
    void aGermanDecimalCommaAndAScriptsPointAreBothRead();
};

void TestDisplayUnits::valuesReadInTheirDisplayUnits_data() {
    QTest::addColumn<QString>("family");
    QTest::addColumn<QByteArray>("code");
    QTest::addColumn<qint64>("wire");
    QTest::addColumn<TemperatureUnit>("unit");
    QTest::addColumn<QString>("shown");
    const auto c = TemperatureUnit::Celsius, f = TemperatureUnit::Fahrenheit;
    QTest::newRow("a setpoint") << "DME" << QByteArray("ST1") << qint64(350) << c << "350 °C";
    QTest::newRow("in °F") << "DME" << QByteArray("ST1") << qint64(350) << f << "662 °F";
    QTest::newRow("an adjust in °F, no 32")
        << "DME" << QByteArray("A11") << qint64(-10) << f << "-18 °F";
    QTest::newRow("power") << "DDR" << QByteArray("PLM") << qint64(840) << c << "84.0 %";
    QTest::newRow("a length") << "SFR" << QByteArray("LEN") << qint64(200) << c << "20.0 mm";
    QTest::newRow("a delay") << "DME" << QByteArray("HD1") << qint64(160) << c << "1.60 s";
    QTest::newRow("a special value")
        << "DME" << QByteArray("HD1") << qint64(99999) << c << "disabled";
}

void TestDisplayUnits::valuesReadInTheirDisplayUnits() {
    QFETCH(QString, family);
    QFETCH(QByteArray, code);
    QFETCH(qint64, wire);
    QFETCH(TemperatureUnit, unit);
    QFETCH(QString, shown);
    QCOMPARE(formatValue(command(family, code), Value::ofNumber(wire), unit), shown);
}

void TestDisplayUnits::typedValuesBecomeTheWiresValue_data() {
    QTest::addColumn<QString>("family");
    QTest::addColumn<QByteArray>("code");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<TemperatureUnit>("unit");
    QTest::addColumn<qint64>("wire");
    const auto c = TemperatureUnit::Celsius, f = TemperatureUnit::Fahrenheit;
    QTest::newRow("a number") << "DME" << QByteArray("ST1") << "350" << c << qint64(350);
    QTest::newRow("with its unit") << "DME" << QByteArray("ST1") << " 350 °C " << c << qint64(350);
    QTest::newRow("a whole °C in °F") << "DME" << QByteArray("ST1") << "662 °F" << f << qint64(350);
    QTest::newRow("an adjust in °F") << "DME" << QByteArray("A11") << "-18" << f << qint64(-10);
    QTest::newRow("per cent") << "DDR" << QByteArray("PLM") << "84.5" << c << qint64(845);
    QTest::newRow("millimetres") << "SFR" << QByteArray("LEN") << "20.1 mm" << c << qint64(201);
    QTest::newRow("seconds") << "DME" << QByteArray("HD1") << "1.6" << c << qint64(160);
    QTest::newRow("by name") << "DME" << QByteArray("HD1") << "disabled" << c << qint64(99999);
}

void TestDisplayUnits::typedValuesBecomeTheWiresValue() {
    QFETCH(QString, family);
    QFETCH(QByteArray, code);
    QFETCH(QString, typed);
    QFETCH(TemperatureUnit, unit);
    QFETCH(qint64, wire);
    const auto parsed = parseDisplayText(command(family, code), typed, unit);
    QVERIFY2(parsed, qPrintable(parsed ? QString() : parsed.error()));
    QCOMPARE(*parsed, wire);
}

void TestDisplayUnits::whatTheWireCannotHoldIsRefusedWithWhatItCan_data() {
    QTest::addColumn<QString>("family");
    QTest::addColumn<QByteArray>("code");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<TemperatureUnit>("unit");
    QTest::addColumn<QString>("said");
    const auto c = TemperatureUnit::Celsius, f = TemperatureUnit::Fahrenheit;
    QTest::newRow("a tenth of a degree")
        << "DME" << QByteArray("ST1") << "350.5" << c
        << "350.5 lies between the values Selected temperature can take: 350 °C or 351 °C";
    // Most whole °F are no whole °C: the two the station can hold are named.
    QTest::newRow("a whole °F")
        << "DME" << QByteArray("ST1") << "650" << f
        << "650 lies between the values Selected temperature can take: 649 °F or 651 °F";
    QTest::newRow("a hundredth of a millimetre")
        << "SFR" << QByteArray("LEN") << "20.05" << c
        << "20.05 lies between the values Feeding length can take: 20.0 mm or 20.1 mm";
    QTest::newRow("not a number") << "DME" << QByteArray("ST1") << "hot" << c
                                  << "'hot' is not a number";
    QTest::newRow("far outside") << "DME" << QByteArray("ST1") << "1e300" << c
                                 << "'1e300' is far outside what Selected temperature can take";
    QTest::newRow("infinite") << "DME" << QByteArray("ST1") << "inf" << c
                              << "'inf' is not a number";
}

void TestDisplayUnits::whatTheWireCannotHoldIsRefusedWithWhatItCan() {
    QFETCH(QString, family);
    QFETCH(QByteArray, code);
    QFETCH(QString, typed);
    QFETCH(TemperatureUnit, unit);
    QFETCH(QString, said);
    const auto parsed = parseDisplayText(command(family, code), typed, unit);
    QVERIFY(!parsed);
    QCOMPARE(parsed.error(), said);
}

void TestDisplayUnits::aGermanDecimalCommaAndAScriptsPointAreBothRead() {
    const ResolvedCommand delay = command(QStringLiteral("DME"), "HD1");
    const QLocale german(QLocale::German, QLocale::Germany);
    QCOMPARE(*parseDisplayText(delay, QStringLiteral("1,6 s"), TemperatureUnit::Celsius, german),
             qint64(160));
    QCOMPARE(*parseDisplayText(delay, QStringLiteral("1.6"), TemperatureUnit::Celsius, german),
             qint64(160));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestDisplayUnits)

} // namespace tst_displayunits
#include "tst_displayunits.moc"
