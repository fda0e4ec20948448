#include "mqttsetup.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QRandomGenerator>
#include <cerrno>
#include <mosquitto.h>
#include <mutex>

namespace tipscope::mqtt {

namespace {

struct Tr {
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

bool applyCredentials(mosquitto *client, const MqttSettings &settings, QString *error) {
    if (settings.username.isEmpty() && settings.password.isEmpty())
        return true;
    if (settings.username.isEmpty()) {
        *error = Tr::tr("A password is set but no user name: MQTT sends a password only with a "
                        "user name.");
        return false;
    }
    const QByteArray user = settings.username.toUtf8();
    const int rc = mosquitto_username_pw_set(
        client, user.constData(),
        settings.password.isEmpty() ? nullptr : settings.password.constData());
    if (rc != MOSQ_ERR_SUCCESS)
        *error = Tr::tr("The user name %1 is not accepted: %2")
                     .arg(settings.username, QString::fromUtf8(mosquitto_strerror(rc)));
    return rc == MOSQ_ERR_SUCCESS;
}

bool applyWill(mosquitto *client, const MqttWill &will, QString *error) {
    if (will.topic.isEmpty())
        return true;
    const QByteArray topic = will.topic.toUtf8();
    const int rc = mosquitto_will_set(client, topic.constData(), int(will.payload.size()),
                                      will.payload.constData(), will.qos, will.retain);
    if (rc != MOSQ_ERR_SUCCESS)
        *error = Tr::tr("The last will on %1 is not accepted: %2")
                     .arg(will.topic, QString::fromUtf8(mosquitto_strerror(rc)));
    return rc == MOSQ_ERR_SUCCESS;
}

bool checkTlsFiles(const MqttTls &tls, QString *error) {
    if (!readable(tls.caFile)) {
        *error = Tr::tr("The CA certificate file %1 cannot be read.").arg(tls.caFile);
        return false;
    }
    if (tls.certFile.isEmpty() != tls.keyFile.isEmpty()) {
        *error = Tr::tr("A client certificate needs both its certificate file and its key file.");
        return false;
    }
    for (const QString &path : {tls.certFile, tls.keyFile}) {
        if (!path.isEmpty() && !readable(path)) {
            *error = Tr::tr("The file %1 cannot be read.").arg(path);
            return false;
        }
    }
    return true;
}

bool applyTls(mosquitto *client, const MqttTls &tls, QString *error) {
    if (tls.caFile.isEmpty())
        return true;
    if (!checkTlsFiles(tls, error))
        return false;
    const QByteArray ca = QFile::encodeName(tls.caFile);
    const QByteArray cert = QFile::encodeName(tls.certFile);
    const QByteArray key = QFile::encodeName(tls.keyFile);
    int rc = mosquitto_tls_set(client, ca.constData(), nullptr,
                               cert.isEmpty() ? nullptr : cert.constData(),
                               key.isEmpty() ? nullptr : key.constData(), refusePassphrase);
    if (rc == MOSQ_ERR_SUCCESS)
        rc = mosquitto_tls_insecure_set(client, tls.insecure);
    if (rc != MOSQ_ERR_SUCCESS)
        *error = Tr::tr("TLS cannot be set up: %1").arg(QString::fromUtf8(mosquitto_strerror(rc)));
    return rc == MOSQ_ERR_SUCCESS;
}

bool applyProtocol(mosquitto *client, MqttProtocol protocol, QString *error) {
    const int version = protocol == MqttProtocol::V5 ? MQTT_PROTOCOL_V5 : MQTT_PROTOCOL_V311;
    const int rc = mosquitto_int_option(client, MOSQ_OPT_PROTOCOL_VERSION, version);
    if (rc != MOSQ_ERR_SUCCESS)
        *error = Tr::tr("The MQTT version cannot be set: %1")
                     .arg(QString::fromUtf8(mosquitto_strerror(rc)));
    return rc == MOSQ_ERR_SUCCESS;
}

} // namespace

void MosquittoDeleter::operator()(mosquitto *client) const {
    mosquitto_destroy(client);
}

QString effectiveClientId(const MqttSettings &settings) {
    if (!settings.clientId.isEmpty())
        return settings.clientId;
    return QStringLiteral("tipscope-%1")
        .arg(QRandomGenerator::global()->generate64() & 0xffffffffffffULL, 12, 16, QChar(u'0'));
}

MosquittoHandle createMosquitto(const MqttSettings &settings, void *userData, QString *error) {
    initialiseLibraryOnce();
    const QByteArray id = effectiveClientId(settings).toUtf8();
    MosquittoHandle client(mosquitto_new(id.constData(), settings.cleanSession, userData));
    if (!client) {
        *error = errno == EINVAL
                     ? Tr::tr("The client id %1 is not accepted.").arg(QString::fromUtf8(id))
                     : Tr::tr("Out of memory for an MQTT client.");
        return nullptr;
    }
    if (!applyProtocol(client.get(), settings.protocol, error) ||
        !applyCredentials(client.get(), settings, error) ||
        !applyWill(client.get(), settings.will, error) ||
        !applyTls(client.get(), settings.tls, error))
        return nullptr;
    return client;
}

} // namespace tipscope::mqtt
