// AmqpSender: one AMQP 1.0 connection to a plant's broker, with one sending link to the CFX
// exchange, run by Qpid Proton C++ on a thread of its own. Polling and journaling run on the Qt
// event loop and never wait for the broker: send() hands a message over and returns at once; a
// slow, refusing or absent broker only delays the signals.
//
// Contract: accepted(tag) says the broker settled the message as accepted, the only moment it
// counts as sent; refused(tag, why) says it rejected or released it. disconnected() says every
// message handed over and not yet settled is forgotten: the caller sends it again after the next
// connected() (the journal is the spool, journal-side code keeps the order and the UniqueID).
// A message handed over under an older connection is never sent on a newer one, so a message
// is not sent twice because the link came back while it waited.
//
// Reconnection: after a failed attempt or a lost connection the sender waits retryMinMs, then
// twice as long after each further failure, up to retryMaxMs; a connection that opened resets the
// wait. Each failed attempt emits problem() in words that say what to fix (a refused login,
// nothing listening, a broker without AMQP 1.0, an exchange that does not exist); a front end
// says it once until connected() (as the agent does for MQTT).
// RabbitMQ's addresses keep their leading slash: the link is opened on the connection with the
// whole address, never written into the connection URL.
//
// Requests: with a requestAddress the sender also takes messages from that queue, each at most
// kMaxRequestBytes (a larger one is rejected unread), and hands them over as requestReceived();
// reply() sends an answer to the address a request named, on a link of its own (at most
// kMaxReplyLinks at a time, the oldest closed first). Answers are not spooled: a request whose
// answer is lost is asked again, as CFX's requesters do.
//
// The password lives in Settings only; it is never logged nor put into a problem text.
#pragma once

#include "cfxenvelope.h"

#include <QObject>
#include <QString>
#include <memory>

namespace tipscope::cfx {

class AmqpSender : public QObject {
    Q_OBJECT
public:
    struct Settings {
        QString host = QStringLiteral("localhost");
        int port = 5672;
        bool tls = false;
        QString caFile;   // TLS: the CA that signed the broker's certificate
        QString certFile; // TLS: this client's certificate and key, both or neither
        QString keyFile;
        QString user; // empty: anonymous
        QByteArray password;
        QString address = QStringLiteral("/exchange/amq.topic");
        QString requestAddress; // empty: no requests are taken
        int retryMinMs = 1000;
        int retryMaxMs = 60000;
    };
    enum class State { Stopped, Connecting, Connected, WaitingToRetry };
    Q_ENUM(State)
    static constexpr int kMaxReplyLinks = 8;

    using Request = AmqpRequest;

    explicit AmqpSender(QObject *parent = nullptr);
    ~AmqpSender() override; // stops the thread, abandoning what was not settled

    void start(const Settings &settings);
    void stop();

    // Hands a message over; 0 when not connected (nothing is queued then). Else its tag for
    // accepted() or refused().
    [[nodiscard]] quint64 send(const AmqpMessage &message);
    // Sends an answer to `address` (a request's reply-to) while connected; dropped otherwise.
    void reply(const QString &address, const AmqpMessage &message);

    [[nodiscard]] State state() const { return m_state; }
    // "amqp://host:port" or "amqps://host:port", for messages.
    [[nodiscard]] QString where() const;

Q_SIGNALS:
    void stateChanged(tipscope::cfx::AmqpSender::State state);
    void connected();
    void disconnected(const QString &reason);
    void problem(const QString &text);
    void accepted(quint64 tag);
    void refused(quint64 tag, const QString &reason);
    void requestReceived(const tipscope::cfx::AmqpRequest &request);

private:
    class Engine;
    friend class Engine;
    void setState(State state);
    void onOpened(int generation);
    void onLost(int generation, const QString &reason, bool retrying);

    Settings m_settings;
    std::unique_ptr<Engine> m_engine;
    State m_state = State::Stopped;
    int m_generation = 0; // the connection the Qt side believes is open
    quint64 m_nextTag = 0;
};

} // namespace tipscope::cfx
