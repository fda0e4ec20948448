// What the CFX tests against a broker share: why they cannot run here, and a sender's settings
// for the test's own RabbitMQ node (anonymous, on loopback, quick to retry).
#pragma once

#include "cfx/amqpsender.h"
#include "cfxconsumer.h"
#include "rabbitmqbroker.h"

namespace tipscope::testing {

inline QString cfxBrokerSkipReason() {
    const QString broker = RabbitMqBroker::skipReason();
    return broker.isEmpty() ? CfxConsumer::skipReason() : broker;
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
