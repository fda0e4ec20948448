// JointLimitRules: the most specific rule judges a joint; rules read from JSON and from the
// command line's words, and a bad rule is refused with the reason.
#include "model/joints/jointlimitrules.h"
#include "testmain.h"

#include <QJsonArray>
#include <QTest>

namespace tst_jointlimitrules {

using namespace tipscope::model;

class TestJointLimitRules : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void theMostSpecificRuleWins_data();
    void theMostSpecificRuleWins();
    void aRuleForTheSamePortAndToolReplacesTheEarlierOne();
    void rulesSurviveTheirJson();
    void aRuleIsReadFromWords();
    void aBadRuleIsRefusedWithTheReason_data();
    void aBadRuleIsRefusedWithTheReason();
    void badJsonIsRefusedNamingTheRule();
};

void TestJointLimitRules::theMostSpecificRuleWins_data() {
    QTest::addColumn<int>("port");
    QTest::addColumn<QString>("tool");
    QTest::addColumn<qint64>("maxRecoveryMs");
    QTest::addColumn<int>("maxDipK");
    QTest::newRow("nothing matches: defaults") << 3 << "T210" << qint64(5000) << 80;
    QTest::newRow("the port") << 1 << "T210" << qint64(4000) << 80;
    QTest::newRow("the tool, any case") << 2 << "c245" << qint64(3000) << 60;
    QTest::newRow("port and tool") << 1 << "C245" << qint64(2000) << 60;
}

void TestJointLimitRules::theMostSpecificRuleWins() {
    QFETCH(int, port);
    QFETCH(QString, tool);
    QFETCH(qint64, maxRecoveryMs);
    QFETCH(int, maxDipK);
    JointLimitRules rules;
    // Added most specific first, to show the order of adding does not decide.
    rules.add({1, QStringLiteral("C245"), 2000, std::nullopt, std::nullopt});
    rules.add({std::nullopt, QStringLiteral("C245"), 3000, 60, std::nullopt});
    rules.add({1, {}, 4000, std::nullopt, std::nullopt});
    const JointLimits limits = rules.limitsFor(port, tool);
    QCOMPARE(limits.maxRecoveryMs, maxRecoveryMs);
    QCOMPARE(limits.maxDipK, maxDipK);
    QCOMPARE(limits.bandK, JointLimits{}.bandK);
}

void TestJointLimitRules::aRuleForTheSamePortAndToolReplacesTheEarlierOne() {
    JointLimitRules rules;
    rules.add({2, QStringLiteral("C245"), 2000, std::nullopt, std::nullopt});
    rules.add({2, QStringLiteral("c245"), 2500, std::nullopt, std::nullopt});
    QCOMPARE(rules.rules().size(), 1);
    QCOMPARE(rules.limitsFor(2, QStringLiteral("C245")).maxRecoveryMs, 2500);
}

void TestJointLimitRules::rulesSurviveTheirJson() {
    JointLimits defaults;
    defaults.maxRecoveryMs = 4500;
    defaults.maxDipK = 70;
    defaults.wearShare = 0.25;
    JointLimitRules rules(defaults);
    rules.add({1, QStringLiteral("C245"), 3500, 60, std::nullopt});
    rules.add({std::nullopt, QStringLiteral("C470"), std::nullopt, std::nullopt, 0.5});
    const auto back = JointLimitRules::fromJson(rules.toJson());
    QVERIFY2(back, qPrintable(back.error()));
    QVERIFY(back.value() == rules);
}

void TestJointLimitRules::aRuleIsReadFromWords() {
    const auto rule =
        JointLimitRules::parseRule(QStringLiteral("port=2, tool=C245, recovery=3.5,dip=60"));
    QVERIFY2(rule, qPrintable(rule.error()));
    QCOMPARE(rule.value().port, 2);
    QCOMPARE(rule.value().tool, QStringLiteral("C245"));
    QCOMPARE(rule.value().maxRecoveryMs, 3500);
    QCOMPARE(rule.value().maxDipK, 60);
    QVERIFY(!rule.value().wearShare);
    QCOMPARE(JointLimitRules::ruleText(rule.value()),
             QStringLiteral("port=2,tool=C245,recovery=3.5,dip=60"));
}

void TestJointLimitRules::aBadRuleIsRefusedWithTheReason_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("reason");
    QTest::newRow("no limit") << "port=1,tool=C245"
                              << "sets no limit";
    QTest::newRow("unknown word") << "recovery=3,speed=4"
                                  << "“speed=4” is not a limit";
    QTest::newRow("port 9") << "port=9,dip=50"
                            << "a port is a number from 1 to 4";
    QTest::newRow("negative recovery") << "recovery=-1"
                                       << "more than 0 s";
    QTest::newRow("fractional dip") << "dip=50.5"
                                    << "whole number of kelvin";
    QTest::newRow("comma decimal") << "recovery=3,5"
                                   << "“5” is not a limit";
}

void TestJointLimitRules::aBadRuleIsRefusedWithTheReason() {
    QFETCH(QString, text);
    QFETCH(QString, reason);
    const auto rule = JointLimitRules::parseRule(text);
    QVERIFY(!rule);
    QVERIFY2(rule.error().contains(reason), qPrintable(rule.error()));
}

void TestJointLimitRules::badJsonIsRefusedNamingTheRule() {
    const QJsonObject json{
        {QStringLiteral("rules"),
         QJsonArray{QJsonObject{{QStringLiteral("port"), 1}, {QStringLiteral("max_recovery_s"), 3}},
                    QJsonObject{{QStringLiteral("max_dip_k"), QStringLiteral("deep")}}}}};
    const auto rules = JointLimitRules::fromJson(json);
    QVERIFY(!rules);
    QVERIFY2(rules.error().contains(QStringLiteral("rule 2")), qPrintable(rules.error()));
    QVERIFY2(rules.error().contains(QStringLiteral("max_dip_k")), qPrintable(rules.error()));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestJointLimitRules)

} // namespace tst_jointlimitrules
#include "tst_jointlimitrules.moc"
