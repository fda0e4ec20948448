// The user interface language: how it is chosen, and that both programs show their texts in it.
// tipscope-cli follows the system (LANGUAGE, LC_ALL, LANG; QLocale reads them even when glibc
// has no such locale installed); tipscope follows the ui/language preference or the system.
#include "i18n/translations.h"
#include "mainwindow.h"
#include "programrun.h"
#include "protocol/catalog.h"
#include "protocol/catalogtext.h"
#include "testmain.h"

#include <QDir>
#include <QLibraryInfo>
#include <QMenuBar>
#include <QProcess>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTranslator>

namespace tst_uilanguage {

using namespace tipscope;

namespace {

using Run = testing::ProgramRun;

// Runs a built program with the language variables replaced by `env` ("NAME=value" each).
Run runWith(const QString &program, const QStringList &args, const QStringList &env) {
    QProcessEnvironment e = QProcessEnvironment::systemEnvironment();
    for (const char *name : {"LANGUAGE", "LC_ALL", "LC_MESSAGES", "LANG"})
        e.remove(QLatin1String(name));
    for (const QString &assignment : env)
        e.insert(assignment.section(QLatin1Char('='), 0, 0),
                 assignment.section(QLatin1Char('='), 1));
    QProcess p;
    p.setProcessEnvironment(e);
    p.start(testing::binaryPath(program), args);
    return testing::finishProcess(p, 30000);
}

// What TipScope's embedded catalogue for `language` says for a source text.
QString translated(const QString &language, const char *context, const char *source) {
    QTranslator t;
    if (!t.load(QStringLiteral(":/i18n/tipscope_%1.qm").arg(language)))
        return {};
    return t.translate(context, source);
}

const char kGuiDescription[] = "Configure and monitor JBC soldering stations and the SFR feeder.";

} // namespace

class TestUiLanguage : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void preferenceOrFirstKnownSystemLanguageIsChosen_data();
    void preferenceOrFirstKnownSystemLanguageIsChosen();
    void cliUsageFollowsTheSystemLanguage_data();
    void cliUsageFollowsTheSystemLanguage();
    void cliErrorsAreTranslatedToo();
    void guiHelpFollowsThePreference_data();
    void guiHelpFollowsThePreference();
    void mainWindowShowsGermanWithQtsOwnTexts();
    void catalogTextsAndLinkErrorsAreShownInGermanButDataStaysEnglish();
    void englishCountsInSingularAndPlural();
};

void TestUiLanguage::initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("TipScopeTests"));
    QSettings().clear();
    QCOMPARE(i18n::availableLanguages(),
             QStringList({QStringLiteral("en"), QStringLiteral("es"), QStringLiteral("de")}));
}

void TestUiLanguage::preferenceOrFirstKnownSystemLanguageIsChosen_data() {
    QTest::addColumn<QString>("preference");
    QTest::addColumn<QStringList>("system");
    QTest::addColumn<QString>("shown");
    const QStringList german{QStringLiteral("de-DE"), QStringLiteral("de")};
    QTest::newRow("system German") << "system" << german << "de";
    QTest::newRow("system Mexican Spanish") << "system" << QStringList{"es-MX"} << "es";
    QTest::newRow("system C") << "system" << QStringList{"C"} << "en";
    QTest::newRow("system French, then German") << "system" << QStringList{"fr-FR", "de"} << "de";
    QTest::newRow("system English before German") << "system" << QStringList{"en-GB", "de"} << "en";
    QTest::newRow("system Italian only") << "system" << QStringList{"it-IT"} << "en";
    QTest::newRow("preference Spanish") << "es" << german << "es";
    QTest::newRow("preference English") << "en" << german << "en";
    QTest::newRow("unknown preference") << "xx" << german << "de";
}

void TestUiLanguage::preferenceOrFirstKnownSystemLanguageIsChosen() {
    QFETCH(QString, preference);
    QFETCH(QStringList, system);
    QFETCH(QString, shown);
    QCOMPARE(i18n::resolveLanguage(preference, system), shown);
}

