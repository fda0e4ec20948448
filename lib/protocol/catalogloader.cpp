// Parses the catalog's JSON resources into Catalog. Kept apart from the lookups in catalog.cpp
// because it is all about tolerating (and reporting) malformed data, not about the protocol.
#include "catalog.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace tipscope::protocol {

class CatalogLoader {
public:
    explicit CatalogLoader(Catalog &c)
        : m_c(c) {}

    bool loadFamilies(const QJsonObject &root);
    bool loadCommands(const QJsonObject &root);
    QString error;

private:
    bool fail(const QString &why) {
        if (error.isEmpty())
            error = why;
        return false;
    }
    static QMap<int, QString> intMap(const QJsonObject &o);
    bool loadAdvice(const QJsonObject &advice);
    bool inheritAdvice(const QMap<QString, QString> &from);
    bool parseCommand(const QJsonObject &o, const QJsonObject &groups, CommandSpec &spec);
    Catalog &m_c;
};

QMap<int, QString> CatalogLoader::intMap(const QJsonObject &o) {
    QMap<int, QString> m;
    for (auto it = o.begin(); it != o.end(); ++it)
        m.insert(it.key().toInt(), it.value().toString());
    return m;
}

// What to check, per error table and code; "other" (kept as -1) for codes the table lacks. A
// table may take another's texts ("adviceFrom") and add or replace codes of its own, so that a
// text shared by error tables that mean the same is written, and translated, once.
bool CatalogLoader::loadAdvice(const QJsonObject &advice) {
    QMap<QString, QString> from;
    for (auto table = advice.begin(); table != advice.end(); ++table) {
        const QJsonObject codes = table.value().toObject();
        QMap<int, QString> byCode;
        for (auto it = codes.begin(); it != codes.end(); ++it) {
            if (it.key() == QLatin1String("adviceFrom")) {
                from.insert(table.key(), it.value().toString());
                continue;
            }
            bool isNumber = false;
            const int code = it.key().toInt(&isNumber);
            if (!isNumber && it.key() != QLatin1String("other"))
                return fail(
                    QStringLiteral("advice for %1 has a bad code '%2'").arg(table.key(), it.key()));
            byCode.insert(isNumber ? code : -1, it.value().toString());
        }
        m_c.m_advice.insert(table.key(), byCode);
    }
    return inheritAdvice(from);
}

// Each table that names another gets the texts of the whole chain it names, its own last so
// that they win. A name that is no advice table, or a chain that comes back to itself, is
// refused: either would silently leave a table without the texts it was meant to have.
bool CatalogLoader::inheritAdvice(const QMap<QString, QString> &from) {
    const QMap<QString, QMap<int, QString>> own = m_c.m_advice;
    for (auto it = from.cbegin(); it != from.cend(); ++it) {
        QStringList chain{it.key()};
        while (from.contains(chain.last())) {
            const QString next = from.value(chain.last());
            if (!own.contains(next))
                return fail(QStringLiteral("advice for %1 takes its texts from '%2', which is no "
                                           "advice table")
                                .arg(chain.last(), next));
            if (chain.contains(next))
                return fail(QStringLiteral("advice for %1 takes its texts from itself: %2")
                                .arg(it.key(), (chain << next).join(QStringLiteral(" -> "))));
            chain.append(next);
        }
        QMap<int, QString> merged;
        for (auto t = chain.crbegin(); t != chain.crend(); ++t)
            merged.insert(own.value(*t));
        m_c.m_advice.insert(it.key(), merged);
    }
    return true;
}

static QList<int> intList(const QJsonArray &a) {
    QList<int> out;
    for (const auto &v : a)
        out.append(v.toInt());
    return out;
}

