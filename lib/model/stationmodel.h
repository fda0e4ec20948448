// StationModel: a soldering station of any family: its ports, station settings (MAT, MIT, PLM
// where the family has it), station error, transformer temperature, fuse (UCR, ALE), the ALE's
// dispensing settings and commands, and the dangerous actions, which run only with
// Confirmation::Confirmed. Changes of errors, alarms and port status go to the event log.
#pragma once

#include "devicemodel.h"
#include "portmodel.h"

namespace tipscope::model {

class StationModel : public DeviceModel {
    Q_OBJECT
public:
    StationModel(link::RequestQueue &queue, const link::DeviceInfo &info,
                 QObject *parent = nullptr);

    [[nodiscard]] const QList<PortModel *> &ports() const { return m_ports; }
    [[nodiscard]] PortModel *port(int number) const { return m_ports.value(number - 1); }

    [[nodiscard]] QList<Parameter *> stationSettings() const;    // MAT, MIT, PLM
    [[nodiscard]] QList<Parameter *> dispensingSettings() const; // ALE only
    [[nodiscard]] std::optional<int> stationError() const;
    [[nodiscard]] QString stationErrorText() const;
    [[nodiscard]] std::optional<qint64> transformerTemperature() const;
    [[nodiscard]] std::optional<bool> fusePresent() const; // UCR and ALE

    // W-NVS; on success the selected temperatures count as saved.
    QString saveToMemory();
    QString factoryReset(Confirmation c) { return triggerAction("RSP", c); }
    QString restart(Confirmation c) { return triggerAction("RST", c); }
    QString setAddress(int address, Confirmation c) { return triggerAction("SAD", c, address); }
    QString ignoreFuseError(Confirmation c) { return triggerAction("IFE", c); }

protected:
    void onParameterChanged(Parameter *p) override;

private:
    QString triggerAction(const char *code, Confirmation c, qint64 argument = 0);
    void logChange(Parameter *p, int port);

    QList<PortModel *> m_ports;
    QMap<QByteArray, qint64> m_lastLogged;
};

} // namespace tipscope::model
