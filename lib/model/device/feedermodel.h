// FeederModel: the SFR solder feeder: feeding settings (the catalog's "feeder" group: mode,
// speed, length, wire thickness, switch input), live feeding status and fed length, the error
// code with its reset, total and partial counters with the partial resets, and the feeding
// commands (start forward or backward, stop, loading). Error changes go to the event log.
#pragma once

#include "devicemodel.h"
#include "model/events/problemlevel.h"

namespace tipscope::model {

class FeederModel : public DeviceModel {
    Q_OBJECT
public:
    // The counters as a table shows them: what is counted (the catalog's English "quantity",
    // or the counter's name), its total and its partial counter as the catalog pairs them
    // (either may be missing), and the action that resets the partial.
    struct CounterRow {
        QString quantity;
        Parameter *total = nullptr;
        Parameter *partial = nullptr;
        Action *reset = nullptr;
    };

    FeederModel(link::RequestQueue &queue, const link::DeviceInfo &info, QObject *parent = nullptr);
    FeederModel(link::RequestQueue &queue, const link::DeviceInfo &info,
                const protocol::Catalog &catalog, QObject *parent = nullptr);

    [[nodiscard]] QList<Parameter *> settings() const; // what the feeder group can set
    [[nodiscard]] QList<Parameter *> counters() const; // totals and partials
    [[nodiscard]] QList<CounterRow> counterRows() const;
    [[nodiscard]] QList<Parameter *> liveParameters() const; // feeding status, fed length
    [[nodiscard]] std::optional<bool> isFeeding() const;
    [[nodiscard]] std::optional<qint64> fedLength() const; // tenths of a millimetre
    [[nodiscard]] std::optional<qint64> feedSpeed() const; // tenths of a millimetre a second
    [[nodiscard]] std::optional<int> errorCode() const;
    [[nodiscard]] QString errorText() const;
    [[nodiscard]] Level errorLevel() const; // Unknown until read

    QString startFeeding(bool forward) {
        return trigger(protocol::Role::Start, Confirmation::None, forward ? 1 : 0);
    }
    QString stopFeeding() { return trigger(protocol::Role::Stop); }
    QString setLoading(bool on) {
        return trigger(protocol::Role::Loading, Confirmation::None, on ? 1 : 0);
    }
    QString resetError() { return trigger(protocol::Role::ResetError); }
    // The reset of a partial counter (the action with the counter's code); it needs a
    // confirmation.
    QString resetPartialCounter(const QByteArray &code, Confirmation c);
    QString saveToMemory() { return trigger(protocol::Role::SaveToMemory); }

protected:
    void onParameterChanged(Parameter *p) override;

private:
    QString trigger(protocol::Role role, Confirmation c = Confirmation::None, qint64 arg = 0);
    QString trigger(Action *action, const QString &name, Confirmation c, qint64 arg);
    std::optional<qint64> m_lastError;
};

} // namespace tipscope::model
