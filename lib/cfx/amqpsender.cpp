#include "amqpsender.h"

#include "amqpproblem.h"

#include <QCoreApplication>
#include <QLoggingCategory>
#include <QPointer>

#include <proton/connection.hpp>
#include <proton/connection_options.hpp>
#include <proton/container.hpp>
#include <proton/delivery.hpp>
#include <proton/delivery_mode.hpp>
#include <proton/error_condition.hpp>
#include <proton/message.hpp>
#include <proton/message_id.hpp>
#include <proton/messaging_handler.hpp>
#include <proton/receiver.hpp>
#include <proton/receiver_options.hpp>
#include <proton/sender.hpp>
#include <proton/sender_options.hpp>
#include <proton/session.hpp>
#include <proton/ssl.hpp>
#include <proton/tracker.hpp>
#include <proton/transport.hpp>
#include <proton/work_queue.hpp>

#include <atomic>
#include <cstring>
#include <deque>
#include <list>
#include <mutex>
#include <optional>
#include <thread>

Q_LOGGING_CATEGORY(lcAmqp, "tipscope.cfx.amqp")

namespace tipscope::cfx {

namespace {

std::string utf8(const QString &text) {
    return text.toStdString();
}

QString text(const std::string &bytes) {
    return QString::fromStdString(bytes);
}

// A request's body: one Data section, or a string as some clients send; anything else is none.
std::optional<QByteArray> bodyOf(const proton::message &message) {
    const proton::value &body = message.body();
    if (body.type() == proton::BINARY) {
        const auto bytes = proton::get<proton::binary>(body);
        return QByteArray(reinterpret_cast<const char *>(bytes.data()), qsizetype(bytes.size()));
    }
    if (body.type() == proton::STRING)
        return QByteArray::fromStdString(proton::get<std::string>(body));
    return std::nullopt;
}

proton::binary tagBytes(quint64 tag) {
    proton::binary bytes(sizeof tag, 0);
    std::memcpy(bytes.data(), &tag, sizeof tag);
    return bytes;
}

quint64 tagOf(const proton::tracker &tracker) {
    const proton::binary bytes = tracker.tag();
    quint64 tag = 0;
    if (bytes.size() == sizeof tag)
        std::memcpy(&tag, bytes.data(), sizeof tag);
    return tag;
}

proton::message protonMessage(const AmqpMessage &from) {
    proton::message m;
    m.inferred(true); // a binary body goes out as one Data section, as the SDK sends it
    m.body(proton::binary(from.body.cbegin(), from.body.cend()));
    m.id(proton::message_id(utf8(from.messageId)));
    if (!from.to.isEmpty())
        m.to(utf8(from.to));
    m.reply_to(utf8(from.replyTo));
    if (!from.correlationId.isEmpty())
        m.correlation_id(proton::message_id(utf8(from.correlationId)));
    m.content_type(utf8(from.contentType));
    if (!from.contentEncoding.isEmpty())
        m.content_encoding(utf8(from.contentEncoding));
    m.subject(utf8(from.subject));
    m.creation_time(proton::timestamp(from.creationTimeMs));
    m.durable(from.durable);
    for (auto it = from.applicationProperties.cbegin(); it != from.applicationProperties.cend();
         ++it)
        m.properties().put(utf8(it.key()),
                           it.value().isNull() ? proton::scalar() : proton::scalar(utf8(*it)));
    return m;
}

} // namespace

// Everything below runs on the Proton thread, except the constructor, the destructor and
// enqueue(), which only touch the container and, under its mutex, the connection's work queue.
class AmqpSender::Engine : public proton::messaging_handler {
public:
    Engine(AmqpSender &owner, const Settings &settings)
        : m_owner(&owner)
        , m_settings(settings)
        , m_container(*this) {
        m_container.auto_stop(false);
        m_delayMs = settings.retryMinMs;
        m_thread = std::thread([this] {
            try {
                m_container.run();
            } catch (const std::exception &e) {
                qCCritical(lcAmqp, "the AMQP thread stopped: %s", e.what());
            }
        });
    }
    ~Engine() override {
        m_stopping = true; // the connections the stop aborts must not be opened again
        m_container.stop();
        m_thread.join();
    }

