#include "action.h"

#include "devicemodel.h"
#include "parameter.h"

#include "protocol/valuecodec.h"

#include <QCoreApplication>

namespace tipscope::model {

using namespace tipscope::link;
using namespace tipscope::protocol;

namespace {
struct ActionTr {
    Q_DECLARE_TR_FUNCTIONS(Action)
};
} // namespace

Action::Action(DeviceModel &device, const ResolvedCommand &command, QObject *parent)
    : QObject(parent)
    , m_device(device)
    , m_command(command) {}

QString Action::trigger(Confirmation confirmation, qint64 argument) {
    if (m_device.writesBlocked())
        return ActionTr::tr("monitor-only mode is on: nothing is written");
    if (isDangerous() && confirmation != Confirmation::Confirmed)
        return ActionTr::tr("%1 needs an explicit confirmation: %2").arg(name(), danger());
    if (m_running)
        return ActionTr::tr("%1 is already running").arg(name());
    const auto data = encodeWrite(m_command, argument);
    if (!data)
        return data.error();
    m_running = true;
    Reply *reply = m_device.queue().enqueue(
        Request::write(m_device.address(), m_command.code, *data, !isDangerous()), this);
    connect(reply, &Reply::finished, this, [this, reply] {
        reply->deleteLater();
        m_running = false;
        if (reply->ok()) {
            m_device.logWrite(m_command.port, ActionTr::tr("%1 done").arg(name()));
            // A reset's result is worth seeing at once (ECV, CPP, CFP, CTP share their code).
            if (Parameter *same = m_device.parameter(code()))
                same->refresh();
            Q_EMIT finished(true, {});
        } else {
            m_device.logCommunication(name(), reply->errorString());
            Q_EMIT finished(false, reply->errorString());
        }
    });
    return {};
}

} // namespace tipscope::model
