// Translations: chooses the user interface language at startup and installs its translators
// before the first translated string is made.
//
// English is the source language, so English needs no translator. TipScope's own catalogue is
// embedded in this library (":/i18n/tipscope_<language>.qm", made by lrelease from
// translations/*.ts during the build), so nothing has to be installed for it. Qt's own catalogue
// (qtbase_<language>.qm: standard buttons, file dialogs, QCommandLineParser) is loaded from Qt's
// translations folder when the system has it (package qt6-translations-l10n).
//
// Only the language of the texts is chosen here: QLocale() keeps following the system locale,
// so numbers and dates are shown the way the user's system writes them.
#pragma once

#include <QLocale>
#include <QString>
#include <QStringList>

class QCoreApplication;

namespace tipscope::i18n {

// The languages TipScope can show: "en" (the source) and those with an embedded catalogue.
[[nodiscard]] QStringList availableLanguages();

// The language to show for a preference (the QSettings value ui/language): "en", "es" or "de"
// chooses it; "system", an empty or an unknown value takes the first of the `ui` languages that
// TipScope has (on Unix QLocale reads them from LANGUAGE, LC_ALL, LC_MESSAGES and LANG), and
// English when none is. Returns a code from availableLanguages().
[[nodiscard]] QString resolveLanguage(const QString &preference,
                                      const QStringList &ui = QLocale::system().uiLanguages());

// Installs TipScope's and Qt's translators for resolveLanguage(preference) on `app`, which owns
// them. Returns the language shown.
QString installTranslators(QCoreApplication &app, const QString &preference);

} // namespace tipscope::i18n