    void enqueue(int generation, quint64 tag, proton::message message) {
        // The connection's own queue: it wakes an idle container, which the container's queue
        // did not always do. Without a connection the message would be dropped there anyway.
        const std::lock_guard<std::mutex> lock(m_workMutex);
        if (!m_work)
            return;
        m_work->add([this, generation, tag, message = std::move(message)]() mutable {
            if (generation != m_generation || !m_sender)
                return; // handed over under a connection that is gone: the caller sends again
            m_outbox.push_back({tag, std::move(message)});
            flush();
        });
    }

    void on_container_start(proton::container &) override { connect(); }

    void on_connection_open(proton::connection &connection) override {
        {
            const std::lock_guard<std::mutex> lock(m_workMutex);
            m_work = &connection.work_queue();
        }
        proton::sender_options options;
        options.delivery_mode(proton::delivery_mode::AT_LEAST_ONCE);
        m_opening = connection.open_sender(utf8(m_settings.address), options);
        if (!m_settings.requestAddress.isEmpty()) {
            proton::receiver_options requests;
            requests.auto_accept(false).credit_window(kRequestCredit);
            connection.open_receiver(utf8(m_settings.requestAddress), requests);
        }
    }

    void reply(int generation, const std::string &address, proton::message message) {
        const std::lock_guard<std::mutex> lock(m_workMutex);
        if (!m_work)
            return;
        m_work->add([this, generation, address, message = std::move(message)]() mutable {
            if (generation != m_generation || !m_sender)
                return;
            ReplyLink &link = replyLink(address);
            link.outbox.push_back(std::move(message));
            flushReplies(link);
        });
    }

    void on_message(proton::delivery &delivery, proton::message &message) override {
        const std::optional<QByteArray> body = bodyOf(message);
        if (!body || body->size() > kMaxRequestBytes) {
            delivery.reject(); // hostile or foreign: never parsed
            qCWarning(lcAmqp, "a request that is not CFX or is larger than %lld bytes was refused",
                      static_cast<long long>(kMaxRequestBytes));
            return;
        }
        AmqpSender::Request request{*body, text(message.content_encoding()),
                                    text(proton::to_string(message.id())),
                                    text(message.reply_to())};
        delivery.accept();
        post([request](AmqpSender &owner) { Q_EMIT owner.requestReceived(request); });
    }

    void on_sender_open(proton::sender &sender) override {
        if (!(sender == m_opening)) { // an answer's link
            for (ReplyLink &link : m_replies)
                if (link.sender == sender)
                    flushReplies(link);
            return;
        }
        m_sender = sender;
        m_delayMs = m_settings.retryMinMs;
        m_lastError.clear();
        const int generation = ++m_generation;
        post([generation](AmqpSender &owner) { owner.onOpened(generation); });
    }

    void on_sendable(proton::sender &sender) override {
        if (sender == m_sender)
            return flush();
        for (ReplyLink &link : m_replies)
            if (link.sender == sender)
                flushReplies(link);
    }

    void on_tracker_accept(proton::tracker &tracker) override {
        const quint64 tag = tagOf(tracker);
        if (tag != kReplyTag)
            post([tag](AmqpSender &owner) { Q_EMIT owner.accepted(tag); });
    }
    void on_tracker_reject(proton::tracker &tracker) override {
        settleRefused(tracker, QCoreApplication::translate("Cfx", "rejected by the broker"));
    }
    void on_tracker_release(proton::tracker &tracker) override {
        settleRefused(tracker, QCoreApplication::translate("Cfx", "released by the broker"));
    }

