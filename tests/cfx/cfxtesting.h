// What the CFX tests against a broker share: why they cannot run here, their node, and a
// sender's settings for it (anonymous, on loopback, quick to retry).
#pragma once

#include "cfx/amqpsender.h"
#include "cfxconsumer.h"
#include "rabbitmqbroker.h"

#include <QTest>
#include <memory>
#include <optional>

namespace tipscope::testing {

inline QString cfxBrokerSkipReason() {
    const QString broker = RabbitMqBroker::skipReason();
    return broker.isEmpty() ? CfxConsumer::skipReason() : broker;
}

// The test case's RabbitMQ node, for an initTestCase(): skips the case where it cannot run, fails
// it where it does not start. With `tls`, it also listens with TLS.
inline void startCfxBroker(std::unique_ptr<RabbitMqBroker> &broker,
                           const std::optional<RabbitMqBroker::Tls> &tls = std::nullopt) {
    if (const QString why = cfxBrokerSkipReason(); !why.isEmpty())
        QSKIP(qPrintable(why));
    broker = std::make_unique<RabbitMqBroker>();
    if (tls)
        broker->setTls(*tls);
    QString error;
    QVERIFY2(broker->start(&error), qPrintable(error));
}

inline cfx::AmqpSender::Settings quickSenderSettings(const RabbitMqBroker &broker,
                                                     const QString &address) {
    cfx::AmqpSender::Settings s;
    s.host = QStringLiteral("127.0.0.1");
    s.port = broker.port();
    s.address = address;
    s.retryMinMs = 100;
    s.retryMaxMs = 400;
    return s;
}

} // namespace tipscope::testing
