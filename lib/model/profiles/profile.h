// Profile: every writable setting of a device, saved to a JSON file and applied to other
// stations of the same family.
//
// The file holds a format tag, a schema version, the family, model and software version it was
// taken from, the date, an optional comment, and the values as the wire's data fields, so a
// profile means exactly what goes on the wire. Schema 2 writes each value as an object that a
// person can read too: {"raw": "00350", "name": "Selected temperature, port 1", "value":
// "350 °C"}; only "raw" is applied, "name" and "value" (English, °C) are notes. Schema 1 files
// ("ST1": "00350") still load, and schema 2 takes a bare data field as well. Loading validates
// every entry against the catalog (the code exists for the family and is writable, the value
// parses and is allowed) and refuses the whole file on any error: a malformed or out-of-range
// profile writes nothing. Runtime state (port status) and actions are never part of a profile.
#pragma once

#include "base/outcome.h"

#include <QDateTime>
#include <QList>
#include <QMap>
#include <QString>
#include <optional>

namespace tipscope::model {

class DeviceModel;
class Parameter;

inline constexpr int kProfileSchema = 2; // written; 1 and 2 are read
inline constexpr int kOldestProfileSchema = 1;
inline constexpr qint64 kMaxProfileBytes = 1 << 20;

// A value as a person reads it, written beside its data field and never applied: the name with
// its tool and port, and the value with its unit, in English and °C.
struct ProfileNote {
    QString name;  // "Sleep delay, T245, port 1"
    QString value; // "10 min"
};

struct Profile {
    QString family;
    QString model;
    QString softwareVersion;
    QDateTime created;
    QString comment;
    QList<QPair<QByteArray, QByteArray>> values; // code -> data field, in apply order
    QMap<QByteArray, ProfileNote> notes;         // code -> what it means, where known

    [[nodiscard]] static bool isProfileParameter(const Parameter &p);
    // Takes every profile parameter whose value is known. Unknown values are listed in `missing`.
    [[nodiscard]] static Profile capture(const DeviceModel &device, QStringList *missing = nullptr);
    [[nodiscard]] QByteArray toJson() const;
    // Empty, or why `bytes` is too large for a profile ("2097152 bytes; a profile is at most
    // 1048576"): the one bound of files, standard input and remote requests.
    [[nodiscard]] static QString sizeProblem(qint64 bytes);
    // The reason a file is refused names the first problem; load() adds the file's name.
    [[nodiscard]] static base::Outcome<Profile> fromJson(const QByteArray &json);
    [[nodiscard]] base::Outcome<void> save(const QString &path) const; // atomic
    [[nodiscard]] static base::Outcome<Profile> load(const QString &path);
    // Entries that are not valid for `family` (empty when all are), as "CODE: why" lines.
    [[nodiscard]] QStringList problemsFor(const QString &family) const;
};

struct ProfileDifference {
    QByteArray code;
    QString name;       // with its tool and port, in the user interface language
    QString deviceText; // as people read it; "unknown" when the device did not answer
    QString profileText;
    QByteArray deviceData;
    QByteArray profileData;
};

// What would change if `profile` were applied to `device`, from the device's current values.
[[nodiscard]] QList<ProfileDifference> diffProfile(const Profile &profile,
                                                   const DeviceModel &device);

} // namespace tipscope::model
