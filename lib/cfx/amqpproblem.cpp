#include "amqpproblem.h"

#include <QCoreApplication>

namespace tipscope::cfx {

namespace {

struct AmqpProblemTr {
    Q_DECLARE_TR_FUNCTIONS(AmqpProblem)
};

bool mentions(const QString &text, const char *word) {
    return text.contains(QLatin1String(word), Qt::CaseInsensitive);
}

QString advice(const QString &name, const QString &description, const QString &address) {
    const QString both = name + QLatin1Char(' ') + description;
    if (mentions(name, "unauthorized-access") || mentions(description, "authentication failed"))
        return AmqpProblemTr::tr("The broker refused the login: check the user and the password "
                                 "(file or environment variable).");
    if (mentions(description, "protocol header") || mentions(description, "AMQP header"))
        return AmqpProblemTr::tr("The broker does not speak AMQP 1.0: enable its plugin "
                                 "(rabbitmq-plugins enable rabbitmq_amqp1_0).");
    if (mentions(both, "unknown_destination") || mentions(both, "invalid-field"))
        return AmqpProblemTr::tr("The broker does not know the address %1: RabbitMQ wants "
                                 "/exchange/NAME, /exchange/NAME/KEY or /queue/NAME.")
            .arg(address);
    if (mentions(name, "not-found") || mentions(description, "no exchange"))
        return AmqpProblemTr::tr("The exchange or queue of %1 does not exist on the broker: "
                                 "declare it there, or fix the address.")
            .arg(address);
    if (mentions(both, "ssl") || mentions(both, "tls") || mentions(both, "certificate"))
        return AmqpProblemTr::tr("TLS failed: check the CA file, the client certificate and that "
                                 "the host name matches the broker's certificate.");
    if (mentions(description, "refused"))
        return AmqpProblemTr::tr("Nothing accepts connections there: check the host and port, "
                                 "and that the broker runs.");
    if (mentions(description, "not known") || mentions(description, "resolve") ||
        mentions(description, "no address"))
        return AmqpProblemTr::tr("The broker's host name cannot be found: check it.");
    return {};
}

} // namespace

QString describeAmqpError(const QString &name, const QString &description, const QString &address) {
    const QString broker = description.isEmpty() ? name : description;
    const QString what = advice(name, description, address);
    if (what.isEmpty())
        return AmqpProblemTr::tr("The broker said: %1.").arg(broker);
    return AmqpProblemTr::tr("%1 (The broker said: %2)").arg(what, broker);
}

} // namespace tipscope::cfx
