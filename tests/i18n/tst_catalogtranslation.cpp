// The command catalog's words (names, descriptions, value labels, error tables) and the event
// log's kinds come out in the user interface language wherever people read them, with TipScope's
// real German catalogue loaded, while what is data keeps the catalog's English. The catalogue is
// the one embedded by the build, so a text lupdate did not collect (scripts/gen-catalog-strings not
// run) or a label shown without catalogText() stays English here and fails.
#include "../model/simfixture.h"
#include "base/timetext.h"
#include "i18n/translations.h"
#include "model/context/deviceidentity.h"
#include "model/events/eventhistorymodel.h"
#include "model/events/eventtext.h"
#include "model/report/supportreport.h"
#include "testmain.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QTranslator>

namespace tst_catalogtranslation {

using namespace tipscope;
using namespace tipscope::model;
using namespace tipscope::protocol;
using namespace tipscope::testing;

class TestCatalogTranslation : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void parameterNamesDescriptionsAndValuesAreGerman();
    void specialLabelsAreAcceptedAndRefusalsExplainedInGerman();
    void actionsExplainThemselvesInGerman();
    void errorTablesAreGermanForPeopleAndEnglishAsData();
    void aNakReachesTheParameterInGerman();
    void supportReportTextNamesParametersInGerman();
    void eventKindsAreGermanForPeopleAndEnglishAsData();
    void aRepeatedEventSaysHowOftenInGermanInTheTableAndTheReport();
    void aDeviceIsDescribedWithTheWordAddressInGerman();
};

void TestCatalogTranslation::initTestCase() {
    QCOMPARE(i18n::installTranslators(*QCoreApplication::instance(), QStringLiteral("de")),
             QStringLiteral("de"));
}

void TestCatalogTranslation::cleanupTestCase() {
    qDeleteAll(QCoreApplication::instance()->findChildren<QTranslator *>());
}

void TestCatalogTranslation::parameterNamesDescriptionsAndValuesAreGerman() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    const Parameter *selected = st->parameter("ST1");
    QCOMPARE(selected->label(), QStringLiteral("Eingestellte Temperatur"));
    QVERIFY2(selected->description().startsWith(QStringLiteral("Arbeitstemperatur der Spitze")),
             qPrintable(selected->description()));
    QCOMPARE(selected->meta().name, QStringLiteral("Selected temperature")); // data stays English

    const Parameter *status = st->parameter("PS1");
    const TemperatureUnit c = TemperatureUnit::Celsius;
    QCOMPARE(formatValue(status->spec(), Value::ofNumber(11), c),
             QStringLiteral("Ablage, Abkühlen"));
    QCOMPARE(describeValue(status->spec(), Value::ofNumber(11), Wording::Catalog),
             QStringLiteral("Stand, Cooling"));
    QCOMPARE(formatValue(st->parameter("HD1")->spec(), Value::ofNumber(99999), c),
             QStringLiteral("deaktiviert"));
    QCOMPARE(formatValue(st->parameter("CT1")->spec(), Value::ofNumber(0), c),
             QStringLiteral("Kein Werkzeug"));
    QCOMPARE(formatValue(st->parameter("CT1")->spec(), Value::ofNumber(1), c),
             QStringLiteral("T210")); // model names are not translated
    QCOMPARE(st->parameter("D12")->allowedText(),
             QStringLiteral("0 min bis 9 min, oder deaktiviert"));
}

void TestCatalogTranslation::specialLabelsAreAcceptedAndRefusalsExplainedInGerman() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    const ResolvedCommand &status = st->parameter("PS1")->spec();
    const TemperatureUnit c = TemperatureUnit::Celsius;
    const ResolvedCommand &delay = st->parameter("D12")->spec();
    QCOMPARE(parseDisplayText(delay, QStringLiteral("Deaktiviert"), c).value(), 99999);
    const auto sleep = parseUserValue(status, QStringLiteral("Ruhemodus"));
    QVERIFY(!sleep);
    QCOMPARE(sleep.error(),
             QStringLiteral("'Ruhemodus' ist keine ganze Zahl; für PS1 zulässig: einer der Werte "
                            "0 (In Betrieb), 1 (Ablage), 10 (Abkühlen)"));
}

void TestCatalogTranslation::actionsExplainThemselvesInGerman() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    const Action *reset = st->action("RSP");
    QVERIFY(reset);
    QCOMPARE(reset->name(), QStringLiteral("Werkseinstellungen wiederherstellen"));
    QVERIFY2(reset->danger().startsWith(QStringLiteral("Alle Einstellungen des Geräts")),
             qPrintable(reset->danger()));
}