void TestUiLanguage::cliUsageFollowsTheSystemLanguage_data() {
    QTest::addColumn<QStringList>("env");
    QTest::addColumn<QString>("usage");
    QTest::addColumn<QString>("commands");
    QTest::newRow("LANGUAGE=es") << QStringList{"LANGUAGE=es", "LANG=C.UTF-8"} << "Uso:"
                                 << "Comandos:";
    QTest::newRow("LC_ALL=es_ES.UTF-8") << QStringList{"LC_ALL=es_ES.UTF-8"} << "Uso:"
                                        << "Comandos:";
    QTest::newRow("LANG=de_DE.UTF-8") << QStringList{"LANG=de_DE.UTF-8"} << "Aufruf:"
                                      << "Befehle:";
    QTest::newRow("LANG=C.UTF-8") << QStringList{"LANG=C.UTF-8"} << "Usage:"
                                  << "Commands:";
}

void TestUiLanguage::cliUsageFollowsTheSystemLanguage() {
    QFETCH(QStringList, env);
    QFETCH(QString, usage);
    QFETCH(QString, commands);
    const Run r = runWith(QStringLiteral("tipscope-cli"), {QStringLiteral("--help")}, env);
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(r.out.startsWith(usage + QStringLiteral(" tipscope-cli")), qPrintable(r.out));
    QVERIFY2(r.out.contains(QLatin1Char('\n') + commands + QLatin1Char('\n')), qPrintable(r.out));
    // Commands and options are what people type: never translated.
    QVERIFY2(r.out.contains(QStringLiteral("[--port ")), qPrintable(r.out));
    QVERIFY2(r.out.contains(QStringLiteral("\n  profile apply ")), qPrintable(r.out));
}

void TestUiLanguage::cliErrorsAreTranslatedToo() {
    const Run r = runWith(QStringLiteral("tipscope-cli"), {QStringLiteral("--bogus")},
                          {QStringLiteral("LANGUAGE=es")});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.startsWith(QStringLiteral("tipscope-cli: opción desconocida --bogus\n")),
             qPrintable(r.err));
    QVERIFY2(r.err.contains(QStringLiteral("Uso:")), qPrintable(r.err));
}

void TestUiLanguage::guiHelpFollowsThePreference_data() {
    QTest::addColumn<QString>("preference");
    QTest::addColumn<QStringList>("env");
    QTest::addColumn<QString>("language");
    QTest::newRow("preference de, system C") << "de" << QStringList{"LANG=C.UTF-8"} << "de";
    QTest::newRow("preference system, LANGUAGE=es")
        << "system" << QStringList{"LANGUAGE=es"} << "es";
    QTest::newRow("preference en, LANGUAGE=de") << "en" << QStringList{"LANGUAGE=de"} << "en";
}

void TestUiLanguage::guiHelpFollowsThePreference() {
    QFETCH(QString, preference);
    QFETCH(QStringList, env);
    QFETCH(QString, language);
    QTemporaryDir config;
    QVERIFY2(config.isValid(), qPrintable(config.errorString()));
    {
        QSettings s(config.filePath(QStringLiteral("TipScope/TipScope.conf")),
                    QSettings::IniFormat);
        s.setValue(QStringLiteral("ui/language"), preference);
    }
    env << QStringLiteral("XDG_CONFIG_HOME=") + config.path();
    const Run r = runWith(QStringLiteral("tipscope"), {QStringLiteral("--help")}, env);
    QCOMPARE(r.exitCode, 0);
    const QString expected = language == QLatin1String("en")
                                 ? QString::fromLatin1(kGuiDescription)
                                 : translated(language, "main", kGuiDescription);
    QVERIFY(!expected.isEmpty());
    QVERIFY2(r.out.contains(expected), qPrintable(r.out));
}

