// A catalog for tests: the built-in families.json and commands.json with extra command entries
// appended, loaded the way the built-in catalog is (Catalog::load). Adding a command to TipScope
// is meant to be one catalog entry; tests use this to prove that a new entry reaches the models
// and pages without any other change.
#pragma once

#include "protocol/catalog.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>
#include <optional>

namespace tipscope::testing {

inline QByteArray builtinCatalogFile(const char *name) {
    (void)protocol::Catalog::builtin(); // makes sure the library's resources are registered
    QFile f(QStringLiteral(":/tipscope/catalog/") + QLatin1String(name));
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// The built-in catalog plus `entries` (objects as in commands.json), or why it does not load.
inline base::Outcome<protocol::Catalog> catalogWith(const QList<QJsonObject> &entries) {
    QJsonObject commands = QJsonDocument::fromJson(builtinCatalogFile("commands.json")).object();
    QJsonArray list = commands.value(QLatin1String("commands")).toArray();
    for (const QJsonObject &e : entries)
        list.append(e);
    commands.insert(QLatin1String("commands"), list);
    return protocol::Catalog::load(builtinCatalogFile("families.json"),
                                   QJsonDocument(commands).toJson());
}

// Entries the built-in catalog does not have: a station setting, a port counter, and a feeder
// total and partial counter with the partial's reset.
inline QList<QJsonObject> newCommandEntries() {
    const QJsonArray stations{QStringLiteral("@stations")};
    const QJsonArray feeder{QStringLiteral("SFR")};
    return {
        {{"code", "BRT"},
         {"access", "rw"},
         {"default", 5},
         {"families", stations},
         {"kind", "number"},
         {"min", 0},
         {"max", 9},
         {"step", 1},
         {"group", "station"},
         {"poll", "settings"},
         {"name", "Display brightness"},
         {"description", "Brightness of the station's display"}},
        {{"code", "CKx"},
         {"access", "r"},
         {"families", stations},
         {"kind", "number"},
         {"unit", "count"},
         {"group", "counter"},
         {"poll", "counter"},
         {"name", "Tip changes"},
         {"description", "Tips changed on the port"}},
        {{"code", "CJT"},
         {"access", "r"},
         {"families", feeder},
         {"kind", "number"},
         {"unit", "count"},
         {"group", "counter"},
         {"quantity", "Wire jams"},
         {"poll", "counter"},
         {"name", "Wire jams (total)"},
         {"description", "Wire jams, total counter"}},
        {{"code", "CJP"},
         {"access", "r"},
         {"families", feeder},
         {"kind", "number"},
         {"unit", "count"},
         {"group", "counter"},
         {"quantity", "Wire jams"},
         {"partial", true},
         {"poll", "counter"},
         {"name", "Wire jams (partial)"},
         {"description", "Wire jams since the partial counter was reset"}},
        {{"code", "CJP"},
         {"access", "w"},
         {"families", feeder},
         {"kind", "action"},
         {"data", "00000"},
         {"dangerous", true},
         {"group", "counter"},
         {"partial", true},
         {"label", "Reset partial wire jams"},
         {"poll", "none"},
         {"name", "Reset wire jams (partial)"},
         {"description", "Resets the partial wire-jam counter"},
         {"danger", "The partial wire-jam counter goes back to zero."}},
    };
}

} // namespace tipscope::testing