void TestCatalogTranslation::errorTablesAreGermanForPeopleAndEnglishAsData() {
    const Catalog &cat = Catalog::builtin();
    QCOMPARE(cat.portErrorText(QStringLiteral("DME"), 1, Wording::Translated),
             QStringLiteral("Kurzschluss"));
    QCOMPARE(cat.portErrorText(QStringLiteral("DME"), 1, Wording::Catalog),
             QStringLiteral("Short circuit"));
    QCOMPARE(cat.portErrorText(QStringLiteral("DME"), 42, Wording::Translated),
             QStringLiteral("Unbekannter Portfehler 42"));
    QCOMPARE(cat.stationErrorText(QStringLiteral("DME"), 3, Wording::Translated),
             QStringLiteral("Speicherfehler"));
    QVERIFY(
        cat.nakText(3, Wording::Translated).startsWith(QStringLiteral("Außerhalb des Bereichs")));
    QCOMPARE(cat.feederErrorText(0, Wording::Translated), QStringLiteral("Kein Fehler"));
}

void TestCatalogTranslation::aNakReachesTheParameterInGerman() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    sim::SimFaults faults;
    faults.nakCode = 3; // out of range
    f.simLine->setFaults(faults);
    auto st = f.station();
    Parameter *p = st->parameter("ST2");
    QCOMPARE(p->setEdit(300), QString());
    QSignalSpy done(p, &Parameter::writeFinished);
    p->apply();
    QVERIFY(done.wait(10000));
    QCOMPARE(done.first().at(0).toBool(), false);
    const QString why = done.first().at(1).toString();
    QVERIFY2(why.contains(QStringLiteral("NAK 00003: Außerhalb des Bereichs: der Wert liegt")),
             qPrintable(why));
    QCOMPARE(p->failure(), why);
}

void TestCatalogTranslation::supportReportTextNamesParametersInGerman() {
    // The JSON half of the report carries the catalog's English name; the text half is read by
    // people and names the parameter in their language.
    const QJsonObject value{{QStringLiteral("code"), QStringLiteral("ST1")},
                            {QStringLiteral("name"), QStringLiteral("Selected temperature")},
                            {QStringLiteral("text"), QStringLiteral("350 °C")}};
    const QJsonObject device{{QStringLiteral("values"), QJsonArray{value}}};
    const QString text =
        supportReportText(QJsonObject{{QStringLiteral("devices"), QJsonArray{device}}});
    QVERIFY2(text.contains(QStringLiteral("  ST1  Eingestellte Temperatur: 350 °C\n")),
             qPrintable(text));
}

void TestCatalogTranslation::eventKindsAreGermanForPeopleAndEnglishAsData() {
    // The chart markers' tooltips and the Errors page name the kind; the report's JSON keys it.
    QCOMPARE(Event::kindTitle(Event::Kind::StationError), QStringLiteral("Stationsfehler"));
    QCOMPARE(Event::kindTitle(Event::Kind::Write), QStringLiteral("Schreiben"));
    QCOMPARE(Event::kindName(Event::Kind::Write), QStringLiteral("write"));
}

void TestCatalogTranslation::aRepeatedEventSaysHowOftenInGermanInTheTableAndTheReport() {
    const QString text = QStringLiteral("nicht gesendet");
    QCOMPARE(repeatedEventText(text, 1, QStringLiteral("10:02:13")), text);
    const QString repeated = QStringLiteral("nicht gesendet (75-mal, bis 10:02:13)");
    QCOMPARE(repeatedEventText(text, 75, QStringLiteral("10:02:13")), repeated);

    Event e;
    e.text = text;
    e.count = 75;
    e.time = QDateTime::currentDateTime().addSecs(-60);
    e.lastTime = e.time.addSecs(30);
    QCOMPARE(EventHistoryModel::text(e, EventHistoryModel::Text, false),
             QStringLiteral("nicht gesendet (75-mal, bis %1)")
                 .arg(tipscope::base::clockText(e.lastTime)));
    const QJsonObject event{{QStringLiteral("text"), text},
                            {QStringLiteral("count"), 75},
                            {QStringLiteral("lastTime"), QStringLiteral("10:02:13")}};
    const QString report =
        supportReportText(QJsonObject{{QStringLiteral("events"), QJsonArray{event}}});
    QVERIFY2(report.contains(repeated), qPrintable(report));
}

// The other German texts say "Adresse 01"; a bare "an 01" reads as a time or a port.
void TestCatalogTranslation::aDeviceIsDescribedWithTheWordAddressInGerman() {
    const DeviceIdentity identity{QStringLiteral("demo"), 1, QStringLiteral("DME-2C"),
                                  QStringLiteral("9996780")};
    QCOMPARE(identity.description(),
             QStringLiteral("DME-2C an Adresse 01 über demo, Software 9996780"));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestCatalogTranslation)

} // namespace tst_catalogtranslation
#include "tst_catalogtranslation.moc"