void TestUiLanguage::mainWindowShowsGermanWithQtsOwnTexts() {
    QCOMPARE(i18n::installTranslators(*QCoreApplication::instance(), QStringLiteral("de")),
             QStringLiteral("de"));
    {
        gui::MainWindow w;
        w.show();
        QCOMPARE(w.windowTitle(), QStringLiteral("TipScope — nicht verbunden"));
        QStringList menus;
        for (QAction *a : w.menuBar()->actions())
            menus << a->text();
        QCOMPARE(menus, QStringList({"&Datei", "&Extras", "&Hilfe"}));
    }
    const QString qtCatalogue = QDir(QLibraryInfo::path(QLibraryInfo::TranslationsPath))
                                    .filePath(QStringLiteral("qtbase_de.qm"));
    const bool haveQtGerman = QFile::exists(qtCatalogue);
    const QString cancel = QCoreApplication::translate("QPlatformTheme", "Cancel");
    // Leave the application in English for whatever runs after this.
    qDeleteAll(QCoreApplication::instance()->findChildren<QTranslator *>());
    if (!haveQtGerman)
        QSKIP(
            qPrintable(qtCatalogue + QStringLiteral(" is not installed (qt6-translations-l10n)")));
    QCOMPARE(cancel, QStringLiteral("Abbrechen"));
}

// The catalog's words (names, descriptions, value labels, error tables) and the link's messages
// reach people in their language; what scripts read (Wording::Catalog) stays the catalog's English.
void TestUiLanguage::catalogTextsAndLinkErrorsAreShownInGermanButDataStaysEnglish() {
    QCOMPARE(i18n::installTranslators(*QCoreApplication::instance(), QStringLiteral("de")),
             QStringLiteral("de"));
    const protocol::Catalog &c = protocol::Catalog::builtin();
    const QString selected = protocol::catalogText(QStringLiteral("Selected temperature"));
    const QString nak = c.nakText(5, protocol::Wording::Translated);
    const QString nakData = c.nakText(5, protocol::Wording::Catalog);
    const QString noTool = c.portErrorText(QStringLiteral("DME"), 4, protocol::Wording::Translated);
    const QString notConnected = QCoreApplication::translate("tipscope::link::RequestQueue",
                                                             "not sent: the line is not connected");
    qDeleteAll(QCoreApplication::instance()->findChildren<QTranslator *>());

    QCOMPARE(selected, translated(QStringLiteral("de"), "Catalog", "Selected temperature"));
    QVERIFY2(!selected.isEmpty() && selected != QLatin1String("Selected temperature"),
             qPrintable(selected));
    QVERIFY2(nak.contains(QLatin1String("Robot")) &&
                 !nak.startsWith(QLatin1String("Robot mode is")),
             qPrintable(nak));
    QCOMPARE(nakData, QStringLiteral("Robot mode is off: switch \"Robot mode\" on in the station "
                                     "menu"));
    QVERIFY2(noTool != QLatin1String("No tool"), qPrintable(noTool));
    QVERIFY2(notConnected != QLatin1String("not sent: the line is not connected"),
             qPrintable(notConnected));
    // Back in English, the same call gives the catalog's own words.
    QCOMPARE(protocol::catalogText(QStringLiteral("Selected temperature")),
             QStringLiteral("Selected temperature"));
}

// English is the source language, but "%n device(s)" would reach people as written without the
// English plurals catalogue.
void TestUiLanguage::englishCountsInSingularAndPlural() {
    QCOMPARE(i18n::installTranslators(*QCoreApplication::instance(), QStringLiteral("en")),
             QStringLiteral("en"));
    const auto devices = [](int n) {
        return QCoreApplication::translate("Session", "%1, %n device(s)", nullptr, n)
            .arg(QStringLiteral("demo"));
    };
    const QString one = devices(1);
    const QString two = devices(2);
    const QString recoveries =
        QCoreApplication::translate("MeasurementReport", "… %n more recovery(s)", nullptr, 3);
    const QString plain = QCoreApplication::translate("tipscope::gui::ChartsPage", "&Follow");

    qDeleteAll(QCoreApplication::instance()->findChildren<QTranslator *>());
    QCOMPARE(one, QStringLiteral("demo, 1 device"));
    QCOMPARE(two, QStringLiteral("demo, 2 devices"));
    QCOMPARE(recoveries, QStringLiteral("… 3 more recoveries"));
    QCOMPARE(plain, QStringLiteral("&Follow")); // everything else is the source itself
}

TIPSCOPE_TEST_MAIN(TestUiLanguage)

} // namespace tst_uilanguage
#include "tst_uilanguage.moc"
