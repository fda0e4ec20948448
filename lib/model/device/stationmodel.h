// StationModel: a soldering station of any family: its ports, station settings (the catalog's
// "station" group: MAT, MIT, PLM where the family has it), station error, transformer
// temperature, fuse (UCR, ALE), the ALE's dispensing settings and commands, and the dangerous
// actions, which run only with Confirmation::Confirmed. Changes of errors, alarms and port status
// go to the event log.
#pragma once

#include "devicemodel.h"
#include "model/events/problemlevel.h"
#include "portmodel.h"

namespace tipscope::model {

class StationModel : public DeviceModel {
    Q_OBJECT
public:
    StationModel(link::RequestQueue &queue, const link::DeviceInfo &info,
                 QObject *parent = nullptr);
    StationModel(link::RequestQueue &queue, const link::DeviceInfo &info,
                 const protocol::Catalog &catalog, QObject *parent = nullptr);

    [[nodiscard]] const QList<PortModel *> &ports() const { return m_ports; }
    [[nodiscard]] PortModel *port(int number) const { return m_ports.value(number - 1); }

    [[nodiscard]] QList<Parameter *> stationSettings() const;    // the "station" group
    [[nodiscard]] QList<Parameter *> dispensingSettings() const; // ALE only
    // The station's own counters (a port's are PortModel::counters()); none in today's catalog.
    [[nodiscard]] QList<Parameter *> counters() const;
    [[nodiscard]] std::optional<int> stationError() const;
    [[nodiscard]] QString stationErrorText() const;
    [[nodiscard]] Level stationErrorLevel() const; // Unknown until read
    [[nodiscard]] std::optional<qint64> transformerTemperature() const;
    [[nodiscard]] std::optional<bool> fusePresent() const; // UCR and ALE

    // W-NVS; on success the selected temperatures count as saved.
    QString saveToMemory();
    QString factoryReset(Confirmation c) { return triggerAction(protocol::Role::FactoryReset, c); }
    QString restart(Confirmation c) { return triggerAction(protocol::Role::Restart, c); }
    QString setAddress(int address, Confirmation c) {
        return triggerAction(protocol::Role::SetAddress, c, address);
    }
    QString ignoreFuseError(Confirmation c) {
        return triggerAction(protocol::Role::IgnoreFuseError, c);
    }

protected:
    void onParameterChanged(Parameter *p) override;

private:
    QString triggerAction(protocol::Role role, Confirmation c, qint64 argument = 0);
    void logChange(Parameter *p, int port);

    QList<PortModel *> m_ports;
    QMap<QByteArray, qint64> m_lastLogged;
};

} // namespace tipscope::model
