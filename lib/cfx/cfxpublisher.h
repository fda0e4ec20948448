// CfxPublisher: a workspace's stations as IPC-CFX endpoints on one AMQP connection, the sibling
// of plant/plantpublisher.h for MQTT. It owns the sender and the journal's forwarder
// (cfxforwarder.h: faults, store and forward) and adds what describes the present and so is not
// spooled: EndpointConnected for every station once per broker connection (when the connection
// opens, or when the station is found: stationsChanged()), a Heartbeat per station every
// heartbeatS with the faults active there (CfxForwarder::activeFaults), StationStateChanged when a
// watched station's condition changes (watchStation(), stationstate.h), and EndpointShuttingDown on
// stop(). A change while the broker is away is said once it is back, from the state the broker last
// heard to the present one, its duration unknown.
//
// The endpoints are named by endpoints() (asked anew each time, so stations found later are
// included); with a request address they also answer requests (cfxrequests.h) and the journal's
// records by handleOf(); `boards` says which stations work on the board the shared work context
// names and when their joints are in (the forwarder's per-board messages). All three come from
// the front end, which knows the workspace. stop() sends the goodbyes, waits for the broker to
// accept them (at most `timeoutMs`) and emits stopped(). The journal must outlive the publisher.
#pragma once

#include "amqpsender.h"
#include "cfxforwarder.h"
#include "cfxmessages.h"
#include "cfxrequests.h"
#include "cfxsettings.h"
#include "stationstate.h"

#include <QObject>
#include <QSet>
#include <QTimer>
#include <functional>
#include <map>
#include <memory>

namespace tipscope::cfx {

class CfxPublisher : public QObject {
    Q_OBJECT
public:
    using Endpoints = std::function<QList<EndpointIdentity>()>;

    CfxPublisher(journal::Journal &journal, const CfxSettings &settings,
                 CfxForwarder::HandleOf handleOf, Endpoints endpoints,
                 CfxForwarder::Boards boards = {}, QObject *parent = nullptr);

    void start();
    void stop(int timeoutMs = 3000);
    // Stations were found or lost: the new ones say they are connected.
    void stationsChanged();
    // Follows `station`'s condition as the endpoint `handle` (once per station; forgotten when
    // the station goes).
    void watchStation(model::StationModel &station, const QString &handle);

    [[nodiscard]] AmqpSender &sender() { return m_sender; }
    [[nodiscard]] CfxForwarder &forwarder() { return m_forwarder; }

Q_SIGNALS:
    void stopped();

private:
    struct Watched {
        std::unique_ptr<StationStateWatcher> watcher;
        QString handle;
        std::optional<StationCondition> told; // what the broker last heard, or was never told
    };

    void sendToEach(const std::function<Message(const QString &handle)> &make);
    [[nodiscard]] quint64 sendNow(const QString &handle, const Message &message);
    void finishStop();
    void tellState(Watched &watched, std::optional<qint64> lastedMs);

    CfxSettings m_settings;
    [[nodiscard]] QStringList handles() const;
    [[nodiscard]] RequestPlace requestPlace() const;
    void answer(const AmqpRequest &request);

    Endpoints m_endpoints;
    AmqpSender m_sender;
    CfxForwarder m_forwarder;
    QTimer m_heartbeat;
    QTimer m_stopTimer;
    QSet<quint64> m_goodbyes;  // waiting for the broker before stopped()
    QSet<QString> m_announced; // on this connection
    std::map<const model::StationModel *, Watched> m_watched;
    bool m_stopping = false;
};

} // namespace tipscope::cfx