    void on_transport_error(proton::transport &transport) override { remember(transport.error()); }
    void on_connection_error(proton::connection &connection) override {
        remember(connection.error());
    }
    void on_sender_error(proton::sender &sender) override {
        for (auto it = m_replies.begin(); it != m_replies.end(); ++it)
            if (it->sender == sender) {
                // A requester's reply address the broker does not know: that answer is lost,
                // the connection and everything else stay.
                qCWarning(lcAmqp, "cannot answer a CFX request at %s: %s", it->address.c_str(),
                          sender.error().what().c_str());
                m_replies.erase(it);
                return;
            }
        remember(sender.error());
        sender.connection().close();
    }
    void on_receiver_error(proton::receiver &receiver) override {
        // Requests cannot be taken: said, while the messages go on.
        const QString why =
            describeAmqpError(text(receiver.error().name()), text(receiver.error().description()),
                              m_settings.requestAddress);
        post([why](AmqpSender &owner) { Q_EMIT owner.problem(why); });
    }
    void on_session_error(proton::session &session) override {
        remember(session.error());
        session.connection().close();
    }
    // Proton's own handler throws here, which would end the thread: every other error is
    // remembered, and the connection's close that follows retries.
    void on_error(const proton::error_condition &error) override { remember(error); }

    void on_transport_close(proton::transport &) override {
        {
            const std::lock_guard<std::mutex> lock(m_workMutex);
            m_work = nullptr; // goes with the connection
        }
        m_sender = proton::sender();
        m_opening = proton::sender();
        m_outbox.clear();
        m_replies.clear();
        const int generation = m_generation;
        const QString reason = m_lastError.isEmpty()
                                   ? QCoreApplication::translate("Cfx", "the connection closed")
                                   : m_lastError;
        m_lastError.clear();
        if (m_stopping)
            return;
        post([generation, reason](AmqpSender &owner) { owner.onLost(generation, reason, true); });
        const int delay = m_delayMs;
        m_delayMs = qMin(m_delayMs * 2, m_settings.retryMaxMs);
        m_container.schedule(proton::duration(delay), [this] { connect(); });
    }

private:
    struct Pending {
        quint64 tag;
        proton::message message;
    };
    struct ReplyLink {
        std::string address;
        proton::sender sender;
        std::deque<proton::message> outbox;
    };
    // Requests waiting to be answered are few: a requester waits for each answer.
    static constexpr int kRequestCredit = 10;
    // Answers are not tracked: their tag is none of the spooled messages'.
    static constexpr quint64 kReplyTag = 0;

    ReplyLink &replyLink(const std::string &address) {
        for (auto it = m_replies.begin(); it != m_replies.end(); ++it)
            if (it->address == address) {
                m_replies.splice(m_replies.end(), m_replies, it); // the newest last
                return m_replies.back();
            }
        if (int(m_replies.size()) >= kMaxReplyLinks) {
            m_replies.front().sender.close();
            m_replies.pop_front();
        }
        proton::sender_options options;
        options.delivery_mode(proton::delivery_mode::AT_LEAST_ONCE);
        m_replies.push_back({address, m_sender.connection().open_sender(address, options), {}});
        return m_replies.back();
    }

    void flushReplies(ReplyLink &link) {
        while (link.sender.credit() > 0 && !link.outbox.empty()) {
            link.sender.send(link.outbox.front(), tagBytes(kReplyTag));
            link.outbox.pop_front();
        }
    }

    template <typename F> void post(F what) {
        QPointer<AmqpSender> owner(m_owner);
        QMetaObject::invokeMethod(
            m_owner,
            [owner, what = std::move(what)] {
                if (owner)
                    what(*owner);
            },
            Qt::QueuedConnection);
    }

    void connect() {
        if (m_stopping)
            return;
        proton::connection_options options;
        options.idle_timeout(proton::duration(30000));
        options.sasl_enabled(true);
        if (!m_settings.user.isEmpty()) {
            options.user(utf8(m_settings.user));
            options.password(m_settings.password.toStdString());
            options.sasl_allowed_mechs("PLAIN");
            // Without TLS the password crosses the network readable: allowed, since a plant may
            // keep its broker on a closed network, and docs/cfx.md says to prefer amqps.
            options.sasl_allow_insecure_mechs(!m_settings.tls);
        }
        if (m_settings.tls) {
            const std::string ca = utf8(m_settings.caFile);
            const auto verify = proton::ssl::VERIFY_PEER_NAME;
            options.ssl_client_options(
                m_settings.certFile.isEmpty()
                    ? proton::ssl_client_options(ca, verify)
                    : proton::ssl_client_options(proton::ssl_certificate(utf8(m_settings.certFile),
                                                                         utf8(m_settings.keyFile)),
                                                 ca, verify));
        }
        const QString url =
            QStringLiteral("%1://%2:%3")
                .arg(m_settings.tls ? QStringLiteral("amqps") : QStringLiteral("amqp"),
                     m_settings.host)
                .arg(m_settings.port);
        try {
            m_container.connect(utf8(url), options);
        } catch (const std::exception &e) {
            m_lastError = QString::fromStdString(e.what());
            proton::transport none;
            on_transport_close(none);
        }
    }

