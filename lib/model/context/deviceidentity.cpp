#include "deviceidentity.h"

#include <QCoreApplication>
#include <QStringList>

namespace tipscope::model {

namespace {

struct DeviceIdentityTr {
    Q_DECLARE_TR_FUNCTIONS(DeviceIdentity)
};

constexpr QChar kKeySeparator = QLatin1Char('|');
constexpr QChar kEscape = QLatin1Char('\\');
constexpr int kFields = 4;

QString escaped(const QString &field) {
    QString out;
    out.reserve(field.size());
    for (const QChar c : field) {
        if (c == kKeySeparator || c == kEscape)
            out += kEscape;
        out += c;
    }
    return out;
}

// The fields of a key, unescaped; empty when an escape is left dangling.
std::optional<QStringList> splitKey(const QString &key) {
    QStringList fields{QString()};
    for (qsizetype i = 0; i < key.size(); ++i) {
        const QChar c = key.at(i);
        if (c == kKeySeparator) {
            fields.append(QString());
        } else if (c != kEscape) {
            fields.last() += c;
        } else if (++i < key.size()) {
            fields.last() += key.at(i);
        } else {
            return std::nullopt;
        }
    }
    return fields;
}

} // namespace

QString DeviceIdentity::key() const {
    const QString addressText =
        address ? QStringLiteral("%1").arg(*address, 2, 10, QLatin1Char('0')) : QString();
    return QStringList{escaped(line), addressText, escaped(model), escaped(softwareVersion)}.join(
        kKeySeparator);
}

std::optional<DeviceIdentity> DeviceIdentity::fromKey(const QString &key) {
    const std::optional<QStringList> fields = splitKey(key);
    if (!fields || fields->size() != kFields)
        return std::nullopt;
    DeviceIdentity identity{fields->at(0), std::nullopt, fields->at(2), fields->at(3)};
    if (!fields->at(1).isEmpty()) {
        bool ok = false;
        const int address = fields->at(1).toInt(&ok);
        if (!ok || address < 0)
            return std::nullopt;
        identity.address = address;
    }
    return identity;
}

QString DeviceIdentity::description() const {
    const QString where =
        address ? DeviceIdentityTr::tr("%1 at %2").arg(model).arg(*address, 2, 10, QLatin1Char('0'))
                : model;
    const QString software = softwareVersion.isEmpty()
                                 ? DeviceIdentityTr::tr("software unknown")
                                 : DeviceIdentityTr::tr("software %1").arg(softwareVersion);
    return DeviceIdentityTr::tr("%1 on %2, %3").arg(where, line, software);
}

} // namespace tipscope::model
