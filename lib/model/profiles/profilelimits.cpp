#include "profilelimits.h"

#include "model/device/devicemodel.h"

#include <QCoreApplication>

namespace tipscope::model {

using namespace tipscope::protocol;

namespace {

struct ProfileLimitsTr {
    Q_DECLARE_TR_FUNCTIONS(ProfileLimits)
};

// A bound of the catalog: the value of `lower` may not exceed the value of `upper`.
struct Bound {
    QByteArray lower;
    QByteArray upper;
    friend bool operator==(const Bound &a, const Bound &b) {
        return a.lower == b.lower && a.upper == b.upper;
    }
};

QList<Bound> boundsOf(const DeviceModel &device) {
    QList<Bound> bounds;
    auto add = [&bounds](const QByteArray &lower, const QByteArray &upper) {
        if (!bounds.contains(Bound{lower, upper}))
            bounds.append({lower, upper});
    };
    for (const Parameter *p : device.parameters()) {
        const CommandSpec &s = p->meta();
        if (!s.limitMin.isEmpty() && device.parameter(s.limitMin.toLatin1()))
            add(s.limitMin.toLatin1(), p->code());
        if (!s.limitMax.isEmpty() && device.parameter(s.limitMax.toLatin1()))
            add(p->code(), s.limitMax.toLatin1());
    }
    return bounds;
}

std::optional<QByteArray> profileData(const Profile &profile, const QByteArray &code) {
    for (const auto &[c, data] : profile.values)
        if (c == code)
            return data;
    return std::nullopt;
}

// A setting's value once the profile is applied, and where it comes from.
struct EndValue {
    std::optional<qint64> number;
    bool fromProfile = false;
};

EndValue endValue(const Profile &profile, const Parameter &p, const QSet<QByteArray> &unread = {}) {
    if (const auto data = profileData(profile, p.code())) {
        const auto v = decodeAnswer(p.spec(), *data);
        return {v && !v->isText ? std::optional<qint64>(v->number) : std::nullopt, true};
    }
    return {unread.contains(p.code()) ? std::nullopt : p.number(), false};
}

QString describe(const Parameter &p, const EndValue &v, TemperatureUnit unit) {
    const QString where = v.fromProfile ? ProfileLimitsTr::tr("in the profile")
                                        : ProfileLimitsTr::tr("on the device now");
    return ProfileLimitsTr::tr("%1 %2 (%3)")
        .arg(QString::fromLatin1(p.code()), formatNumber(p.spec(), *v.number, unit), where);
}

bool isSpecial(const Parameter &p, qint64 v) {
    return p.meta().special.contains(int(v));
}

// Empty when the bound holds at the end.
QString check(const Bound &b, const Profile &profile, const DeviceModel &device,
              const QSet<QByteArray> &unread) {
    const Parameter &lo = *device.parameter(b.lower);
    const Parameter &hi = *device.parameter(b.upper);
    const EndValue l = endValue(profile, lo, unread);
    const EndValue h = endValue(profile, hi, unread);
    if (!l.number || !h.number) {
        const Parameter &unknown = l.number ? hi : lo;
        const Parameter &other = l.number ? lo : hi;
        return ProfileLimitsTr::tr(
                   "%1 is not known (the device did not answer), so %2 cannot be checked "
                   "against it")
            .arg(QString::fromLatin1(unknown.code()), QString::fromLatin1(other.code()));
    }
    if (isSpecial(lo, *l.number) || isSpecial(hi, *h.number) || *l.number <= *h.number)
        return {};
    const TemperatureUnit unit = device.temperatureUnit();
    return ProfileLimitsTr::tr("%1 is above %2").arg(describe(lo, l, unit), describe(hi, h, unit));
}

bool touches(const Bound &b, const Profile &profile) {
    return profileData(profile, b.lower) || profileData(profile, b.upper);
}

} // namespace

QList<QByteArray> limitRelatedCodes(const Profile &profile, const DeviceModel &device) {
    QList<QByteArray> codes;
    for (const auto &entry : profile.values)
        if (device.parameter(entry.first))
            codes.append(entry.first);
    for (const Bound &b : boundsOf(device)) {
        if (!touches(b, profile))
            continue;
        for (const QByteArray &c : {b.lower, b.upper})
            if (!codes.contains(c))
                codes.append(c);
    }
    return codes;
}

QStringList limitConflicts(const Profile &profile, const DeviceModel &device,
                           const QSet<QByteArray> &unread) {
    QStringList conflicts;
    for (const Bound &b : boundsOf(device))
        if (touches(b, profile))
            if (const QString why = check(b, profile, device, unread); !why.isEmpty())
                conflicts.append(why);
    return conflicts;
}

QList<QByteArray> limitSafeOrder(const QList<QByteArray> &codes, const Profile &profile,
                                 const DeviceModel &device) {
    // A code only ever on the lower side of a bound (MIT) widens what is allowed by going down,
    // one only on the upper side (MAT) by going up; one on both sides (STx) is what is bounded.
    const QList<Bound> bounds = boundsOf(device);
    auto onSide = [&bounds](const QByteArray &code, bool asLower) {
        return std::any_of(bounds.begin(), bounds.end(), [&](const Bound &b) {
            return (asLower ? b.lower : b.upper) == code && (asLower ? b.upper : b.lower) != code;
        });
    };
    QList<QByteArray> widen, middle, narrow;
    for (const QByteArray &code : codes) {
        const Parameter *p = device.parameter(code);
        const bool lower = p && onSide(code, true) && !onSide(code, false);
        const bool upper = p && onSide(code, false) && !onSide(code, true);
        const auto now = p ? p->number() : std::nullopt;
        const auto end = p ? endValue(profile, *p).number : std::nullopt;
        if ((!lower && !upper) || !now || !end)
            middle.append(code);
        else if (lower == (*end < *now)) // a lower bound going down, an upper one going up
            widen.append(code);
        else
            narrow.append(code);
    }
    return widen + middle + narrow;
}

} // namespace tipscope::model