bool CatalogLoader::loadFamilies(const QJsonObject &root) {
    const QJsonObject fams = root.value(QLatin1String("families")).toObject();
    if (fams.isEmpty())
        return fail(QStringLiteral("families.json has no families"));
    for (auto it = fams.begin(); it != fams.end(); ++it) {
        const QJsonObject o = it.value().toObject();
        FamilyInfo f;
        f.name = it.key();
        f.kind = o.value(QLatin1String("kind")).toString();
        f.title = o.value(QLatin1String("title")).toString();
        f.guide = o.value(QLatin1String("guide")).toString();
        f.ports = o.value(QLatin1String("ports")).toInt();
        f.tools = intList(o.value(QLatin1String("tools")).toArray());
        f.toolTable = o.value(QLatin1String("toolTable")).toString();
        f.tempMin = o.value(QLatin1String("tempMin")).toInt();
        f.tempMax = o.value(QLatin1String("tempMax")).toInt();
        f.factoryMat = o.value(QLatin1String("factoryMat")).toInt();
        f.factoryMit = o.value(QLatin1String("factoryMit")).toInt();
        f.maxPowerW = o.value(QLatin1String("maxPowerW")).toInt();
        f.addressedByDefault = o.value(QLatin1String("addressedByDefault")).toBool(true);
        f.defaultAddress = o.value(QLatin1String("defaultAddress")).toInt(1);
        f.writeAnswerEchoesData = o.value(QLatin1String("writeAnswerEchoesData")).toBool();
        f.stationErrors = o.value(QLatin1String("stationErrors")).toString();
        f.portErrors = o.value(QLatin1String("portErrors")).toString();
        f.nakUndefined = o.value(QLatin1String("nakUndefined")).toInt(9);
        if (f.kind != QLatin1String("station") && f.kind != QLatin1String("feeder"))
            return fail(QStringLiteral("family %1 has unknown kind").arg(f.name));
        m_c.m_families.insert(f.name, f);
    }
    // Keep the order people know from the guides rather than alphabetical.
    for (const char *n : {"UCR", "ALE", "NAE", "DDE", "DME", "HDE", "DDR", "HDR", "SFR"})
        if (m_c.m_families.contains(QLatin1String(n)))
            m_c.m_familyOrder.append(QLatin1String(n));
    for (const auto &name : m_c.m_families.keys())
        if (!m_c.m_familyOrder.contains(name))
            m_c.m_familyOrder.append(name);

    const QJsonObject tables = root.value(QLatin1String("tables")).toObject();
    for (auto it = tables.begin(); it != tables.end(); ++it) {
        if (it.key() == QLatin1String("severity")) {
            const QJsonObject sev = it.value().toObject();
            for (auto s = sev.begin(); s != sev.end(); ++s)
                m_c.m_severity.insert(s.key(), intMap(s.value().toObject()));
        } else if (it.key() == QLatin1String("advice")) {
            if (!loadAdvice(it.value().toObject()))
                return false;
        } else if (it.key() == QLatin1String("portErrorAliases")) {
            const QJsonObject al = it.value().toObject();
            for (auto a = al.begin(); a != al.end(); ++a)
                m_c.m_portErrorAliases.insert(a.key().toInt(), a.value().toInt());
        } else if (it.value().isArray()) {
            QList<DigitField> fields;
            for (const auto &d : it.value().toArray()) {
                const QJsonObject o = d.toObject();
                fields.append({o.value(QLatin1String("digit")).toInt(),
                               o.value(QLatin1String("name")).toString(),
                               intMap(o.value(QLatin1String("values")).toObject())});
            }
            m_c.m_digits.insert(it.key(), fields);
        } else {
            m_c.m_tables.insert(it.key(), intMap(it.value().toObject()));
        }
    }
    const QJsonObject units = root.value(QLatin1String("units")).toObject();
    for (auto it = units.begin(); it != units.end(); ++it) {
        const QJsonObject o = it.value().toObject();
        m_c.m_units.insert(it.key(), {it.key(), o.value(QLatin1String("symbol")).toString(),
                                      o.value(QLatin1String("display")).toString(),
                                      o.value(QLatin1String("scale")).toDouble(1),
                                      o.value(QLatin1String("decimals")).toInt()});
    }
    const QJsonObject addr = root.value(QLatin1String("addresses")).toObject();
    for (auto it = addr.begin(); it != addr.end(); ++it)
        m_c.m_addresses.insert(it.key(), it.value().toInt());
    return true;
}

static bool isKnownToken(const QString &t) {
    bool isNumber = false;
    t.toInt(&isNumber);
    static const QStringList tokens = {QStringLiteral("$tempMin"), QStringLiteral("$tempMax"),
                                       QStringLiteral("$factoryMat"),
                                       QStringLiteral("$factoryMit")};
    return t.isEmpty() || isNumber || tokens.contains(t);
}

static QString tokenOf(const QJsonValue &v) {
    if (v.isDouble())
        return QString::number(v.toInt());
    return v.toString();
}

