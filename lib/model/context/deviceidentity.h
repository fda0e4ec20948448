// DeviceIdentity: which device a record belongs to, as the line and the device itself say it.
//
// The line is how the device is reached (a serial port path, preferably its /dev/serial/by-id
// name, or host:port for TCP); the address is the device's bus address (none when it answers
// frames without addresses); model and software version are what R-SMN and R-SVR answered.
// key() is a stable text for files and databases: the four fields joined by '|', with '\' and
// '|' inside a field escaped by '\', and the address as two digits or empty:
//     "/dev/serial/by-id/usb-FTDI_A1-if00-port0|01|DME-2C|9996780"
// fromKey() reads it back. Histories are keyed by it, so a device whose software changed counts
// as another device: its records before and after the update stay apart.
#pragma once

#include <QHashFunctions>
#include <QString>
#include <optional>

namespace tipscope::model {

struct DeviceIdentity {
    QString line;
    std::optional<int> address;
    QString model;
    QString softwareVersion;

    [[nodiscard]] QString key() const;
    // For people, whose history a view shows: "DME-2C at 01 on /dev/ttyUSB0, software 9996780".
    [[nodiscard]] QString description() const;
    [[nodiscard]] static std::optional<DeviceIdentity> fromKey(const QString &key);
    // No line: a record about no device in particular (a context change, the journal itself).
    [[nodiscard]] bool isEmpty() const { return line.isEmpty(); }

    friend bool operator==(const DeviceIdentity &a, const DeviceIdentity &b) {
        return a.line == b.line && a.address == b.address && a.model == b.model &&
               a.softwareVersion == b.softwareVersion;
    }
    friend bool operator!=(const DeviceIdentity &a, const DeviceIdentity &b) { return !(a == b); }
};

inline size_t qHash(const DeviceIdentity &identity, size_t seed = 0) {
    return qHash(identity.key(), seed);
}

} // namespace tipscope::model
