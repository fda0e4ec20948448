#include "mqttclient.h"

#include "mqttcallbacks.h"
#include "mqttpump.h"
#include "mqtttopic.h"

#include <QCoreApplication>
#include <QHostAddress>
#include <QHostInfo>
#include <QLoggingCategory>
#include <QPointer>
#include <mosquitto.h>

namespace tipscope::mqtt {

Q_LOGGING_CATEGORY(lcMqtt, "tipscope.mqtt")

namespace {

// One translation context for every text of the client: here, mqttproblem.cpp, mqttsetup.cpp.
struct MqttClientTr {
    Q_DECLARE_TR_FUNCTIONS(MqttClient)
};

// How long stop() waits for the DISCONNECT to be written before closing the socket anyway.
constexpr int kStopTimeoutMs = 3000;

} // namespace

MqttClient::MqttClient(QObject *parent)
    : QObject(parent)
    , m_pump(new MqttPump(this)) {
    m_retryTimer.setSingleShot(true);
    connect(&m_retryTimer, &QTimer::timeout, this, &MqttClient::attempt);
    m_stopTimer.setSingleShot(true);
    connect(&m_stopTimer, &QTimer::timeout, this, &MqttClient::finishStop);
    connect(m_pump, &MqttPump::serviced, this, &MqttClient::onServiced);
    connect(m_pump, &MqttPump::hungUp, this, &MqttClient::onHungUp);
}

MqttClient::~MqttClient() {
    if (m_lookupId >= 0)
        QHostInfo::abortHostLookup(m_lookupId);
    m_pump->attach(nullptr);
    // Closes the socket without DISCONNECT: the broker publishes the will.
    m_mosquitto.reset();
}

void MqttClient::setSettings(const MqttSettings &settings) {
    m_settings = settings;
}

QString MqttClient::where() const {
    return QStringLiteral("%1:%2").arg(m_settings.host).arg(m_settings.port);
}

void MqttClient::setState(State state) {
    if (state == m_state)
        return;
    m_state = state;
    qCDebug(lcMqtt) << "broker" << where() << "state" << state;
    Q_EMIT stateChanged(state);
}

void MqttClient::setProblem(const MqttProblemReport &report) {
    m_problem = report;
    if (report.problem == MqttProblem::None)
        return;
    qCWarning(lcMqtt).noquote() << report.text;
    Q_EMIT problemOccurred(report.problem, report.text);
}

void MqttClient::start() {
    if (m_state != State::Stopped)
        return;
    MqttSettings settings = m_settings;
    settings.clientId = m_clientId = effectiveClientId(m_settings);
    auto created = createMosquitto(settings, this);
    if (!created) {
        setProblem({MqttProblem::InvalidSettings, created.error()});
        return;
    }
    m_mosquitto = std::move(created).value();
    MqttCallbacks::install(m_mosquitto.get());
    m_pending.clear();
    m_nextDelayMs = qMax(1, m_settings.retryMinMs);
    attempt();
}

void MqttClient::attempt() {
    m_connackSeen = false;
    m_tlsDetail.clear();
    setState(State::Connecting);
    if (!QHostAddress(m_settings.host).isNull()) {
        connectNow();
        return;
    }
    m_lookupId = QHostInfo::lookupHost(m_settings.host, this, &MqttClient::onLookedUp);
}

void MqttClient::onLookedUp(const QHostInfo &info) {
    m_lookupId = -1;
    if (m_state != State::Connecting)
        return;
    if (info.error() != QHostInfo::NoError) {
        setProblem(describeLookupFailure(m_settings.host, info.errorString()));
        scheduleRetry();
        return;
    }
    connectNow();
}

void MqttClient::setQuiet(bool on) {
    m_pump->setQuiet(on);
}

bool MqttClient::watchesReads() const {
    return m_pump->watchesReads();
}

void MqttClient::connectNow() {
    const QByteArray host = m_settings.host.toUtf8();
    errno = 0;
    // Closes the previous socket (one the pump gave up on included) and opens a new one.
    const int rc = mosquitto_connect_async(m_mosquitto.get(), host.constData(), m_settings.port,
                                           m_settings.keepAliveSeconds);
    const int errnoValue = errno;
    m_pump->attach(m_mosquitto.get());
    if (rc != MOSQ_ERR_SUCCESS) {
        setProblem(describeLibraryError(rc, errnoValue, where(), m_tlsDetail));
        scheduleRetry();
        return;
    }
    onServiced(MOSQ_ERR_SUCCESS, 0);
}

void MqttClient::onServiced(int rc, int errnoValue) {
    dispatchEvents();
    if (!m_mosquitto)
        return;
    m_pump->sync();
    if (m_pump->watching())
        return;
    if (m_state == State::Stopping) {
        finishStop();
        return;
    }
    if (m_state != State::Connecting && m_state != State::Connected)
        return;
    // A refusal in the CONNACK was reported already; anything else is reported now. A TLS
    // alert from the broker (no client certificate) ends the connection as a plain loss.
    if (!m_connackSeen && !m_tlsDetail.isEmpty())
        rc = MOSQ_ERR_TLS;
    else if (rc == MOSQ_ERR_SUCCESS || rc == MOSQ_ERR_CONN_REFUSED)
        rc = MOSQ_ERR_CONN_LOST;
    if (!m_connackSeen || m_problem.problem == MqttProblem::None)
        setProblem(describeLibraryError(rc, errnoValue, where(), m_tlsDetail));
    afterConnectionEnded();
}

void MqttClient::onHungUp() {
    if (m_state == State::Stopping) {
        finishStop();
        return;
    }
    if (m_connackSeen)
        setProblem(describeLibraryError(MOSQ_ERR_CONN_LOST, 0, where(), {}));
    else if (!m_tlsDetail.isEmpty()) // the broker's TLS alert, such as "certificate required"
        setProblem(describeLibraryError(MOSQ_ERR_TLS, 0, where(), m_tlsDetail));
    else
        setProblem(describeHangUp(where()));
    afterConnectionEnded();
}

void MqttClient::afterConnectionEnded() {
    const bool wasConnected = m_state == State::Connected;
    // libmosquitto drops unwritten QoS 0 packets when it reconnects, and says nothing of them.
    m_pending.removeIf([](const auto &entry) { return entry.value() == 0; });
    scheduleRetry();
    if (wasConnected)
        Q_EMIT disconnected(m_problem.text);
}

void MqttClient::scheduleRetry() {
    m_retryDelayMs = m_nextDelayMs;
    m_nextDelayMs = qMin(m_nextDelayMs * 2, qMax(m_retryDelayMs, m_settings.retryMaxMs));
    m_retryTimer.start(m_retryDelayMs);
    setState(State::WaitingToRetry);
}

void MqttClient::stop() {
    m_retryTimer.stop();
    if (m_lookupId >= 0)
        QHostInfo::abortHostLookup(m_lookupId);
    m_lookupId = -1;
    if (!m_mosquitto || m_state == State::Stopping)
        return;
    if (m_state != State::Connected) {
        finishStop();
        return;
    }
    setState(State::Stopping);
    mosquitto_disconnect(m_mosquitto.get());
    m_stopTimer.start(kStopTimeoutMs);
    onServiced(MOSQ_ERR_SUCCESS, 0);
}

void MqttClient::finishStop() {
    const bool wasRunning = m_state != State::Stopped;
    const bool wasConnected = m_state == State::Connected || m_state == State::Stopping;
    m_stopTimer.stop();
    m_pump->attach(nullptr);
    m_mosquitto.reset();
    m_events.clear();
    m_pending.clear();
    m_problem = {};
    setState(State::Stopped);
    if (wasRunning && wasConnected)
        Q_EMIT disconnected(QString());
}

void MqttClient::dispatchEvents() {
    QPointer<MqttClient> self(this);
    while (self && !m_events.empty()) {
        Event event = std::move(m_events.front());
        m_events.erase(m_events.begin());
        switch (event.kind) {
        case Event::Kind::Connack:
            onConnack(event.code);
            break;
        case Event::Kind::Disconnect:
            break; // the closed socket is handled once the call has returned
        case Event::Kind::Published:
            m_pending.remove(event.messageId);
            if (event.code < 0x80)
                Q_EMIT published(event.messageId);
            else
                Q_EMIT publishRejected(
                    event.messageId,
                    MqttClientTr::tr("The broker %1 refused the message: %2.")
                        .arg(where(), QString::fromUtf8(mosquitto_reason_string(event.code))));
            break;
        case Event::Kind::Subscribed:
            Q_EMIT subscribed(event.messageId, event.code == 0);
            break;
        case Event::Kind::Message:
            Q_EMIT messageReceived(event.topic, event.payload, event.retained);
            break;
        }
    }
}

void MqttClient::onConnack(int code) {
    m_connackSeen = true;
    if (code != 0) {
        setProblem(describeConnack(code, m_settings.protocol, where()));
        return;
    }
    m_problem = {};
    m_nextDelayMs = qMax(1, m_settings.retryMinMs);
    qCInfo(lcMqtt).noquote() << "connected to" << where() << "as" << m_clientId;
    resubscribe();
    setState(State::Connected);
    Q_EMIT connected();
}

void MqttClient::resubscribe() {
    for (auto it = m_subscriptions.cbegin(); it != m_subscriptions.cend(); ++it) {
        const QByteArray filter = it.key().toUtf8();
        mosquitto_subscribe(m_mosquitto.get(), nullptr, filter.constData(), it.value());
    }
}

void MqttClient::serviceSoon() {
    m_pump->sync();
    // Events of the call (a QoS 0 message written), or a socket it found closed, are handled
    // once the caller has its result.
    if (!m_events.empty() || !m_pump->watching())
        QMetaObject::invokeMethod(
            this, [this] { onServiced(MOSQ_ERR_SUCCESS, 0); }, Qt::QueuedConnection);
}

MqttResult MqttClient::refuse(const QString &reason) {
    ++m_refused;
    qCDebug(lcMqtt).noquote() << reason;
    return {0, reason};
}

MqttResult MqttClient::publish(const QString &topic, const QByteArray &payload, int qos,
                               bool retain) {
    if (!isValidTopicName(topic))
        return refuse(
            MqttClientTr::tr("'%1' is not a topic a message can be published to.").arg(topic));
    if (qos < 0 || qos > 2)
        return refuse(MqttClientTr::tr("QoS %1 does not exist; MQTT has 0, 1 and 2.").arg(qos));
    if (m_state != State::Connected)
        return refuse(
            MqttClientTr::tr("Not connected to the broker %1: the message to %2 is dropped.")
                .arg(where(), topic));
    if (m_pending.size() >= m_settings.maxPendingMessages)
        return refuse(
            MqttClientTr::tr("%1 messages wait to be taken by the broker %2: the message to %3 is "
                             "dropped.")
                .arg(m_pending.size())
                .arg(where(), topic));
    const QByteArray name = topic.toUtf8();
    int messageId = 0;
    const int rc = mosquitto_publish(m_mosquitto.get(), &messageId, name.constData(),
                                     int(payload.size()), payload.constData(), qos, retain);
    serviceSoon();
    if (rc != MOSQ_ERR_SUCCESS)
        return refuse(MqttClientTr::tr("The message to %1 was not sent: %2")
                          .arg(topic, QString::fromUtf8(mosquitto_strerror(rc))));
    m_pending.insert(messageId, qos);
    return {messageId, {}};
}

MqttResult MqttClient::subscribe(const QString &filter, int qos) {
    if (!isValidTopicFilter(filter))
        return {0, MqttClientTr::tr("'%1' is not a valid subscription filter.").arg(filter)};
    if (qos < 0 || qos > 2)
        return {0, MqttClientTr::tr("QoS %1 does not exist; MQTT has 0, 1 and 2.").arg(qos)};
    m_subscriptions.insert(filter, qos);
    if (m_state != State::Connected)
        return {};
    const QByteArray name = filter.toUtf8();
    int messageId = 0;
    const int rc = mosquitto_subscribe(m_mosquitto.get(), &messageId, name.constData(), qos);
    serviceSoon();
    if (rc != MOSQ_ERR_SUCCESS)
        return {0, MqttClientTr::tr("The subscription to %1 was not sent: %2")
                       .arg(filter, QString::fromUtf8(mosquitto_strerror(rc)))};
    return {messageId, {}};
}

MqttResult MqttClient::unsubscribe(const QString &filter) {
    if (!m_subscriptions.remove(filter))
        return {0, MqttClientTr::tr("There is no subscription to %1.").arg(filter)};
    if (m_state != State::Connected)
        return {};
    const QByteArray name = filter.toUtf8();
    int messageId = 0;
    const int rc = mosquitto_unsubscribe(m_mosquitto.get(), &messageId, name.constData());
    serviceSoon();
    if (rc != MOSQ_ERR_SUCCESS)
        return {0, MqttClientTr::tr("The subscription to %1 was not ended: %2")
                       .arg(filter, QString::fromUtf8(mosquitto_strerror(rc)))};
    return {messageId, {}};
}

} // namespace tipscope::mqtt