bool CatalogLoader::parseCommand(const QJsonObject &o, const QJsonObject &groups, CommandSpec &s) {
    static const QMap<QString, ValueKind> kinds = {
        {QStringLiteral("number"), ValueKind::Number}, {QStringLiteral("delay"), ValueKind::Delay},
        {QStringLiteral("hex"), ValueKind::Hex},       {QStringLiteral("text"), ValueKind::Text},
        {QStringLiteral("enum"), ValueKind::Enum},     {QStringLiteral("flags"), ValueKind::Flags},
        {QStringLiteral("action"), ValueKind::Action}};
    s.pattern = o.value(QLatin1String("code")).toString();
    if (s.pattern.size() != 3)
        return fail(QStringLiteral("command code '%1' is not 3 characters").arg(s.pattern));
    const QString access = o.value(QLatin1String("access")).toString();
    s.readable = access.contains(QLatin1Char('r'));
    s.writable = access.contains(QLatin1Char('w'));
    const QString kind = o.value(QLatin1String("kind")).toString();
    if (!kinds.contains(kind) || (!s.readable && !s.writable))
        return fail(QStringLiteral("command %1 has a bad kind or access").arg(s.pattern));
    s.kind = kinds.value(kind);
    for (const auto &f : o.value(QLatin1String("families")).toArray()) {
        const QString name = f.toString();
        if (name.startsWith(QLatin1Char('@'))) {
            const QJsonValue g = groups.value(name.mid(1));
            if (!g.isArray())
                return fail(QStringLiteral("unknown family group %1").arg(name));
            for (const auto &m : g.toArray())
                s.families.append(m.toString());
        } else {
            s.families.append(name);
        }
    }
    for (const auto &f : s.families)
        if (!m_c.m_families.contains(f))
            return fail(QStringLiteral("command %1 names unknown family %2").arg(s.pattern, f));
    s.name = o.value(QLatin1String("name")).toString();
    s.description = o.value(QLatin1String("description")).toString();
    s.danger = o.value(QLatin1String("danger")).toString();
    s.unit = o.value(QLatin1String("unit")).toString(QStringLiteral("none"));
    if (!m_c.m_units.contains(s.unit))
        return fail(QStringLiteral("command %1 has unknown unit %2").arg(s.pattern, s.unit));
    s.minToken = tokenOf(o.value(QLatin1String("min")));
    s.maxToken = tokenOf(o.value(QLatin1String("max")));
    s.defaultToken = tokenOf(o.value(QLatin1String("default")));
    if (!isKnownToken(s.minToken) || !isKnownToken(s.maxToken) || !isKnownToken(s.defaultToken))
        return fail(QStringLiteral("command %1 has a bad range token").arg(s.pattern));
    s.step = o.value(QLatin1String("step")).toInt(1);
    s.special = intMap(o.value(QLatin1String("special")).toObject());
    s.table = o.value(QLatin1String("table")).toString();
    s.values = intMap(o.value(QLatin1String("values")).toObject());
    s.writeValues = intMap(o.value(QLatin1String("writeValues")).toObject());
    s.digitsTable = o.value(QLatin1String("digits")).toString();
    s.fixedData = o.value(QLatin1String("data")).toString().toLatin1();
    const QString group = o.value(QLatin1String("group")).toString();
    const auto groupId = groupFromName(group);
    if (!groupId)
        return fail(QStringLiteral("command %1 has unknown group '%2'").arg(s.pattern, group));
    s.group = *groupId;
    if (const QJsonValue role = o.value(QLatin1String("role")); !role.isUndefined()) {
        const auto roleId = roleFromName(role.toString());
        if (!roleId)
            return fail(
                QStringLiteral("command %1 has unknown role '%2'").arg(s.pattern, role.toString()));
        s.role = *roleId;
    }
    s.quantity = o.value(QLatin1String("quantity")).toString();
    s.partial = o.value(QLatin1String("partial")).toBool();
    s.label = o.value(QLatin1String("label")).toString();
    s.poll = o.value(QLatin1String("poll")).toString();
    s.dangerous = o.value(QLatin1String("dangerous")).toBool();
    s.isVolatile = o.value(QLatin1String("volatile")).toBool();
    s.savedBy = o.value(QLatin1String("savedBy")).toString();
    for (const auto &f : o.value(QLatin1String("clearsOnRead")).toArray())
        s.clearsOnRead.append(f.toString());
    const QJsonObject limits = o.value(QLatin1String("limits")).toObject();
    s.limitMin = limits.value(QLatin1String("min")).toString();
    s.limitMax = limits.value(QLatin1String("max")).toString();
    return true;
}

bool CatalogLoader::loadCommands(const QJsonObject &root) {
    const QJsonObject groups = root.value(QLatin1String("familyGroups")).toObject();
    const QJsonArray cmds = root.value(QLatin1String("commands")).toArray();
    if (cmds.isEmpty())
        return fail(QStringLiteral("commands.json has no commands"));
    for (const auto &v : cmds) {
        CommandSpec spec;
        if (!parseCommand(v.toObject(), groups, spec))
            return false;
        m_c.m_commands.append(spec);
    }
    return true;
}

static base::Outcome<QJsonObject> parseObject(const QByteArray &json, const char *what) {
    QJsonParseError pe;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &pe);
    if (pe.error != QJsonParseError::NoError || !doc.isObject())
        return base::failure(QStringLiteral("%1: %2 at offset %3")
                                 .arg(QLatin1String(what), pe.errorString())
                                 .arg(pe.offset));
    return doc.object();
}

base::Outcome<Catalog> Catalog::load(const QByteArray &familiesJson,
                                     const QByteArray &commandsJson) {
    const auto fams = parseObject(familiesJson, "families.json");
    if (!fams)
        return base::failure(fams.error());
    const auto cmds = parseObject(commandsJson, "commands.json");
    if (!cmds)
        return base::failure(cmds.error());
    Catalog c;
    CatalogLoader loader(c);
    if (!loader.loadFamilies(*fams) || !loader.loadCommands(*cmds))
        return base::failure(loader.error);
    return c;
}

} // namespace tipscope::protocol
