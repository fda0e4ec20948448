// One line for the person who set the CFX endpoint up, from an AMQP error condition: what to fix
// (the login, the broker's AMQP 1.0 plugin, the address, the exchange, TLS, the host and port),
// with the broker's own words kept at the end; words it does not know are passed on as they are.
// The conditions are worded as Qpid Proton and RabbitMQ word theirs.
#include "cfx/amqpproblem.h"
#include "testmain.h"

#include <QTest>

namespace tst_amqpproblem {

using tipscope::cfx::describeAmqpError;

namespace {
const QString kAddress = QStringLiteral("/exchange/cfx");
}

class TestAmqpProblem : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void eachConditionSaysWhatToFix_data();
    void eachConditionSaysWhatToFix();
    void wordsItDoesNotKnowArePassedOn();
};

void TestAmqpProblem::eachConditionSaysWhatToFix_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("description");
    QTest::addColumn<QString>("says");
    QTest::newRow("login") << "amqp:unauthorized-access"
                           << "Authentication failed [mechanism PLAIN]"
                           << "refused the login";
    QTest::newRow("no AMQP 1.0 plugin") << "proton:io"
                                        << "AMQP header mismatch: Insufficient data"
                                        << "rabbitmq_amqp1_0";
    QTest::newRow("address form") << "amqp:not-found"
                                  << "unknown_destination: \"cfx\"" << kAddress;
    QTest::newRow("no exchange") << "amqp:not-found"
                                 << "no exchange 'cfx' in vhost '/'"
                                 << "declare it there";
    QTest::newRow("TLS") << "amqp:connection:framing-error"
                         << "SSL Failure: certificate verify failed"
                         << "CA file";
    QTest::newRow("nothing listens") << "proton:io"
                                     << "connection refused - connecting to 127.0.0.1:5671"
                                     << "check the host and port";
    QTest::newRow("host name") << "proton:io"
                               << "Name or service not known - resolving broker.plant"
                               << "host name cannot be found";
}

void TestAmqpProblem::eachConditionSaysWhatToFix() {
    QFETCH(QString, name);
    QFETCH(QString, description);
    QFETCH(QString, says);
    const QString line = describeAmqpError(name, description, kAddress);
    QVERIFY2(line.contains(says), qPrintable(line));
    // The broker's own words close the line.
    QVERIFY2(line.endsWith(QStringLiteral("(The broker said: %1)").arg(description)),
             qPrintable(line));
    QVERIFY(!line.contains(QLatin1Char('\n')));
}

void TestAmqpProblem::wordsItDoesNotKnowArePassedOn() {
    QCOMPARE(describeAmqpError(QStringLiteral("amqp:resource-limit-exceeded"),
                               QStringLiteral("queue full"), kAddress),
             QStringLiteral("The broker said: queue full."));
    QCOMPARE(describeAmqpError(QStringLiteral("amqp:internal-error"), QString(), kAddress),
             QStringLiteral("The broker said: amqp:internal-error."));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestAmqpProblem)

} // namespace tst_amqpproblem

#include "tst_amqpproblem.moc"
