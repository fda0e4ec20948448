#include "valuecodec.h"

#include "base/elide.h"
#include "datafield.h"

#include <QCoreApplication>
#include <cmath>

namespace tipscope::protocol {

namespace {
struct ValueCodecTr {
    Q_DECLARE_TR_FUNCTIONS(ValueCodec)
};
} // namespace

static QString joinSpecials(const QMap<int, QString> &special) {
    QStringList names;
    for (const auto &label : special)
        names.append(catalogText(label));
    return names.join(QLatin1String(", "));
}

static QString formatNumber(const ResolvedCommand &cmd, qint64 v) {
    if (cmd.spec->kind == ValueKind::Delay)
        return QString::number(v / 100.0, 'f', 2);
    return QString::number(v);
}

QString wireUnitSymbol(const ResolvedCommand &cmd) {
    if (cmd.spec->kind == ValueKind::Delay)
        return QStringLiteral("s");
    const Unit *u = Catalog::builtin().unit(cmd.spec->unit);
    return u ? u->symbol : QString();
}

QString allowedText(const ResolvedCommand &cmd) {
    const CommandSpec &s = *cmd.spec;
    switch (s.kind) {
    case ValueKind::Number:
    case ValueKind::Delay: {
        QString unit = wireUnitSymbol(cmd);
        QString t = ValueCodecTr::tr("%1 to %2%3")
                        .arg(formatNumber(cmd, cmd.min), formatNumber(cmd, cmd.max),
                             unit.isEmpty() ? QString() : QLatin1Char(' ') + unit);
        if (s.step > 1)
            t += ValueCodecTr::tr(" in steps of %1").arg(s.step);
        if (!s.special.isEmpty())
            t += ValueCodecTr::tr(", or %1").arg(joinSpecials(s.special));
        return t;
    }
    case ValueKind::Enum:
    case ValueKind::Flags: {
        QStringList items;
        for (auto it = cmd.values.begin(); it != cmd.values.end(); ++it)
            items.append(QStringLiteral("%1 (%2)").arg(it.key()).arg(catalogText(it.value())));
        return ValueCodecTr::tr("one of %1").arg(items.join(QLatin1String(", ")));
    }
    case ValueKind::Action:
        return ValueCodecTr::tr("no value (the command carries %1)")
            .arg(QString::fromLatin1(s.fixedData));
    case ValueKind::Hex:
    case ValueKind::Text:
        return ValueCodecTr::tr("nothing: it is read-only");
    }
    return {};
}

static QString refused(const ResolvedCommand &cmd, qint64 value) {
    return ValueCodecTr::tr("%1 refused for %2 (%3): allowed is %4")
        .arg(formatNumber(cmd, value), QString::fromLatin1(cmd.code), catalogText(cmd.spec->name),
             allowedText(cmd));
}

QString validate(const ResolvedCommand &cmd, qint64 value) {
    const CommandSpec &s = *cmd.spec;
    const QString code = QString::fromLatin1(cmd.code);
    if (cmd.direction != Direction::Write || !s.writable)
        return ValueCodecTr::tr("%1 cannot be written").arg(code);
    switch (s.kind) {
    case ValueKind::Action:
        return {};
    case ValueKind::Hex:
    case ValueKind::Text:
        return ValueCodecTr::tr("%1 cannot be written").arg(code);
    case ValueKind::Enum:
    case ValueKind::Flags:
        if (cmd.values.contains(int(value)) && value == qint64(int(value)))
            return {};
        break;
    case ValueKind::Number:
    case ValueKind::Delay:
        if (s.special.contains(int(value)) && value == qint64(int(value)))
            return {};
        if (value >= cmd.min && value <= cmd.max && (value - cmd.min) % s.step == 0)
            return {};
        break;
    }
    return refused(cmd, value);
}

QString validateData(const ResolvedCommand &cmd, const QByteArray &data) {
    const ValueKind k = cmd.spec->kind;
    if (k == ValueKind::Action || k == ValueKind::Hex || k == ValueKind::Text)
        return {};
    if (const auto v = decodeAnswer(cmd, data))
        return validate(cmd, v->number);
    return ValueCodecTr::tr("'%1' is no data field of %2 (%3): allowed is %4")
        .arg(base::elided(QString::fromLatin1(data)), QString::fromLatin1(cmd.code),
             catalogText(cmd.spec->name), allowedText(cmd));
}

base::Outcome<QByteArray> encodeWrite(const ResolvedCommand &cmd, qint64 value) {
    if (const QString why = validate(cmd, value); !why.isEmpty())
        return base::failure(why);
    const CommandSpec &s = *cmd.spec;
    if (s.kind == ValueKind::Action)
        return s.fixedData;
    const bool delay = s.kind == ValueKind::Delay && !s.special.contains(int(value));
    // Only a catalog range wider than the data field lets a valid value fail here.
    if (const auto field = delay ? encodeDelay(int(value)) : encodeNumber(value))
        return *field;
    return base::failure(refused(cmd, value));
}

std::optional<Value> decodeAnswer(const ResolvedCommand &cmd, const QByteArray &data) {
    const CommandSpec &s = *cmd.spec;
    switch (s.kind) {
    case ValueKind::Text:
        if (auto t = parseText(data))
            return Value::ofText(*t);
        return std::nullopt;
    case ValueKind::Hex:
        if (auto h = parseHex(data))
            return Value::ofNumber(qint64(*h));
        return std::nullopt;
    case ValueKind::Delay:
        if (auto d = parseDelay(data))
            return Value::ofNumber(*d);
        if (auto n = parseNumber(data); n && s.special.contains(*n))
            return Value::ofNumber(*n);
        return std::nullopt;
    case ValueKind::Number:
    case ValueKind::Enum:
    case ValueKind::Flags:
    case ValueKind::Action:
        if (auto n = parseNumber(data))
            return Value::ofNumber(*n);
        return std::nullopt;
    }
    return std::nullopt;
}

static std::optional<qint64> parseDelayText(const QString &t) {
    if (auto d = parseDelay(t.toLatin1()))
        return *d;
    bool ok = false;
    const double seconds = t.toDouble(&ok);
    if (!ok || !std::isfinite(seconds) || seconds < 0 || seconds > 99.99)
        return std::nullopt;
    const qint64 centis = qRound64(seconds * 100);
    if (qAbs(seconds * 100 - double(centis)) > 1e-6)
        return std::nullopt; // finer than hundredths cannot be sent
    return centis;
}

std::optional<qint64> labelled(const QMap<int, QString> &labels, const QString &text) {
    for (auto it = labels.begin(); it != labels.end(); ++it) {
        if (it.value().isEmpty())
            continue;
        if (text.compare(it.value(), Qt::CaseInsensitive) == 0 ||
            text.compare(catalogText(it.value()), Qt::CaseInsensitive) == 0)
            return it.key();
    }
    return std::nullopt;
}

base::Outcome<qint64> parseUserValue(const ResolvedCommand &cmd, const QString &text) {
    const CommandSpec &s = *cmd.spec;
    const QString t = text.trimmed();
    if (s.kind == ValueKind::Action)
        return 0;
    if (auto special = labelled(s.special, t))
        return *special;
    if (auto choice = labelled(cmd.values, t))
        return *choice;
    if (s.kind == ValueKind::Delay) {
        if (auto n = parseNumber(t.toLatin1()); n && s.special.contains(*n))
            return *n;
        if (auto d = parseDelayText(t))
            return *d;
        return base::failure(ValueCodecTr::tr("'%1' is not a delay in seconds such as 1.6 or 01.60")
                                 .arg(base::elided(t)));
    }
    bool ok = false;
    const qint64 v = t.toLongLong(&ok);
    if (!ok)
        return base::failure(
            ValueCodecTr::tr("'%1' is not a whole number; %2 takes %3")
                .arg(base::elided(t), QString::fromLatin1(cmd.code), allowedText(cmd)));
    return v;
}

QStringList flagLabels(const QList<DigitField> &digits, qint64 value, Wording wording) {
    QStringList labels;
    for (const DigitField &d : digits) {
        qint64 div = 1;
        for (int i = 0; i < d.digit; ++i)
            div *= 10;
        const int digit = int((value / div) % 10);
        // A digit the catalog does not know is shown by its field's name: "motor 7?".
        const auto it = d.values.constFind(digit);
        const QString label = it == d.values.constEnd()
                                  ? QStringLiteral("%1 %2?").arg(d.name).arg(digit)
                                  : catalogText(it.value(), wording);
        if (!label.isEmpty())
            labels.append(label);
    }
    return labels;
}

QString describeValue(const ResolvedCommand &cmd, const Value &value, Wording wording) {
    const CommandSpec &s = *cmd.spec;
    if (value.isText)
        return value.text;
    if (s.special.contains(int(value.number)))
        return catalogText(s.special.value(int(value.number)), wording);
    switch (s.kind) {
    case ValueKind::Delay:
        return QString::number(value.number / 100.0, 'f', 2);
    case ValueKind::Enum: {
        if (s.table == QLatin1String("$portErrors"))
            return Catalog::builtin().portErrorText(cmd.family, int(value.number), wording);
        const auto it = cmd.values.constFind(int(value.number));
        if (it != cmd.values.constEnd())
            return catalogText(it.value(), wording);
        return catalogText(QString::fromUtf8(QT_TRANSLATE_NOOP("Catalog", "unknown (%1)")), wording)
            .arg(value.number);
    }
    case ValueKind::Flags: {
        const QStringList labels =
            flagLabels(Catalog::builtin().digits(s.digitsTable), value.number, wording);
        return labels.isEmpty()
                   ? catalogText(QString::fromUtf8(QT_TRANSLATE_NOOP("Catalog", "none")), wording)
                   : labels.join(QLatin1String(", "));
    }
    default:
        return QString::number(value.number);
    }
}

} // namespace tipscope::protocol
