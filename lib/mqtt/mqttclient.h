// MqttClient: one connection to an MQTT broker through libmosquitto, for the agent, the CLI and
// the GUI alike. Everything happens on the thread that owns the object; nothing blocks it.
//
// Event loop. libmosquitto runs without its own thread: MqttPump watches its socket with
// QSocketNotifiers and calls mosquitto_loop_misc once a second. Chosen over mosquitto_loop_start()
// because that thread's loop_forever() gives up for good on a TLS or DNS error and reconnects
// with a blocking connect, so this class would need to watch and restart it anyway, and every
// callback would have to cross threads. Connecting is mosquitto_connect_async(); the one blocking
// step inside it, the host-name lookup, is done first by QHostInfo on Qt's own lookup thread
// (skipped for an address literal), so a dead DNS server never freezes the caller.
//
// Contract (use it from the thread it lives in only):
// - start() (from Stopped; otherwise it does nothing) connects and keeps the connection: after any
// failure or loss it waits
//   (settings.retryMinMs, doubled each failure up to retryMaxMs, reset by a good connection)
//   and tries again, until stop(). state() and problemText() say where it stands and why.
// - stop() sends DISCONNECT (the broker then discards the will) after whatever is already
//   written; messages not yet acknowledged are forgotten (their published() never comes).
//   Destroying the client without stop() only closes the socket: the broker publishes the will,
//   as after a crash, so presence never claims a client that is gone.
// - publish() while not Connected is refused, as is any message once maxPendingMessages wait
//   to be written or acknowledged (a broker that stopped reading): nothing queues without bound.
//   Refusals return the reason and are counted (refusedCount()). What must not be lost is kept
//   by the caller (the journal) and sent again. A QoS 1/2 message already handed over when the
//   connection drops stays with libmosquitto and is sent again after reconnecting; QoS 0
//   messages not yet written then are dropped (and no longer count as pending).
// - published(id): QoS 0 when written, QoS 1 on the broker's PUBACK, QoS 2 on PUBCOMP. With
//   MQTT 5 a PUBACK carrying a failure reason emits publishRejected() instead.
// - subscribe() is remembered and sent again after every reconnect (so retained messages
//   arrive again, refreshing a view); made while disconnected it is sent on connecting.
// - Signals are emitted after libmosquitto has returned, never from inside its callbacks, so a
//   slot may call anything here, stop() included (deleteLater() rather than delete).
// - The password is never logged, and errors never contain it.
#pragma once

#include "mqttproblem.h"
#include "mqttsettings.h"
#include "mqttsetup.h"

#include <QHash>
#include <QMap>
#include <QObject>
#include <QTimer>
#include <vector>

class QHostInfo;

namespace tipscope::mqtt {

class MqttPump;
struct MqttCallbacks;

struct MqttResult {
    // The libmosquitto message id; 0 for a subscription kept until connected.
    int messageId = 0;
    // Empty on success, else why, in the user's language.
    QString error;
    [[nodiscard]] bool ok() const { return error.isEmpty(); }
};

class MqttClient : public QObject {
    Q_OBJECT
public:
    enum class State { Stopped, Connecting, Connected, WaitingToRetry, Stopping };
    Q_ENUM(State)

    explicit MqttClient(QObject *parent = nullptr);
    ~MqttClient() override;

    // Used from the next start() on.
    void setSettings(const MqttSettings &settings);
    // A client that only holds a will and publishes now and then: its socket is watched only
    // around what it sends (MqttPump::setQuiet()); what else comes is read within a second.
    void setQuiet(bool on);
    [[nodiscard]] bool watchesReads() const;
    void start();
    void stop();

    [[nodiscard]] State state() const { return m_state; }
    [[nodiscard]] MqttProblem problem() const { return m_problem.problem; }
    // Why the last attempt failed or the connection was lost; empty while connected.
    [[nodiscard]] QString problemText() const { return m_problem.text; }
    // The wait before the next attempt, while WaitingToRetry.
    [[nodiscard]] int retryDelayMs() const { return m_retryDelayMs; }
    [[nodiscard]] QString clientId() const { return m_clientId; }
    // Messages published and not yet written (QoS 0) or acknowledged (QoS 1, 2).
    [[nodiscard]] int pendingCount() const { return int(m_pending.size()); }
    [[nodiscard]] qint64 refusedCount() const { return m_refused; }

    [[nodiscard]] MqttResult publish(const QString &topic, const QByteArray &payload, int qos,
                                     bool retain);
    [[nodiscard]] MqttResult subscribe(const QString &filter, int qos = 1);
    [[nodiscard]] MqttResult unsubscribe(const QString &filter);

Q_SIGNALS:
    void stateChanged(tipscope::mqtt::MqttClient::State state);
    void connected();
    // After a connection ends; `reason` is empty after stop().
    void disconnected(const QString &reason);
    // A failed attempt or a lost connection, as a kind and a sentence for people.
    void problemOccurred(tipscope::mqtt::MqttProblem problem, const QString &text);
    void published(int messageId);
    void publishRejected(int messageId, const QString &reason);
    // The broker's SUBACK; `granted` false when it refused the filter.
    void subscribed(int messageId, bool granted);
    void messageReceived(const QString &topic, const QByteArray &payload, bool retained);

private:
    friend struct MqttCallbacks;
    struct Event;

    [[nodiscard]] QString where() const;
    void setState(State state);
    void setProblem(const MqttProblemReport &report);
    void attempt();
    void onLookedUp(const QHostInfo &info);
    void connectNow();
    void onServiced(int rc, int errnoValue);
    void onHungUp();
    void afterConnectionEnded();
    void serviceSoon();
    void scheduleRetry();
    void finishStop();
    void dispatchEvents();
    void onConnack(int code);
    void resubscribe();
    [[nodiscard]] MqttResult refuse(const QString &reason);

    MqttSettings m_settings;
    QString m_clientId;
    MosquittoHandle m_mosquitto;
    MqttPump *m_pump = nullptr;
    State m_state = State::Stopped;
    MqttProblemReport m_problem;
    QTimer m_retryTimer;
    QTimer m_stopTimer;
    int m_retryDelayMs = 0;
    int m_nextDelayMs = 0;
    int m_lookupId = -1;
    bool m_connackSeen = false;
    QHash<int, int> m_pending; // message id to QoS
    qint64 m_refused = 0;
    QMap<QString, int> m_subscriptions;
    std::vector<Event> m_events;
    QString m_tlsDetail;
};

} // namespace tipscope::mqtt
