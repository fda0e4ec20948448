// What the agent and the window say when a broker is not reached: each of libmosquitto's return
// codes, errno values and CONNACK refusals (MQTT 3.1.1 and 5) becomes a kind to act on and one
// sentence naming the broker, never a password; a TLS failure keeps OpenSSL's own words.
#include "mqtt/mqttproblem.h"
#include "testmain.h"

#include <QTest>
#include <cerrno>
#include <mosquitto.h>

namespace tst_mqttproblem {

using namespace tipscope::mqtt;

namespace {
const QString kWhere = QStringLiteral("broker.plant:8883");
}

class TestMqttProblem : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aRefusalIsTheKindItsCodeMeans_data();
    void aRefusalIsTheKindItsCodeMeans();
    void aLibraryErrorIsTheKindItsCodeMeans_data();
    void aLibraryErrorIsTheKindItsCodeMeans();
    void aTlsFailureKeepsOpenSslsWords();
    void aLookupOrAHangUpNamesWhatFailed();
};

void TestMqttProblem::aRefusalIsTheKindItsCodeMeans_data() {
    QTest::addColumn<int>("code");
    QTest::addColumn<bool>("v5");
    QTest::addColumn<MqttProblem>("problem");
    QTest::addColumn<QString>("says");
    QTest::newRow("3.1.1: protocol") << 1 << false << MqttProblem::Refused << "MQTT 3.1.1";
    QTest::newRow("3.1.1: client id") << 2 << false << MqttProblem::Refused << "client id";
    QTest::newRow("3.1.1: unavailable") << 3 << false << MqttProblem::Refused << "unavailable";
    QTest::newRow("3.1.1: credentials")
        << 4 << false << MqttProblem::BadCredentials << "bad user name or password";
    QTest::newRow("3.1.1: not authorised")
        << 5 << false << MqttProblem::NotAuthorised << "not authorised";
    QTest::newRow("3.1.1: unknown") << 9 << false << MqttProblem::Refused << "return code 9";
    QTest::newRow("5: protocol") << 132 << true << MqttProblem::Refused << "MQTT 5";
    QTest::newRow("5: credentials")
        << 134 << true << MqttProblem::BadCredentials << "bad user name or password";
    QTest::newRow("5: not authorised")
        << 135 << true << MqttProblem::NotAuthorised << "not authorised";
    QTest::newRow("5: banned") << 138 << true << MqttProblem::NotAuthorised << "not authorised";
    QTest::newRow("5: busy") << 137 << true << MqttProblem::Refused << "unavailable";
    QTest::newRow("5: unknown") << 153 << true << MqttProblem::Refused << "reason code 153";
}

void TestMqttProblem::aRefusalIsTheKindItsCodeMeans() {
    QFETCH(int, code);
    QFETCH(bool, v5);
    QFETCH(MqttProblem, problem);
    QFETCH(QString, says);
    const MqttProblemReport r =
        describeConnack(code, v5 ? MqttProtocol::V5 : MqttProtocol::V311, kWhere);
    QCOMPARE(r.problem, problem);
    QVERIFY2(r.text.contains(kWhere) && r.text.contains(says), qPrintable(r.text));
}

void TestMqttProblem::aLibraryErrorIsTheKindItsCodeMeans_data() {
    QTest::addColumn<int>("rc");
    QTest::addColumn<int>("errnoValue");
    QTest::addColumn<MqttProblem>("problem");
    QTest::addColumn<QString>("says");
    QTest::newRow("refused") << int(MOSQ_ERR_ERRNO) << ECONNREFUSED << MqttProblem::Unreachable
                             << "connection refused";
    QTest::newRow("reset") << int(MOSQ_ERR_ERRNO) << ECONNRESET << MqttProblem::ConnectionLost
                           << "closed the connection";
    QTest::newRow("no route") << int(MOSQ_ERR_ERRNO) << EHOSTUNREACH << MqttProblem::Unreachable
                              << "cannot be reached";
    // libmosquitto's sign that OpenSSL failed, said or not.
    QTest::newRow("EPROTO") << int(MOSQ_ERR_ERRNO) << EPROTO << MqttProblem::TlsFailure
                            << "TLS handshake";
    QTest::newRow("lookup") << int(MOSQ_ERR_EAI) << 0 << MqttProblem::HostNotFound
                            << "cannot be resolved";
    QTest::newRow("keep-alive") << int(MOSQ_ERR_KEEPALIVE) << 0 << MqttProblem::ConnectionLost
                                << "keep-alive";
    QTest::newRow("lost") << int(MOSQ_ERR_CONN_LOST) << 0 << MqttProblem::ConnectionLost
                          << "was lost";
    QTest::newRow("malformed") << int(MOSQ_ERR_MALFORMED_PACKET) << 0 << MqttProblem::ProtocolError
                               << "not valid MQTT";
    QTest::newRow("anything else") << int(MOSQ_ERR_NOMEM) << 0 << MqttProblem::ConnectionLost
                                   << QString::fromUtf8(mosquitto_strerror(MOSQ_ERR_NOMEM));
}

void TestMqttProblem::aLibraryErrorIsTheKindItsCodeMeans() {
    QFETCH(int, rc);
    QFETCH(int, errnoValue);
    QFETCH(MqttProblem, problem);
    QFETCH(QString, says);
    const MqttProblemReport r = describeLibraryError(rc, errnoValue, kWhere, QString());
    QCOMPARE(r.problem, problem);
    QVERIFY2(r.text.contains(kWhere) && r.text.contains(says), qPrintable(r.text));
    // Success is no problem, and says nothing.
    const MqttProblemReport ok = describeLibraryError(MOSQ_ERR_SUCCESS, 0, kWhere, QString());
    QCOMPARE(ok.problem, MqttProblem::None);
    QVERIFY(ok.text.isEmpty());
}

void TestMqttProblem::aTlsFailureKeepsOpenSslsWords() {
    const QString openssl = QStringLiteral("certificate verify failed");
    const MqttProblemReport r = describeLibraryError(MOSQ_ERR_TLS, 0, kWhere, openssl);
    QCOMPARE(r.problem, MqttProblem::TlsFailure);
    QVERIFY2(r.text.contains(kWhere) && r.text.endsWith(openssl), qPrintable(r.text));
    const MqttProblemReport viaErrno =
        describeLibraryError(MOSQ_ERR_ERRNO, EPROTO, kWhere, openssl);
    QCOMPARE(viaErrno.text, r.text);
}

void TestMqttProblem::aLookupOrAHangUpNamesWhatFailed() {
    const MqttProblemReport lookup =
        describeLookupFailure(QStringLiteral("broker.plant"), QStringLiteral("Name not known"));
    QCOMPARE(lookup.problem, MqttProblem::HostNotFound);
    QVERIFY2(lookup.text.contains(QStringLiteral("broker.plant")) &&
                 lookup.text.contains(QStringLiteral("Name not known")),
             qPrintable(lookup.text));
    const MqttProblemReport hangUp = describeHangUp(kWhere);
    QCOMPARE(hangUp.problem, MqttProblem::Unreachable);
    QVERIFY2(hangUp.text.contains(kWhere), qPrintable(hangUp.text));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestMqttProblem)

} // namespace tst_mqttproblem

#include "tst_mqttproblem.moc"