    void flush() {
        while (m_sender && m_sender.credit() > 0 && !m_outbox.empty()) {
            Pending &next = m_outbox.front();
            m_sender.send(next.message, tagBytes(next.tag));
            m_outbox.pop_front();
        }
    }

    void settleRefused(proton::tracker &tracker, const QString &reason) {
        const quint64 tag = tagOf(tracker);
        if (tag == kReplyTag) {
            qCWarning(lcAmqp, "an answer to a CFX request was %s", qPrintable(reason));
            return;
        }
        post([tag, reason](AmqpSender &owner) { Q_EMIT owner.refused(tag, reason); });
    }

    void remember(const proton::error_condition &error) {
        if (!error.empty() && m_lastError.isEmpty())
            m_lastError =
                describeAmqpError(QString::fromStdString(error.name()),
                                  QString::fromStdString(error.description()), m_settings.address);
    }

    AmqpSender *m_owner;
    Settings m_settings;
    proton::container m_container;
    std::mutex m_workMutex;
    proton::work_queue *m_work = nullptr; // the open connection's, guarded by m_workMutex
    std::thread m_thread;
    proton::sender m_sender;
    proton::sender m_opening; // the link to the exchange, until it opens
    std::deque<Pending> m_outbox;
    std::list<ReplyLink> m_replies; // the least recently used first
    int m_generation = 0;
    int m_delayMs = 1000;
    QString m_lastError;
    std::atomic<bool> m_stopping{false};
};

AmqpSender::AmqpSender(QObject *parent)
    : QObject(parent) {}

AmqpSender::~AmqpSender() {
    m_engine.reset();
}

void AmqpSender::start(const Settings &settings) {
    stop();
    m_settings = settings;
    setState(State::Connecting);
    m_engine = std::make_unique<Engine>(*this, m_settings);
}

void AmqpSender::stop() {
    if (!m_engine)
        return;
    m_engine.reset();
    m_generation = -1;
    setState(State::Stopped);
}

quint64 AmqpSender::send(const AmqpMessage &message) {
    if (m_state != State::Connected || !m_engine)
        return 0;
    const quint64 tag = ++m_nextTag;
    m_engine->enqueue(m_generation, tag, protonMessage(message));
    return tag;
}

void AmqpSender::reply(const QString &address, const AmqpMessage &message) {
    if (m_state != State::Connected || !m_engine || address.isEmpty())
        return;
    m_engine->reply(m_generation, utf8(address), protonMessage(message));
}

QString AmqpSender::where() const {
    return QStringLiteral("%1://%2:%3")
        .arg(m_settings.tls ? QStringLiteral("amqps") : QStringLiteral("amqp"), m_settings.host)
        .arg(m_settings.port);
}

void AmqpSender::setState(State state) {
    if (state == m_state)
        return;
    m_state = state;
    Q_EMIT stateChanged(state);
}

void AmqpSender::onOpened(int generation) {
    if (!m_engine)
        return;
    m_generation = generation;
    setState(State::Connected);
    Q_EMIT connected();
}

void AmqpSender::onLost(int generation, const QString &reason, bool retrying) {
    if (!m_engine)
        return;
    const bool wasConnected = m_state == State::Connected && generation == m_generation;
    setState(retrying ? State::WaitingToRetry : State::Stopped);
    if (wasConnected)
        Q_EMIT disconnected(reason);
    Q_EMIT problem(reason);
}

} // namespace tipscope::cfx
