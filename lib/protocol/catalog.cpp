#include "catalog.h"
#include "frame.h"

#include <QFile>
#include <QtGlobal>

static void initCatalogResources() {
    Q_INIT_RESOURCE(catalog);
}

namespace tipscope::protocol {

static QByteArray readResource(const QString &path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return f.readAll();
}

const Catalog &Catalog::builtin() {
    static const Catalog catalog = [] {
        initCatalogResources();
        auto c = load(readResource(QStringLiteral(":/tipscope/catalog/families.json")),
                      readResource(QStringLiteral(":/tipscope/catalog/commands.json")));
        if (!c)
            qFatal("embedded command catalog is broken: %s", qPrintable(c.error()));
        return std::move(c).value();
    }();
    return catalog;
}

const FamilyInfo *Catalog::family(const QString &name) const {
    auto it = m_families.constFind(name.toUpper());
    return it == m_families.constEnd() ? nullptr : &it.value();
}

QMap<int, QString> Catalog::table(const QString &name, const QString &familyName) const {
    QString key = name;
    if (const FamilyInfo *f = family(familyName)) {
        if (name == QLatin1String("$toolTable"))
            key = f->toolTable;
        else if (name == QLatin1String("$portErrors"))
            key = f->portErrors;
        else if (name == QLatin1String("$stationErrors"))
            key = f->stationErrors;
    }
    return m_tables.value(key);
}

const Unit *Catalog::unit(const QString &key) const {
    auto it = m_units.constFind(key);
    return it == m_units.constEnd() ? nullptr : &it.value();
}

QList<DigitField> Catalog::digits(const QString &tableName) const {
    return m_digits.value(tableName);
}

int Catalog::resolveToken(const QString &token, const FamilyInfo &family) const {
    if (token == QLatin1String("$tempMin"))
        return family.tempMin;
    if (token == QLatin1String("$tempMax"))
        return family.tempMax;
    if (token == QLatin1String("$factoryMat"))
        return family.factoryMat;
    if (token == QLatin1String("$factoryMit"))
        return family.factoryMit;
    return token.toInt();
}

std::optional<ResolvedCommand> Catalog::resolveSpec(const CommandSpec &spec,
                                                    const FamilyInfo &family,
                                                    const QByteArray &code,
                                                    Direction direction) const {
    if (code.size() != 3 || !spec.accepts(direction) || !spec.families.contains(family.name))
        return std::nullopt;
    ResolvedCommand r;
    for (int i = 0; i < 3; ++i) {
        const char p = spec.pattern.at(i).toLatin1();
        const char c = code.at(i);
        if (p == 'x') {
            if (!isAsciiDigit(c) || c - '0' < 1 || c - '0' > family.ports)
                return std::nullopt;
            r.port = c - '0';
        } else if (p == 'y') {
            if (!isAsciiDigit(c) || !family.tools.contains(c - '0'))
                return std::nullopt;
            r.tool = c - '0';
        } else if (p != c) {
            return std::nullopt;
        }
    }
    r.spec = &spec;
    r.family = family.name;
    r.code = code;
    r.direction = direction;
    if (spec.kind == ValueKind::Number || spec.kind == ValueKind::Delay) {
        r.min = resolveToken(spec.minToken, family);
        r.max = resolveToken(spec.maxToken, family);
    }
    if (!spec.defaultToken.isEmpty())
        r.factoryDefault = resolveToken(spec.defaultToken, family);
    if (spec.kind == ValueKind::Flags && direction == Direction::Write)
        r.values = spec.writeValues;
    else if (!spec.values.isEmpty())
        r.values = spec.values;
    else if (!spec.table.isEmpty())
        r.values = table(spec.table, family.name);
    return r;
}

std::optional<ResolvedCommand> Catalog::resolve(const QString &familyName, const QByteArray &code,
                                                Direction direction) const {
    const FamilyInfo *f = family(familyName);
    if (!f)
        return std::nullopt;
    for (const CommandSpec &spec : m_commands)
        if (auto r = resolveSpec(spec, *f, code.toUpper(), direction))
            return r;
    return std::nullopt;
}

QList<ResolvedCommand> Catalog::expand(const QString &familyName, Direction direction) const {
    QList<ResolvedCommand> out;
    const FamilyInfo *f = family(familyName);
    if (!f)
        return out;
    for (const CommandSpec &spec : m_commands) {
        if (!spec.families.contains(f->name) || !spec.accepts(direction))
            continue;
        QList<QByteArray> codes{spec.pattern.toLatin1()};
        if (spec.usesPort()) {
            QList<QByteArray> next;
            for (const auto &c : codes)
                for (int p = 1; p <= f->ports; ++p)
                    next.append(QByteArray(c).replace('x', QByteArray::number(p)));
            codes = next;
        }
        if (spec.usesTool()) {
            QList<QByteArray> next;
            for (const auto &c : codes)
                for (int t : f->tools)
                    next.append(QByteArray(c).replace('y', QByteArray::number(t)));
            codes = next;
        }
        for (const auto &c : codes)
            if (auto r = resolveSpec(spec, *f, c, direction))
                out.append(*r);
    }
    return out;
}

QString Catalog::familyForModel(const QString &modelName) const {
    const QString upper = modelName.trimmed().toUpper();
    for (const QString &name : m_familyOrder)
        if (upper.startsWith(name))
            return name;
    return {};
}

std::optional<ResolvedCommand> Catalog::resolve(const QString &familyName, Role role, int port,
                                                Direction direction) const {
    const CommandSpec *spec = command(role, familyName);
    if (!spec)
        return std::nullopt;
    // A port pattern ("TTx") takes the port's digit; a device's own command has no 'x'.
    QString code = spec->pattern;
    if (code.contains(QLatin1Char('x')) != (port > 0))
        return std::nullopt;
    code.replace(QLatin1Char('x'), QString::number(port));
    return resolve(familyName, code.toLatin1(), direction);
}

const CommandSpec *Catalog::command(Role role, const QString &familyName) const {
    const FamilyInfo *f = familyName.isEmpty() ? nullptr : family(familyName);
    if (role == Role::None || (!familyName.isEmpty() && !f))
        return nullptr;
    for (const CommandSpec &spec : m_commands)
        if (spec.role == role && (!f || spec.families.contains(f->name)))
            return &spec;
    return nullptr;
}

// `fallback` is a sentence with %1 for the code, marked for lupdate in the context "Catalog".
static QString lookup(const QMap<int, QString> &table, int code, const char *fallback,
                      Wording wording) {
    auto it = table.constFind(code);
    if (it != table.constEnd())
        return catalogText(it.value(), wording);
    return catalogText(QString::fromUtf8(fallback), wording).arg(code);
}

QString Catalog::nakText(int code, Wording wording) const {
    return lookup(m_tables.value(QStringLiteral("nak")), code,
                  QT_TRANSLATE_NOOP("Catalog", "Unknown NAK code %1"), wording);
}

QString Catalog::stationErrorText(const QString &familyName, int code, Wording wording) const {
    return lookup(table(QStringLiteral("$stationErrors"), familyName), code,
                  QT_TRANSLATE_NOOP("Catalog", "Unknown station error %1"), wording);
}

int Catalog::canonicalPortError(int code) const {
    return m_portErrorAliases.value(code, code);
}

QString Catalog::portErrorText(const QString &familyName, int code, Wording wording) const {
    return lookup(table(QStringLiteral("$portErrors"), familyName), canonicalPortError(code),
                  QT_TRANSLATE_NOOP("Catalog", "Unknown port error %1"), wording);
}

QString Catalog::feederErrorText(int code, Wording wording) const {
    return lookup(m_tables.value(QStringLiteral("feederErrors")), code,
                  QT_TRANSLATE_NOOP("Catalog", "Feeder error %1 (not listed in the SFR guide)"),
                  wording);
}

QString Catalog::errorAdvice(const ResolvedCommand &command, int code, Wording wording) const {
    if (code == 0 || !command.spec)
        return {};
    const QString name = command.spec->table;
    QString key = name;
    if (const FamilyInfo *f = family(command.family)) {
        if (name == QLatin1String("$portErrors")) {
            key = f->portErrors;
            code = canonicalPortError(code);
        } else if (name == QLatin1String("$stationErrors")) {
            key = f->stationErrors;
        }
    }
    const auto advice = m_advice.constFind(key);
    if (advice == m_advice.constEnd())
        return {};
    // A code the family's error table does not list gets the advice for unlisted codes, even
    // when the table the advice was taken from knows it: there it may mean something else.
    const bool listed = m_tables.value(key).contains(code);
    const QString text = listed ? advice->value(code, advice->value(-1)) : advice->value(-1);
    return text.isEmpty() ? QString() : catalogText(text, wording);
}

QString Catalog::severity(const QString &tableName, int code) const {
    if (code == 0)
        return QStringLiteral("ok");
    return m_severity.value(tableName).value(code, QStringLiteral("error"));
}

} // namespace tipscope::protocol
