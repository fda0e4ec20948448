#include "cfxpublisher.h"

#include <QJsonValue>
#include <QLoggingCategory>

Q_LOGGING_CATEGORY(lcCfxPublisher, "tipscope.cfx.publisher")

namespace tipscope::cfx {

CfxPublisher::CfxPublisher(journal::Journal &journal, const CfxSettings &settings,
                           CfxForwarder::HandleOf handleOf, Endpoints endpoints,
                           CfxForwarder::Boards boards, QObject *parent)
    : QObject(parent)
    , m_settings(settings)
    , m_endpoints(std::move(endpoints))
    , m_forwarder(journal, m_sender, std::move(handleOf), settings.codec, std::move(boards)) {
    m_heartbeat.setInterval(settings.heartbeatS * 1000);
    connect(&m_heartbeat, &QTimer::timeout, this, [this] {
        const qint64 periodMs = m_settings.heartbeatS * 1000LL;
        sendToEach([this, periodMs](const QString &handle) {
            return heartbeat(handle, periodMs, m_forwarder.activeFaults(handle));
        });
    });
    connect(&m_sender, &AmqpSender::connected, this, &CfxPublisher::stationsChanged);
    connect(&m_sender, &AmqpSender::requestReceived, this, &CfxPublisher::answer);
    connect(&m_sender, &AmqpSender::connected, this, [this] {
        for (auto &[station, watched] : m_watched)
            tellState(watched, std::nullopt);
    });
    connect(&m_sender, &AmqpSender::disconnected, this, [this] { m_announced.clear(); });
    connect(&m_sender, &AmqpSender::accepted, this, [this](quint64 tag) {
        if (m_goodbyes.remove(tag) && m_goodbyes.isEmpty() && m_stopping)
            finishStop();
    });
    m_stopTimer.setSingleShot(true);
    connect(&m_stopTimer, &QTimer::timeout, this, &CfxPublisher::finishStop);
}

void CfxPublisher::start() {
    AmqpSender::Settings s;
    s.host = m_settings.host;
    s.port = m_settings.port;
    s.tls = m_settings.tls;
    s.caFile = m_settings.caFile;
    s.certFile = m_settings.certFile;
    s.keyFile = m_settings.keyFile;
    s.user = m_settings.username;
    s.password = m_settings.password;
    s.address = m_settings.address;
    s.requestAddress = m_settings.requestAddress;
    s.retryMaxMs = m_settings.retryMaxS * 1000;
    m_sender.start(s);
    m_heartbeat.start();
}

void CfxPublisher::stop(int timeoutMs) {
    if (m_stopping)
        return;
    m_stopping = true;
    m_heartbeat.stop();
    for (const QString &handle : handles())
        if (const quint64 tag = sendNow(handle, endpointShuttingDown(handle)))
            m_goodbyes.insert(tag);
    if (m_goodbyes.isEmpty())
        return finishStop();
    m_stopTimer.start(timeoutMs);
}

void CfxPublisher::stationsChanged() {
    if (m_sender.state() != AmqpSender::State::Connected || m_stopping)
        return;
    for (const QString &handle : handles())
        if (!m_announced.contains(handle) &&
            sendNow(handle, endpointConnected(handle, requestPlace().networkUri,
                                              requestPlace().address)) != 0)
            m_announced.insert(handle);
}

void CfxPublisher::watchStation(model::StationModel &station, const QString &handle) {
    if (m_watched.count(&station))
        return;
    Watched watched{std::make_unique<StationStateWatcher>(station), handle, std::nullopt};
    watched.told = watched.watcher->condition(); // the present needs no message
    connect(watched.watcher.get(), &StationStateWatcher::changed, this,
            [this, key = &station](StationCondition before, std::optional<qint64> lastedMs) {
                Watched &w = m_watched.at(key);
                // The duration is the old condition's only if the broker heard that one.
                if (!w.told)
                    w.told = before;
                tellState(w, w.told == before ? lastedMs : std::nullopt);
            });
    connect(&station, &QObject::destroyed, this, [this, key = &station] { m_watched.erase(key); });
    m_watched.emplace(&station, std::move(watched));
}

void CfxPublisher::tellState(Watched &watched, std::optional<qint64> lastedMs) {
    const std::optional<StationCondition> now = watched.watcher->condition();
    if (!now || !watched.told || *now == *watched.told || m_stopping ||
        m_sender.state() != AmqpSender::State::Connected)
        return;
    if (sendNow(watched.handle, stationStateChanged(*watched.told, lastedMs, *now, {})) != 0)
        watched.told = now;
}

QStringList CfxPublisher::handles() const {
    QStringList all;
    for (const EndpointIdentity &endpoint : m_endpoints())
        all.append(endpoint.handle);
    return all;
}

RequestPlace CfxPublisher::requestPlace() const {
    // Without a request queue nobody can ask: the SDK's EndpointConnected then names none.
    if (m_settings.requestAddress.isEmpty())
        return {};
    return {m_sender.where(), m_settings.requestAddress};
}

void CfxPublisher::answer(const AmqpRequest &request) {
    if (m_stopping)
        return;
    const auto answer = answerRequest(request, m_endpoints(), requestPlace());
    if (!answer) {
        qCWarning(lcCfxPublisher, "%s", qPrintable(answer.error()));
        return;
    }
    m_sender.reply(answer->address, answer->message);
}

void CfxPublisher::finishStop() {
    m_stopTimer.stop();
    m_goodbyes.clear();
    m_sender.stop();
    Q_EMIT stopped();
}

void CfxPublisher::sendToEach(const std::function<Message(const QString &handle)> &make) {
    for (const QString &handle : handles())
        (void)sendNow(handle, make(handle));
}

quint64 CfxPublisher::sendNow(const QString &handle, const Message &message) {
    return m_sender.send(toAmqpMessage(envelopeOf(message, handle), m_settings.codec));
}

} // namespace tipscope::cfx
