// The work context's JSON, which arrives from files, workspaces and the broker: it round-trips;
// a missing field is empty and text is trimmed; a field that is not text, too long, or holding a
// control or format character (an ANSI escape, a right-to-left override) is refused by its name,
// before anything is stamped with it.
#include "model/context/workcontextjson.h"
#include "testmain.h"

#include <QTest>

namespace tst_workcontextjson {

using namespace tipscope::model;

class TestWorkContextJson : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aContextRoundTrips();
    void aMissingFieldIsEmptyAndTextIsTrimmed();
    void whatCannotBeKeptIsRefusedByItsName_data();
    void whatCannotBeKeptIsRefusedByItsName();
    void theLongestFieldKeptIsTheLimit();
};

void TestWorkContextJson::aContextRoundTrips() {
    const WorkContext context{QStringLiteral("WO-1234"), QStringLiteral("SN-0042"),
                              QStringLiteral("Ana Müller")};
    const auto back = workContextFromJson(workContextToJson(context));
    QVERIFY2(back, qPrintable(back ? QString() : back.error()));
    QCOMPARE(*back, context);
    QCOMPARE(workContextToJson(context).value(QStringLiteral("board_serial")).toString(),
             QStringLiteral("SN-0042"));
}

void TestWorkContextJson::aMissingFieldIsEmptyAndTextIsTrimmed() {
    const auto context =
        workContextFromJson({{QStringLiteral("board_serial"), QStringLiteral("  SN-7 \t")},
                             {QStringLiteral("shift"), 3}}); // not ours: ignored
    QVERIFY(context);
    QCOMPARE(context->boardSerial, QStringLiteral("SN-7"));
    QVERIFY(context->workOrder.isEmpty());
    QVERIFY(context->operatorName.isEmpty());
    QVERIFY(workContextFromJson({})->isEmpty());
}

void TestWorkContextJson::whatCannotBeKeptIsRefusedByItsName_data() {
    QTest::addColumn<QJsonObject>("json");
    QTest::addColumn<QString>("said");
    QTest::newRow("a number") << QJsonObject{{QStringLiteral("work_order"), 1234}}
                              << QStringLiteral("work_order must be text");
    QTest::newRow("null") << QJsonObject{{QStringLiteral("operator"), QJsonValue()}}
                          << QStringLiteral("operator must be text");
    QTest::newRow("too long") << QJsonObject{{QStringLiteral("board_serial"), QString(65, 'x')}}
                              << QStringLiteral("board_serial has 65 characters; at most 64");
    QTest::newRow("an escape") << QJsonObject{{QStringLiteral("operator"),
                                               QStringLiteral("ana\x1b[2J")}}
                               << QStringLiteral("operator holds a control character");
    QTest::newRow("a right-to-left override")
        << QJsonObject{{QStringLiteral("board_serial"), QStringLiteral("SN-1\u202e24")}}
        << QStringLiteral("board_serial holds a control character");
}

void TestWorkContextJson::whatCannotBeKeptIsRefusedByItsName() {
    QFETCH(QJsonObject, json);
    QFETCH(QString, said);
    const auto context = workContextFromJson(json);
    QVERIFY(!context);
    QVERIFY2(context.error().startsWith(said), qPrintable(context.error()));
}

void TestWorkContextJson::theLongestFieldKeptIsTheLimit() {
    const QString longest(kMaxWorkContextChars, QLatin1Char('7'));
    const auto context = workContextFromJson({{QStringLiteral("work_order"), longest}});
    QVERIFY(context);
    QCOMPARE(context->workOrder, longest);
    QVERIFY(workContextProblem(*context).isEmpty());
    QVERIFY(!workContextProblem({longest + QLatin1Char('7'), {}, {}}).isEmpty());
}

TIPSCOPE_TEST_GUILESS_MAIN(TestWorkContextJson)

} // namespace tst_workcontextjson
#include "tst_workcontextjson.moc"
