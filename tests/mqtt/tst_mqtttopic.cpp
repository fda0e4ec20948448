// Topic levels made from people's names, and matching subscription filters with + and #, as the
// broker matches them (MQTT 3.1.1, 4.7).
#include "mqtt/mqtttopic.h"
#include "testmain.h"

#include <QTest>

namespace tst_mqtttopic {

using namespace tipscope::mqtt;

class TstMqttTopic : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void levelIsLowerCasedAndOtherCharactersBecomeUnderscores_data();
    void levelIsLowerCasedAndOtherCharactersBecomeUnderscores();
    void filterMatchesTopicsAsTheBrokerDoes_data();
    void filterMatchesTopicsAsTheBrokerDoes();
    void topicNamesAndFiltersAreValidated_data();
    void topicNamesAndFiltersAreValidated();
};

void TstMqttTopic::levelIsLowerCasedAndOtherCharactersBecomeUnderscores_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("level");
    QTest::newRow("kept as it is") << "01-dme"
                                   << "01-dme";
    QTest::newRow("upper case") << "Line-A"
                                << "line-a";
    QTest::newRow("space and dot") << "Hall 2.1"
                                   << "hall_2_1";
    QTest::newRow("slash would add a level") << "a/b"
                                             << "a_b";
    QTest::newRow("wildcards") << "+#"
                               << "__";
    QTest::newRow("umlaut") << QString::fromUtf8("Lötstation") << "l_tstation";
    QTest::newRow("one per code point") << QString::fromUtf8("a\U0001F525b") << "a_b";
    QTest::newRow("underscore and dash kept") << "_x-y_"
                                              << "_x-y_";
    QTest::newRow("empty becomes one underscore") << ""
                                                  << "_";
    QTest::newRow("dollar") << "$SYS"
                            << "_sys";
}

void TstMqttTopic::levelIsLowerCasedAndOtherCharactersBecomeUnderscores() {
    QFETCH(QString, name);
    QFETCH(QString, level);
    QCOMPARE(sanitizeTopicLevel(name), level);
}

void TstMqttTopic::filterMatchesTopicsAsTheBrokerDoes_data() {
    QTest::addColumn<QString>("filter");
    QTest::addColumn<QString>("topic");
    QTest::addColumn<bool>("matches");
    QTest::newRow("exact") << "tipscope/v1/s/l/01-dme/status"
                           << "tipscope/v1/s/l/01-dme/status" << true;
    QTest::newRow("different") << "tipscope/v1/s/l/01-dme/status"
                               << "tipscope/v1/s/l/01-dme/info" << false;
    QTest::newRow("hash matches all below") << "tipscope/v1/#"
                                            << "tipscope/v1/s/l/d/joint" << true;
    QTest::newRow("hash matches the parent") << "tipscope/v1/#"
                                             << "tipscope/v1" << true;
    QTest::newRow("hash alone") << "#"
                                << "a/b/c" << true;
    QTest::newRow("hash needs the prefix") << "tipscope/v1/#"
                                           << "tipscope/v2/s" << false;
    QTest::newRow("plus is one level") << "tipscope/v1/+/+/+/status"
                                       << "tipscope/v1/s/l/d/status" << true;
    QTest::newRow("plus is not two levels") << "tipscope/+/status"
                                            << "tipscope/a/b/status" << false;
    QTest::newRow("plus matches an empty level") << "a/+/c"
                                                 << "a//c" << true;
    QTest::newRow("plus needs its level") << "a/+"
                                          << "a" << false;
    QTest::newRow("longer topic") << "a/b"
                                  << "a/b/c" << false;
    QTest::newRow("case matters") << "a/B"
                                  << "a/b" << false;
    QTest::newRow("hash skips $ topics") << "#"
                                         << "$SYS/broker/uptime" << false;
    QTest::newRow("plus skips $ topics") << "+/broker/uptime"
                                         << "$SYS/broker/uptime" << false;
    QTest::newRow("$ filter matches $ topics") << "$SYS/#"
                                               << "$SYS/broker/uptime" << true;
    QTest::newRow("invalid filter matches nothing") << "a/#/b"
                                                    << "a/x/b" << false;
    QTest::newRow("wildcard topic matches nothing") << "#"
                                                    << "a/+" << false;
}

void TstMqttTopic::filterMatchesTopicsAsTheBrokerDoes() {
    QFETCH(QString, filter);
    QFETCH(QString, topic);
    QFETCH(bool, matches);
    QCOMPARE(topicMatchesFilter(topic, filter), matches);
}

void TstMqttTopic::topicNamesAndFiltersAreValidated_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("validName");
    QTest::addColumn<bool>("validFilter");
    QTest::newRow("plain") << "a/b" << true << true;
    QTest::newRow("empty") << "" << false << false;
    QTest::newRow("leading slash") << "/a" << true << true;
    QTest::newRow("plus level") << "a/+/b" << false << true;
    QTest::newRow("plus inside a level") << "a/b+/c" << false << false;
    QTest::newRow("hash last") << "a/#" << false << true;
    QTest::newRow("hash not last") << "a/#/b" << false << false;
    QTest::newRow("hash inside a level") << "a/b#" << false << false;
    QTest::newRow("NUL") << QStringLiteral("a") + QChar(u'\0') << false << false;
    QTest::newRow("too long") << QString(65536, u'a') << false << false;
}

void TstMqttTopic::topicNamesAndFiltersAreValidated() {
    QFETCH(QString, text);
    QFETCH(bool, validName);
    QFETCH(bool, validFilter);
    QCOMPARE(isValidTopicName(text), validName);
    QCOMPARE(isValidTopicFilter(text), validFilter);
}

TIPSCOPE_TEST_GUILESS_MAIN(TstMqttTopic)

} // namespace tst_mqtttopic
#include "tst_mqtttopic.moc"
