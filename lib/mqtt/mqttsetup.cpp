#include "mqttsetup.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QRandomGenerator>
#include <cerrno>
#include <functional>
#include <mosquitto.h>
#include <mutex>

namespace tipscope::mqtt {

using base::failure;
using base::Outcome;

namespace {

struct MqttSetupTr {
    Q_DECLARE_TR_FUNCTIONS(MqttClient)
};

void initialiseLibraryOnce() {
    static std::once_flag once;
    std::call_once(once, [] { mosquitto_lib_init(); });
}

// A key file with a pass phrase fails to load instead of OpenSSL prompting on the terminal,
// which would block a service for ever.
int refusePassphrase(char *, int, int, void *) {
    return 0;
}

bool readable(const QString &path) {
    const QFileInfo info(path);
    return info.isFile() && info.isReadable();
}

// What libmosquitto reads as a CA file: PEM text. A DER file or anything else fails only at
// the first connection, deep in the TLS handshake.
bool holdsPem(const QString &path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return false;
    const QByteArray text = f.read(1 << 20);
    const qsizetype begin = text.indexOf("-----BEGIN ");
    return begin >= 0 && text.indexOf("CERTIFICATE-----", begin) > begin;
}

QString libraryText(int rc) {
    return QString::fromUtf8(mosquitto_strerror(rc));
}

Outcome<void> applyCredentials(mosquitto *client, const MqttSettings &settings) {
    if (settings.username.isEmpty() && settings.password.isEmpty())
        return {};
    if (settings.username.isEmpty())
        return failure(
            MqttSetupTr::tr("A password is set but no user name: MQTT sends a password only "
                            "with a user name."));
    const QByteArray user = settings.username.toUtf8();
    const int rc = mosquitto_username_pw_set(
        client, user.constData(),
        settings.password.isEmpty() ? nullptr : settings.password.constData());
    if (rc != MOSQ_ERR_SUCCESS)
        return failure(MqttSetupTr::tr("The user name %1 is not accepted: %2")
                           .arg(settings.username, libraryText(rc)));
    return {};
}

Outcome<void> applyWill(mosquitto *client, const MqttWill &will) {
    if (will.topic.isEmpty())
        return {};
    const QByteArray topic = will.topic.toUtf8();
    const int rc = mosquitto_will_set(client, topic.constData(), int(will.payload.size()),
                                      will.payload.constData(), will.qos, will.retain);
    if (rc != MOSQ_ERR_SUCCESS)
        return failure(MqttSetupTr::tr("The last will on %1 is not accepted: %2")
                           .arg(will.topic, libraryText(rc)));
    return {};
}

Outcome<void> applyTls(mosquitto *client, const MqttTls &tls) {
    if (tls.caFile.isEmpty())
        return {};
    if (const auto files = checkTlsFiles(tls); !files)
        return files;
    const QByteArray ca = QFile::encodeName(tls.caFile);
    const QByteArray cert = QFile::encodeName(tls.certFile);
    const QByteArray key = QFile::encodeName(tls.keyFile);
    int rc = mosquitto_tls_set(client, ca.constData(), nullptr,
                               cert.isEmpty() ? nullptr : cert.constData(),
                               key.isEmpty() ? nullptr : key.constData(), refusePassphrase);
    if (rc == MOSQ_ERR_SUCCESS)
        rc = mosquitto_tls_insecure_set(client, tls.insecure);
    if (rc != MOSQ_ERR_SUCCESS)
        return failure(MqttSetupTr::tr("TLS cannot be set up: %1").arg(libraryText(rc)));
    return {};
}

Outcome<void> applyProtocol(mosquitto *client, MqttProtocol protocol) {
    const int version = protocol == MqttProtocol::V5 ? MQTT_PROTOCOL_V5 : MQTT_PROTOCOL_V311;
    const int rc = mosquitto_int_option(client, MOSQ_OPT_PROTOCOL_VERSION, version);
    if (rc != MOSQ_ERR_SUCCESS)
        return failure(MqttSetupTr::tr("The MQTT version cannot be set: %1").arg(libraryText(rc)));
    return {};
}

} // namespace

Outcome<void> checkTlsFiles(const MqttTls &tls) {
    if (tls.caFile.isEmpty())
        return {};
    if (!readable(tls.caFile))
        return failure(
            MqttSetupTr::tr("The CA certificate file %1 cannot be read.").arg(tls.caFile));
    if (!holdsPem(tls.caFile))
        return failure(MqttSetupTr::tr("The CA certificate file %1 holds no PEM certificate "
                                       "(-----BEGIN CERTIFICATE-----).")
                           .arg(tls.caFile));
    if (tls.certFile.isEmpty() != tls.keyFile.isEmpty())
        return failure(MqttSetupTr::tr(
            "A client certificate needs both its certificate file and its key file."));
    for (const QString &path : {tls.certFile, tls.keyFile})
        if (!path.isEmpty() && !readable(path))
            return failure(MqttSetupTr::tr("The file %1 cannot be read.").arg(path));
    return {};
}

void MosquittoDeleter::operator()(mosquitto *client) const {
    mosquitto_destroy(client);
}

QString effectiveClientId(const MqttSettings &settings) {
    if (!settings.clientId.isEmpty())
        return settings.clientId;
    return QStringLiteral("tipscope-%1")
        .arg(QRandomGenerator::global()->generate64() & 0xffffffffffffULL, 12, 16, QChar(u'0'));
}

Outcome<MosquittoHandle> createMosquitto(const MqttSettings &settings, void *userData) {
    initialiseLibraryOnce();
    const QByteArray id = effectiveClientId(settings).toUtf8();
    MosquittoHandle client(mosquitto_new(id.constData(), settings.cleanSession, userData));
    if (!client)
        return failure(
            errno == EINVAL
                ? MqttSetupTr::tr("The client id %1 is not accepted.").arg(QString::fromUtf8(id))
                : MqttSetupTr::tr("Out of memory for an MQTT client."));
    // In this order, and no further than the first refusal.
    const std::function<Outcome<void>()> steps[] = {
        [&] { return applyProtocol(client.get(), settings.protocol); },
        [&] { return applyCredentials(client.get(), settings); },
        [&] { return applyWill(client.get(), settings.will); },
        [&] { return applyTls(client.get(), settings.tls); }};
    for (const auto &step : steps)
        if (const auto applied = step(); !applied)
            return failure(applied.error());
    return client;
}

} // namespace tipscope::mqtt
