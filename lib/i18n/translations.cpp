#include "translations.h"

#include <QCoreApplication>
#include <QFile>
#include <QLibraryInfo>
#include <QLoggingCategory>
#include <QTranslator>

// Debug output (which language was chosen, and why) only when asked for: QT_LOGGING_RULES.
Q_LOGGING_CATEGORY(lcI18n, "tipscope.i18n", QtInfoMsg)

namespace tipscope::i18n {

namespace {

const QString kSourceLanguage = QStringLiteral("en");

QString catalogue(const QString &language) {
    return QStringLiteral(":/i18n/tipscope_%1.qm").arg(language);
}

// "es-ES", "es_ES.UTF-8", "de" -> "es", "es", "de"; "C" -> "C".
QString languageCode(const QString &uiLanguage) {
    return QLocale(uiLanguage).name().section(QLatin1Char('_'), 0, 0);
}

} // namespace

QStringList availableLanguages() {
    QStringList languages{kSourceLanguage};
    for (const QString &language : {QStringLiteral("es"), QStringLiteral("de")}) {
        if (QFile::exists(catalogue(language)))
            languages.append(language);
    }
    return languages;
}

QString resolveLanguage(const QString &preference, const QStringList &ui) {
    const QStringList available = availableLanguages();
    if (available.contains(preference))
        return preference;
    for (const QString &uiLanguage : ui) {
        const QString code = languageCode(uiLanguage);
        if (available.contains(code))
            return code;
    }
    return kSourceLanguage;
}

QString installTranslators(QCoreApplication &app, const QString &preference) {
    const QString language = resolveLanguage(preference);
    qCDebug(lcI18n) << "preference" << preference << "system" << QLocale::system().uiLanguages()
                    << "shows" << language;
    // For English, only the plural forms: every other text is its own English source, and Qt's
    // own texts are English already.
    auto *own = new QTranslator(&app);
    if (own->load(catalogue(language)))
        QCoreApplication::installTranslator(own);
    else
        qCWarning(lcI18n) << "cannot load" << catalogue(language);
    if (language == kSourceLanguage)
        return language;

    auto *qt = new QTranslator(&app);
    const QString qtDir = QLibraryInfo::path(QLibraryInfo::TranslationsPath);
    if (qt->load(QLocale(language), QStringLiteral("qtbase"), QStringLiteral("_"), qtDir))
        QCoreApplication::installTranslator(qt);
    else
        qCDebug(lcI18n) << "no Qt translation for" << language << "in" << qtDir;
    return language;
}

} // namespace tipscope::i18n
