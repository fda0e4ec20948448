// FeederModel: the SFR solder feeder: feeding settings (mode, speed, length, wire thickness,
// switch input), live feeding status and fed length, the error code with its reset, total and
// partial counters with the partial resets, and the feeding commands (start forward or
// backward, stop, loading). Error changes go to the event log.
#pragma once

#include "devicemodel.h"

namespace tipscope::model {

class FeederModel : public DeviceModel {
    Q_OBJECT
public:
    FeederModel(link::RequestQueue &queue, const link::DeviceInfo &info, QObject *parent = nullptr);

    [[nodiscard]] QList<Parameter *> settings() const;       // MOD, SPD, LEN, THI, TES
    [[nodiscard]] QList<Parameter *> counters() const;       // CPT, CPP, CFT, CFP, CTT, CTP
    [[nodiscard]] QList<Parameter *> liveParameters() const; // FDS, FDL
    [[nodiscard]] std::optional<bool> isFeeding() const;
    [[nodiscard]] std::optional<qint64> fedLength() const; // tenths of a millimetre
    [[nodiscard]] std::optional<int> errorCode() const;
    [[nodiscard]] QString errorText() const;

    QString startFeeding(bool forward) {
        return trigger("SFD", Confirmation::None, forward ? 1 : 0);
    }
    QString stopFeeding() { return trigger("SSD"); }
    QString setLoading(bool on) { return trigger("SLD", Confirmation::None, on ? 1 : 0); }
    QString resetError() { return trigger("ECV"); }
    // CPP, CFP or CTP; a counter reset needs a confirmation.
    QString resetPartialCounter(const QByteArray &code, Confirmation c) { return trigger(code, c); }
    QString saveToMemory() { return trigger("NVS"); }

protected:
    void onParameterChanged(Parameter *p) override;

private:
    QString trigger(const QByteArray &code, Confirmation c = Confirmation::None, qint64 arg = 0);
    std::optional<qint64> m_lastError;
};

} // namespace tipscope::model
