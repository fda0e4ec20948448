#include "agentconfig.h"

#include "base/jsonfile.h"
#include "mqtt/mqttsecret.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <algorithm>

namespace tipscope::plant {

namespace {
struct AgentConfigTr {
    Q_DECLARE_TR_FUNCTIONS(AgentConfig)
};

using base::failure;
using base::Outcome;

const QString kFormat = QStringLiteral("tipscope-agent");
constexpr qint64 kMaxBytes = 1024 * 1024;

// One JSON object's optional fields, each read into its target only when present and valid; the
// first problem is kept, named by its dotted field name.
class Reader {
public:
    Reader(const QJsonObject &object, QString prefix, QString *problem)
        : m_object(object)
        , m_prefix(std::move(prefix))
        , m_problem(problem) {}

    void text(const char *key, QString &target) {
        const QJsonValue v = m_object.value(QLatin1String(key));
        if (v.isUndefined() || v.isNull())
            return;
        if (!v.isString())
            return fail(AgentConfigTr::tr("%1 must be text").arg(name(key)));
        target = v.toString();
    }
    void number(const char *key, int &target, int min, int max) {
        const QJsonValue v = m_object.value(QLatin1String(key));
        if (v.isUndefined() || v.isNull())
            return;
        const double d = v.toDouble(-1e300);
        if (!v.isDouble() || d != double(qint64(d)) || d < min || d > max)
            return fail(AgentConfigTr::tr("%1 must be a whole number from %2 to %3")
                            .arg(name(key))
                            .arg(min)
                            .arg(max));
        target = int(d);
    }
    void flag(const char *key, bool &target) {
        const QJsonValue v = m_object.value(QLatin1String(key));
        if (v.isUndefined() || v.isNull())
            return;
        if (!v.isBool())
            return fail(AgentConfigTr::tr("%1 must be true or false").arg(name(key)));
        target = v.toBool();
    }
    [[nodiscard]] QJsonObject object(const char *key) {
        const QJsonValue v = m_object.value(QLatin1String(key));
        if (!v.isUndefined() && !v.isNull() && !v.isObject())
            fail(AgentConfigTr::tr("%1 must be an object").arg(name(key)));
        return v.toObject();
    }
    [[nodiscard]] QString name(const char *key) const { return m_prefix + QLatin1String(key); }
    void fail(const QString &why) {
        if (m_problem->isEmpty())
            *m_problem = why;
    }

private:
    QJsonObject m_object;
    QString m_prefix;
    QString *m_problem;
};

Outcome<void> checkHeader(const QJsonObject &json) {
    if (json.value(QStringLiteral("format")).toString() != kFormat)
        return failure(
            AgentConfigTr::tr("not a TipScope agent configuration (\"format\" is not \"%1\")")
                .arg(kFormat));
    const QJsonValue version = json.value(QStringLiteral("version"));
    if (!version.isDouble() || version.toDouble() < 1 ||
        version.toDouble() != double(version.toInt()))
        return failure(AgentConfigTr::tr("\"version\" must be a whole number from 1"));
    if (version.toInt() > AgentConfig::kVersion)
        return failure(
            AgentConfigTr::tr("written for a later TipScope (version %1); this one reads version "
                              "%2 and older")
                .arg(version.toInt())
                .arg(AgentConfig::kVersion));
    return {};
}

QString resolved(const QString &folder, const QString &path) {
    return path.isEmpty() ? path : QDir(folder).absoluteFilePath(path);
}

void readBroker(Reader &top, AgentConfig &c, const QString &folder, QString *problem,
                QString &passwordFile, QString &passwordEnv) {
    Reader broker(top.object("broker"), QStringLiteral("broker."), problem);
    mqtt::MqttSettings &b = c.broker;
    broker.text("host", b.host);
    broker.number("port", b.port, 1, 65535);
    broker.text("client_id", b.clientId);
    broker.number("keep_alive_s", b.keepAliveSeconds, 5, 3600);
    int retryMaxS = b.retryMaxMs / 1000;
    broker.number("retry_max_s", retryMaxS, 1, 600);
    b.retryMaxMs = retryMaxS * 1000;
    broker.text("username", b.username);
    broker.text("password_file", passwordFile);
    broker.text("password_env", passwordEnv);
    QString protocolName = QStringLiteral("3.1.1");
    broker.text("protocol", protocolName);
    if (protocolName != QLatin1String("3.1.1") && protocolName != QLatin1String("5"))
        broker.fail(AgentConfigTr::tr("broker.protocol must be \"3.1.1\" or \"5\""));
    b.protocol =
        protocolName == QLatin1String("5") ? mqtt::MqttProtocol::V5 : mqtt::MqttProtocol::V311;
    Reader tls(broker.object("tls"), QStringLiteral("broker.tls."), problem);
    tls.text("ca_file", b.tls.caFile);
    tls.text("cert_file", b.tls.certFile);
    tls.text("key_file", b.tls.keyFile);
    tls.flag("insecure", b.tls.insecure);
    b.tls.caFile = resolved(folder, b.tls.caFile);
    b.tls.certFile = resolved(folder, b.tls.certFile);
    b.tls.keyFile = resolved(folder, b.tls.keyFile);
    if (b.host.isEmpty())
        broker.fail(AgentConfigTr::tr("broker.host must name the broker"));
    if (!passwordFile.isEmpty() && !passwordEnv.isEmpty())
        broker.fail(
            AgentConfigTr::tr("broker.password_file and broker.password_env: give one of them"));
}

// Where a password is kept: a file or an environment variable, as the configuration names them.
struct SecretPlace {
    QString file;
    QString env;
};

Outcome<void> readPassword(const SecretPlace &place, QByteArray &password, QString &source) {
    if (!place.file.isEmpty()) {
        auto secret = mqtt::readSecretFile(place.file);
        if (!secret)
            return failure(secret.error());
        password = secret.value();
        source = AgentConfigTr::tr("file %1").arg(place.file);
    } else if (!place.env.isEmpty()) {
        auto secret = mqtt::readSecretEnvironment(place.env);
        if (!secret)
            return failure(secret.error());
        password = secret.value();
        source = AgentConfigTr::tr("environment variable %1").arg(place.env);
    }
    return {};
}

std::optional<cfx::CfxSettings> readCfx(Reader &top, const QString &folder, QString *problem,
                                        SecretPlace &secret) {
    const QJsonObject section = top.object("cfx");
    if (section.isEmpty())
        return std::nullopt;
    Reader r(section, QStringLiteral("cfx."), problem);
    cfx::CfxSettings s;
    r.text("host", s.host);
    r.number("port", s.port, 1, 65535);
    r.text("address", s.address);
    r.text("request_address", s.requestAddress);
    r.text("username", s.username);
    r.text("password_file", secret.file);
    r.text("password_env", secret.env);
    r.text("vendor", s.vendor);
    bool gzip = s.codec == cfx::Codec::Gzip;
    r.flag("gzip", gzip);
    s.codec = gzip ? cfx::Codec::Gzip : cfx::Codec::Raw;
    r.number("heartbeat_s", s.heartbeatS, 1, 300); // CFX: at least every 5 minutes
    r.number("retry_max_s", s.retryMaxS, 1, 600);
    Reader tls(r.object("tls"), QStringLiteral("cfx.tls."), problem);
    tls.flag("enabled", s.tls);
    tls.text("ca_file", s.caFile);
    tls.text("cert_file", s.certFile);
    tls.text("key_file", s.keyFile);
    s.caFile = resolved(folder, s.caFile);
    s.certFile = resolved(folder, s.certFile);
    s.keyFile = resolved(folder, s.keyFile);
    if (s.host.isEmpty())
        r.fail(AgentConfigTr::tr("cfx.host must name the AMQP broker"));
    if (!cfx::isBrokerAddress(s.address))
        r.fail(AgentConfigTr::tr("cfx.address must be /exchange/NAME, /exchange/NAME/KEY or "
                                 "/queue/NAME, not \"%1\"")
                   .arg(s.address.left(80)));
    if (!s.requestAddress.isEmpty() && !cfx::isRequestQueue(s.requestAddress))
        r.fail(AgentConfigTr::tr("cfx.request_address must be a queue, /queue/NAME, not \"%1\"")
                   .arg(s.requestAddress.left(80)));
    if (s.vendor.trimmed().isEmpty() || s.vendor.size() > AgentConfig::kMaxSiteChars)
        r.fail(AgentConfigTr::tr("cfx.vendor must be a name of at most %1 characters")
                   .arg(AgentConfig::kMaxSiteChars));
    if (s.certFile.isEmpty() != s.keyFile.isEmpty())
        r.fail(AgentConfigTr::tr("cfx.tls.cert_file and cfx.tls.key_file: give both or neither"));
    if (!secret.file.isEmpty() && !secret.env.isEmpty())
        r.fail(AgentConfigTr::tr("cfx.password_file and cfx.password_env: give one of them"));
    return s;
}

} // namespace

Outcome<AgentConfig> AgentConfig::fromJson(const QJsonObject &json, const QString &folder) {
    if (const auto header = checkHeader(json); !header)
        return failure(header.error());
    AgentConfig c;
    QString problem;
    Reader top(json, QString(), &problem);
    top.text("site", c.site);
    top.text("workspace", c.workspacePath);
    top.text("journal", c.journalPath);
    top.number("counters_interval_s", c.countersIntervalS, 10, 86400);
    top.flag("remote_apply", c.remoteApply);
    Reader live(top.object("live"), QStringLiteral("live."), &problem);
    live.number("interval_ms", c.live.intervalMs, 100, 3600000);
    live.number("batch_ms", c.live.batchMs, 0, 600000);
    QString passwordFile, passwordEnv;
    // "broker": false publishes no MQTT (CFX only); a missing section is the local broker.
    c.mqtt = json.value(QStringLiteral("broker")) != QJsonValue(false);
    if (c.mqtt)
        readBroker(top, c, folder, &problem, passwordFile, passwordEnv);
    SecretPlace cfxSecret;
    c.cfx = readCfx(top, folder, &problem, cfxSecret);
    if (!c.mqtt && !c.cfx)
        top.fail(AgentConfigTr::tr("broker is false: then a cfx section must say where the "
                                   "lines are published"));
    if (c.site.trimmed().isEmpty())
        top.fail(AgentConfigTr::tr("site must name the site"));
    else if (c.site.size() > AgentConfig::kMaxSiteChars)
        top.fail(AgentConfigTr::tr("site must be at most %1 characters long, not %2")
                     .arg(AgentConfig::kMaxSiteChars)
                     .arg(c.site.size()));
    else if (std::any_of(c.site.cbegin(), c.site.cend(),
                         [](QChar ch) { return ch.category() == QChar::Other_Control; }))
        top.fail(AgentConfigTr::tr("site must not hold control characters"));
    if (c.workspacePath.isEmpty())
        top.fail(AgentConfigTr::tr("workspace must name the workspace file of the lines to run"));
    if (!problem.isEmpty())
        return failure(problem);
    c.workspacePath = resolved(folder, c.workspacePath);
    c.journalPath = resolved(folder, c.journalPath);
    auto workspace = model::WorkspaceFile::load(c.workspacePath);
    if (!workspace)
        return failure(workspace.error());
    c.workspace = workspace.value();
    if (auto password = readPassword({resolved(folder, passwordFile), passwordEnv},
                                     c.broker.password, c.passwordSource);
        !password)
        return failure(password.error());
    if (c.cfx) {
        cfxSecret.file = resolved(folder, cfxSecret.file);
        if (auto password = readPassword(cfxSecret, c.cfx->password, c.cfxPasswordSource);
            !password)
            return failure(password.error());
    }
    return c;
}

Outcome<AgentConfig> AgentConfig::load(const QString &path) {
    const auto read = base::io::readJsonObject(path, kMaxBytes);
    if (const auto *problem = std::get_if<base::io::JsonFileProblem>(&read)) {
        using Kind = base::io::JsonFileProblem::Kind;
        switch (problem->kind) {
        case Kind::Missing:
            return failure(
                AgentConfigTr::tr("cannot read the configuration %1: there is no such file")
                    .arg(path));
        case Kind::Unreadable:
            return failure(AgentConfigTr::tr("cannot read the configuration %1: %2")
                               .arg(path, problem->detail));
        case Kind::TooBig:
            return failure(
                AgentConfigTr::tr("the configuration %1 is too big to be one").arg(path));
        case Kind::NotAnObject:
            return failure(AgentConfigTr::tr("the configuration %1 is not a JSON object: %2")
                               .arg(path, problem->detail.isEmpty()
                                              ? AgentConfigTr::tr("it is a list")
                                              : problem->detail));
        }
    }
    auto config = fromJson(std::get<QJsonObject>(read), QFileInfo(path).absolutePath());
    if (!config)
        return failure(QStringLiteral("%1: %2").arg(path, config.error()));
    AgentConfig loaded = std::move(config).value();
    loaded.path = path;
    return loaded;
}

} // namespace tipscope::plant
