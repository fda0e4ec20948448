// Action: a command that does something rather than set a value (save to memory, factory
// reset, restart, address change, ignore fuse error, start/stop feeding, counter resets).
//
// A dangerous action runs only with Confirmation::Confirmed, so no caller can trigger a factory
// reset by accident; danger() says in plain words what will happen, for the confirmation dialog.
// Monitor-only mode refuses every action before anything reaches the wire.
#pragma once

#include "protocol/catalog.h"

#include <QObject>

namespace tipscope::model {

class DeviceModel;

enum class Confirmation { None, Confirmed };

class Action : public QObject {
    Q_OBJECT
public:
    Action(DeviceModel &device, const protocol::ResolvedCommand &command,
           QObject *parent = nullptr);

    [[nodiscard]] QByteArray code() const { return m_command.code; }
    // The catalog's words for the action, in the user interface language.
    [[nodiscard]] QString name() const { return protocol::catalogText(m_command.spec->name); }
    [[nodiscard]] QString description() const {
        return protocol::catalogText(m_command.spec->description);
    }
    [[nodiscard]] QString danger() const { return protocol::catalogText(m_command.spec->danger); }
    [[nodiscard]] bool isDangerous() const { return m_command.spec->dangerous; }
    // The values the action takes (SFD: forward/backward), labelled in the catalog's English;
    // empty for fixed-data actions.
    [[nodiscard]] QMap<int, QString> choices() const { return m_command.values; }
    [[nodiscard]] const protocol::ResolvedCommand &command() const { return m_command; }
    [[nodiscard]] bool isRunning() const { return m_running; }

    // Returns an error (and sends nothing) when refused; otherwise finished() follows.
    QString trigger(Confirmation confirmation = Confirmation::None, qint64 argument = 0);

Q_SIGNALS:
    void finished(bool ok, const QString &reason);

private:
    DeviceModel &m_device;
    protocol::ResolvedCommand m_command;
    bool m_running = false;
};

} // namespace tipscope::model
