#include "profile.h"

#include "model/device/devicemodel.h"
#include "profilejson.h"

#include "base/atomicsave.h"
#include "base/elide.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>

namespace tipscope::model {

using namespace tipscope::protocol;

namespace {
struct ProfileTr {
    Q_DECLARE_TR_FUNCTIONS(Profile)
};
const QLatin1String kFormat("tipscope-profile");
const QString kRaw = QStringLiteral("raw");
const QString kName = QStringLiteral("name");
const QString kValue = QStringLiteral("value");

// The value in English and °C, whatever the user interface shows: the file is data.
QString noteValue(const ResolvedCommand &cmd, const Value &v) {
    if (v.isText)
        return v.text;
    if (cmd.spec->special.contains(int(v.number)))
        return cmd.spec->special.value(int(v.number));
    if (cmd.spec->kind != ValueKind::Number && cmd.spec->kind != ValueKind::Delay)
        return describeValue(cmd, v, Wording::Catalog);
    const DisplayFormat f = displayFormat(cmd, TemperatureUnit::Celsius);
    const QString number =
        QString::number(toDisplay(cmd, v.number, TemperatureUnit::Celsius), 'f', f.decimals);
    return f.unit.isEmpty() ? number : number + QLatin1Char(' ') + f.unit;
}

// One entry of "values": a data field in quotes or, from schema 2, an object with it in "raw".
std::optional<QByteArray> rawOf(const QJsonValue &v, int schema, ProfileNote *note) {
    if (v.isString())
        return v.toString().toLatin1();
    if (schema < 2 || !v.isObject())
        return std::nullopt;
    const QJsonObject o = v.toObject();
    for (const QString &key : {kName, kValue})
        if (o.contains(key) && !o.value(key).isString())
            return std::nullopt;
    if (!o.value(kRaw).isString())
        return std::nullopt;
    *note = {o.value(kName).toString(), o.value(kValue).toString()};
    return o.value(kRaw).toString().toLatin1();
}
} // namespace

bool Profile::isProfileParameter(const Parameter &p) {
    return p.isReadable() && p.isWritable() && p.meta().kind != ValueKind::Flags &&
           p.meta().kind != ValueKind::Action;
}

Profile Profile::capture(const DeviceModel &device, QStringList *missing) {
    Profile pr;
    pr.family = device.family();
    pr.model = device.info().model;
    pr.softwareVersion = device.info().softwareVersion;
    pr.created = QDateTime::currentDateTime();
    for (const Parameter *p : device.parameters()) {
        if (!isProfileParameter(*p))
            continue;
        if (p->rawValue().isEmpty()) {
            if (missing)
                missing->append(QString::fromLatin1(p->code()));
            continue;
        }
        pr.values.append({p->code(), p->rawValue()});
        pr.notes.insert(p->code(), {device.qualifiedLabel(*p, Wording::Catalog),
                                    noteValue(p->spec(), *p->value())});
    }
    return pr;
}

QByteArray Profile::toJson() const {
    QJsonObject root{{QStringLiteral("format"), kFormat},
                     {QStringLiteral("schema"), kProfileSchema},
                     {QStringLiteral("family"), family},
                     {QStringLiteral("model"), model},
                     {QStringLiteral("softwareVersion"), softwareVersion},
                     {QStringLiteral("created"), created.toString(Qt::ISODateWithMs)},
                     {QStringLiteral("comment"), comment}};
    QJsonObject v;
    for (const auto &[code, data] : values) {
        QJsonObject entry{{kRaw, QString::fromLatin1(data)}};
        if (const auto note = notes.find(code); note != notes.end()) {
            entry.insert(kName, note->name);
            entry.insert(kValue, note->value);
        }
        v.insert(QString::fromLatin1(code), entry);
    }
    root.insert(QStringLiteral("values"), v);
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

QStringList Profile::problemsFor(const QString &fam) const {
    QStringList problems;
    const Catalog &cat = Catalog::builtin();
    for (const auto &[code, data] : values) {
        const QString c = base::elided(QString::fromLatin1(code));
        const auto w = cat.resolve(fam, code, Direction::Write);
        const auto r = cat.resolve(fam, code, Direction::Read);
        if (!w || !r || w->spec->kind == ValueKind::Flags || w->spec->kind == ValueKind::Action) {
            problems.append(ProfileTr::tr("%1: not a setting of a %2").arg(c, fam));
            continue;
        }
        const auto v = decodeAnswer(*r, data);
        if (!v || v->isText) {
            problems.append(ProfileTr::tr("%1: '%2' is not a valid data field")
                                .arg(c, base::elided(QString::fromLatin1(data))));
            continue;
        }
        if (const QString why = validate(*w, v->number); !why.isEmpty())
            problems.append(ProfileTr::tr("%1: %2").arg(c, why));
    }
    return problems;
}

QString Profile::sizeProblem(qint64 bytes) {
    if (bytes <= kMaxProfileBytes)
        return {};
    return ProfileTr::tr("%1 bytes; a profile is at most %2").arg(bytes).arg(kMaxProfileBytes);
}

base::Outcome<Profile> Profile::fromJson(const QByteArray &json) {
    const auto fail = [](const QString &why) { return base::failure(why); };
    // Every way in (a file, a FIFO, a broker's message) meets the same bound.
    if (const QString why = sizeProblem(json.size()); !why.isEmpty())
        return fail(why);
    // Qt takes a NUL inside a string, and keeps the last of two equal keys: both are refused.
    if (const QString why = profilejson::controlCharacterProblem(json); !why.isEmpty())
        return fail(ProfileTr::tr("not a valid JSON file: %1").arg(why));
    QJsonParseError pe;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &pe);
    if (pe.error != QJsonParseError::NoError)
        return fail(ProfileTr::tr("not a valid JSON file: %1 at byte %2")
                        .arg(pe.errorString())
                        .arg(pe.offset));
    if (const QStringList twice = profilejson::duplicateKeys(json); !twice.isEmpty()) {
        QStringList shown;
        for (const QString &key : twice)
            shown.append(base::elided(key));
        return fail(ProfileTr::tr("given more than once, so which value is meant is unclear: %1; "
                                  "nothing will be written")
                        .arg(shown.join(QLatin1String(", "))));
    }
    const QJsonObject root = doc.object();
    if (!doc.isObject() || root.value(QStringLiteral("format")).toString() != kFormat)
        return fail(ProfileTr::tr("not a TipScope profile (no \"format\": \"tipscope-profile\")"));
    const int schema = root.value(QStringLiteral("schema")).toInt(-1);
    if (schema < kOldestProfileSchema || schema > kProfileSchema)
        return fail(ProfileTr::tr(
                        "profile schema %1 is not supported (this version reads schemas %2 to %3)")
                        .arg(schema)
                        .arg(kOldestProfileSchema)
                        .arg(kProfileSchema));
    Profile p;
    p.family = root.value(QStringLiteral("family")).toString().toUpper();
    if (!Catalog::builtin().family(p.family))
        return fail(ProfileTr::tr("unknown device family '%1'").arg(base::elided(p.family)));
    p.model = root.value(QStringLiteral("model")).toString();
    p.softwareVersion = root.value(QStringLiteral("softwareVersion")).toString();
    p.created =
        QDateTime::fromString(root.value(QStringLiteral("created")).toString(), Qt::ISODateWithMs);
    p.comment = root.value(QStringLiteral("comment")).toString();
    const QJsonValue values = root.value(QStringLiteral("values"));
    if (!values.isObject() || values.toObject().isEmpty())
        return fail(ProfileTr::tr("the profile has no values"));
    const QJsonObject v = values.toObject();
    for (auto it = v.begin(); it != v.end(); ++it) {
        ProfileNote note;
        const auto raw = rawOf(it.value(), schema, &note);
        if (!raw && schema < 2)
            return fail(
                ProfileTr::tr("%1: the value must be a data field in quotes, e.g. \"00350\"")
                    .arg(base::elided(it.key())));
        if (!raw)
            return fail(
                ProfileTr::tr("%1: the value must be a data field in quotes, e.g. \"00350\", "
                              "or an object with one in \"raw\" (and text in \"name\" and "
                              "\"value\")")
                    .arg(base::elided(it.key())));
        const QByteArray code = it.key().toUpper().toLatin1();
        p.values.append({code, *raw});
        if (!note.name.isEmpty() || !note.value.isEmpty())
            p.notes.insert(code, note);
    }
    const QStringList problems = p.problemsFor(p.family);
    if (!problems.isEmpty())
        return fail(ProfileTr::tr("the profile is refused, nothing will be written:\n%1")
                        .arg(problems.join(QLatin1Char('\n'))));
    return p;
}

base::Outcome<void> Profile::save(const QString &path) const {
    return base::io::saveAtomically(path, toJson());
}

base::Outcome<Profile> Profile::load(const QString &path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return base::failure(
            ProfileTr::tr("cannot read %1: %2").arg(base::elidedPath(path), f.errorString()));
    // Read at most one byte more than allowed: size() is 0 for a FIFO or standard input.
    const QByteArray bytes = f.read(kMaxProfileBytes + 1);
    if (bytes.size() > kMaxProfileBytes)
        return base::failure(
            ProfileTr::tr("%1 is %2")
                .arg(base::elidedPath(path), sizeProblem(qMax<qint64>(f.size(), bytes.size()))));
    auto p = fromJson(bytes);
    if (!p.ok())
        return base::failure(ProfileTr::tr("%1: %2").arg(base::elidedPath(path), p.error()));
    return p;
}

QList<ProfileDifference> diffProfile(const Profile &profile, const DeviceModel &device) {
    QList<ProfileDifference> out;
    for (const auto &[code, data] : profile.values) {
        const Parameter *p = device.parameter(code);
        if (!p || !Profile::isProfileParameter(*p))
            continue;
        const auto want = decodeAnswer(p->spec(), data);
        const auto have = p->value();
        if (want && have && *want == *have)
            continue;
        const TemperatureUnit t = device.temperatureUnit();
        out.append({code, device.qualifiedLabel(*p),
                    have ? formatValue(p->spec(), *have, t) : ProfileTr::tr("unknown"),
                    want ? formatValue(p->spec(), *want, t) : QString::fromLatin1(data),
                    p->rawValue(), data});
    }
    return out;
}

} // namespace tipscope::model
