// SimDevice: one simulated JBC device, answering requests exactly as its family's guide says.
//
// The generic part is driven by the catalog: a read of a stored setting answers its value, a
// write is checked for format (NAK 00002), catalog range and step (NAK 00003) and the family's
// own limits before it is stored, an unknown command or one the family lacks is NAK 00004, and a
// station with robot mode off answers NAK 00005. Subclasses add the live behaviour (temperatures,
// status, counters, feeding) through readLive() and applyWrite(). Time only moves in advance(),
// so tests can drive it deterministically.
#pragma once

#include "protocol/catalog.h"
#include "protocol/frame.h"
#include "protocol/valuecodec.h"

#include <QMap>
#include <QStringList>
#include <optional>

namespace tipscope::sim {

namespace proto = tipscope::protocol;

class SimDevice {
public:
    SimDevice(const QString &family, int address);
    virtual ~SimDevice() = default;
    SimDevice(const SimDevice &) = delete;
    SimDevice &operator=(const SimDevice &) = delete;

    [[nodiscard]] const proto::FamilyInfo &family() const { return *m_family; }
    [[nodiscard]] int address() const { return m_address; }
    [[nodiscard]] bool isAddressed() const { return m_addressed; }
    void setAddressed(bool on) { m_addressed = on; }
    void setAddress(int address) { m_address = address; }
    [[nodiscard]] bool robotMode() const { return m_robotMode; }
    void setRobotMode(bool on) { m_robotMode = on; }

    [[nodiscard]] QString modelName() const { return m_modelName; }
    void setModelName(const QString &name) { m_modelName = name; }
    [[nodiscard]] QString softwareVersion() const { return m_softwareVersion; }
    void setSoftwareVersion(const QString &v) { m_softwareVersion = v; }

    // The answer to a request routed to this device (addresses are the line's business).
    [[nodiscard]] proto::Frame handle(const proto::Frame &request);
    [[nodiscard]] proto::Frame nak(const QByteArray &command, int code) const;

    // Stored settings by wire code ("ST1", "A12", "MAT").
    [[nodiscard]] std::optional<qint64> setting(const QByteArray &code) const;
    void setSetting(const QByteArray &code, qint64 value) { m_settings[code] = value; }
    [[nodiscard]] const QMap<QByteArray, qint64> &settings() const { return m_settings; }
    // Every write the device accepted, as "CODE=data", oldest first (bounded).
    [[nodiscard]] const QStringList &acceptedWrites() const { return m_acceptedWrites; }

    virtual void advance(int ms) = 0;
    virtual void restoreFactorySettings();

protected:
    // A value that is computed rather than stored; nullopt to fall back to the stored settings.
    virtual std::optional<proto::Value> readLive(const proto::ResolvedCommand &cmd) = 0;
    // Side effects of an accepted write. Returns the data to answer with when the family's guide
    // names one (e.g. "00001" for the SFR's error reset); nullopt for the default answer.
    virtual std::optional<QByteArray> applyWrite(const proto::ResolvedCommand &cmd, qint64 value);
    // Extra limits from the device's current state (the selected temperature between MIT and
    // MAT); returns true when the value is acceptable.
    [[nodiscard]] virtual bool withinDeviceLimits(const proto::ResolvedCommand &cmd,
                                                  qint64 value) const;
    [[nodiscard]] qint64 settingOr(const QByteArray &code, qint64 fallback) const {
        return m_settings.value(code, fallback);
    }

    const proto::Catalog &m_catalog;

private:
    [[nodiscard]] proto::Frame answerRead(const proto::ResolvedCommand &cmd,
                                          const proto::Frame &req);
    [[nodiscard]] proto::Frame answerWrite(const proto::ResolvedCommand &cmd,
                                           const proto::Frame &req);
    [[nodiscard]] QByteArray encodeForAnswer(const proto::ResolvedCommand &cmd,
                                             const proto::Value &value) const;

    const proto::FamilyInfo *m_family;
    int m_address;
    bool m_addressed;
    bool m_robotMode = true;
    QString m_modelName;
    QString m_softwareVersion;
    QMap<QByteArray, qint64> m_settings;
    QStringList m_acceptedWrites;
};

} // namespace tipscope::sim
