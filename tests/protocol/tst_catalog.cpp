// The command catalog covers every command of the four guides with complete, consistent data.
#include "protocol/catalog.h"
#include "protocol/valuecodec.h"
#include "support/testcatalog.h"
#include "testmain.h"

#include <QSet>
#include <QTest>

namespace tst_catalog {

using namespace tipscope::protocol;

namespace {
const QStringList kUcrGroup = {"UCR", "ALE", "NAE", "DDE", "DME", "HDE"};
const QStringList kRobot = {"DDR", "HDR"};

struct Expected {
    const char *pattern;
    const char *access;
    QStringList families;
};

// Transcribed from the command tables of the four guides (R-TT is on the wire as TT0, see
// docs/protocol-notes.md).
QList<Expected> guideCommands() {
    const QStringList st = kUcrGroup + kRobot;
    return {
        {"PSx", "rw", st},
        {"STx", "rw", st},
        {"TTx", "r", st},
        {"PPx", "r", st},
        {"Axy", "rw", st},
        {"MAT", "rw", st},
        {"MIT", "rw", st},
        {"Sxy", "rw", st},
        {"Dxy", "rw", st},
        {"Hxy", "rw", st},
        {"EDx", "r", st},
        {"TT0", "r", st},
        {"QTx", "r", st},
        {"HAx", "rw", st},
        {"LAx", "rw", st},
        {"HDx", "rw", kUcrGroup},
        {"LDx", "rw", kUcrGroup},
        {"TAx", "r", st},
        {"SMN", "r", st},
        {"CTx", "r", st},
        {"PEx", "r", st},
        {"SER", "r", st},
        {"RST", "w", kUcrGroup},
        {"RSP", "w", st},
        {"CPx", "r", st},
        {"CNx", "r", st},
        {"CSx", "r", st},
        {"CHx", "r", st},
        {"CWx", "r", st},
        {"CCx", "r", st},
        {"CDx", "r", st},
        {"NVS", "w", st},
        {"SAD", "w", kUcrGroup},
        {"FST", "r", {"UCR"}},
        {"SVR", "r", kUcrGroup},
        {"DCx", "r", {"ALE"}},
        {"DLx", "r", {"ALE"}},
        {"IFE", "w", {"UCR"}},
        {"MOD", "rw", {"ALE", "SFR"}},
        {"LEN", "rw", {"ALE", "SFR"}},
        {"FEE", "r", {"ALE"}},
        {"SPD", "rw", {"ALE", "SFR"}},
        {"DIA", "rw", {"ALE"}},
        {"BCK", "rw", {"ALE"}},
        {"WCD", "rw", {"ALE"}},
        {"STR", "w", {"ALE"}},
        {"STP", "w", {"ALE"}},
        {"PLM", "rw", kRobot},
        {"SFD", "w", {"SFR"}},
        {"SSD", "w", {"SFR"}},
        {"THI", "rw", {"SFR"}},
        {"TES", "rw", {"SFR"}},
        {"ECV", "rw", {"SFR"}},
        {"CPT", "r", {"SFR"}},
        {"CPP", "rw", {"SFR"}},
        {"CFT", "r", {"SFR"}},
        {"CFP", "rw", {"SFR"}},
        {"CTT", "r", {"SFR"}},
        {"CTP", "rw", {"SFR"}},
        {"SLD", "w", {"SFR"}},
        {"NVS", "w", {"SFR"}},
        {"SAD", "w", {"SFR"}},
        {"RSP", "w", {"SFR"}},
        {"FDS", "r", {"SFR"}},
        {"SMN", "r", {"SFR"}},
        {"FDL", "r", {"SFR"}},
    };
}

QByteArray concrete(const QString &pattern, const FamilyInfo &f) {
    QString c = pattern;
    c.replace(QLatin1Char('x'), QStringLiteral("1"));
    if (!f.tools.isEmpty())
        c.replace(QLatin1Char('y'), QString::number(f.tools.first()));
    return c.toLatin1();
}

// What to check for `code` read from the error of `port` (0: the station's own) of `family`;
// nullopt when the family has no such error. (resolve() by role finds only the first command of
// a role, the port's PEx, so the station's own error is looked for among all.)
std::optional<QString> adviceFor(const Catalog &cat, const QString &family, int port, int code) {
    for (const ResolvedCommand &r : cat.expand(family, Direction::Read))
        if (r.spec->role == Role::Error && r.port == port)
            return cat.errorAdvice(r, code, Wording::Catalog);
    return std::nullopt;
}

// A catalog with one family X, whose station errors (read with SER) are the table "errors" and
// whose advice tables are `advice`.
tipscope::base::Outcome<Catalog> catalogWithAdvice(const QByteArray &advice) {
    const QByteArray fams =
        R"({"families":{"X":{"kind":"station","stationErrors":"errors"}},"units":{"none":{}},)"
        R"("tables":{"errors":{"0":"OK","1":"one","2":"two","3":"three"},"advice":)" +
        advice + "}}";
    return Catalog::load(
        fams, R"({"commands":[{"code":"SER","access":"r","kind":"enum","families":["X"],)"
              R"("table":"$stationErrors","group":"errors","role":"error"}]})");
}
} // namespace

class TestCatalog : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aRoleOnAPortResolvesToItsWireCode_data();
    void aRoleOnAPortResolvesToItsWireCode();
    void everyCommandOfTheGuidesIsPresentForItsFamilies();
    void everyEntryHasCompleteMetadata();
    void noFamilyHasTwoEntriesForTheSameCodeAndDirection();
    void rangesAndStepsAreConsistent();
    void familiesCarryPortsToolsLimitsAndAddresses();
    void resolveRejectsPortsAndToolsTheFamilyDoesNotHave();
    void familyIsFoundFromTheModelName();
    void errorTablesExplainCodesIncludingTheMisprintedOne();
    void errorTablesThatMeanTheSameShareOneAdvice_data();
    void errorTablesThatMeanTheSameShareOneAdvice();
    void everyAdviceTextIsWrittenOnceInTheCatalog();
    void adviceTakenFromAnotherTableFollowsTheChainAndKeepsItsOwnTexts();
    void adviceFromNoTableOrFromItselfIsRefusedWithAReason_data();
    void adviceFromNoTableOrFromItselfIsRefusedWithAReason();
    void validationSaysWhatIsAllowed();
    void malformedCatalogDataIsRefusedWithAReason();
    void aRoleFindsOneValueAndOneActionPerPort();
    void rolesNameTheCommandsFrontEndsLookFor_data();
    void rolesNameTheCommandsFrontEndsLookFor();
    void aRoleNamesItsFirstCommandBeforeAFamilyIsKnown();
    void partialCountersPairWithATotalAndAResetButton();
    void unknownRolesAndGroupsAreRefusedWithAReason();
    void rolesAndGroupsReadBackTheirNames();
};

void TestCatalog::everyCommandOfTheGuidesIsPresentForItsFamilies() {
    const Catalog &cat = Catalog::builtin();
    int checked = 0;
    for (const Expected &e : guideCommands()) {
        for (const QString &fam : e.families) {
            const FamilyInfo *f = cat.family(fam);
            QVERIFY(f);
            const QByteArray code = concrete(QLatin1String(e.pattern), *f);
            const bool r = QByteArray(e.access).contains('r');
            const bool w = QByteArray(e.access).contains('w');
            QVERIFY2(!r || cat.resolve(fam, code, Direction::Read),
                     qPrintable(QStringLiteral("%1 R-%2 missing").arg(fam, code)));
            QVERIFY2(!w || cat.resolve(fam, code, Direction::Write),
                     qPrintable(QStringLiteral("%1 W-%2 missing").arg(fam, code)));
            ++checked;
        }
    }
    QVERIFY(checked > 250);
}

void TestCatalog::everyEntryHasCompleteMetadata() {
    const Catalog &cat = Catalog::builtin();
    for (const CommandSpec &s : cat.commands()) {
        const QString id = s.pattern + QLatin1Char(' ') + s.families.join(QLatin1Char(','));
        QVERIFY2(!s.name.isEmpty() && !s.description.isEmpty(), qPrintable(id));
        QVERIFY2(!s.poll.isEmpty() && !groupName(s.group).isEmpty(), qPrintable(id));
        QVERIFY2(!s.families.isEmpty(), qPrintable(id));
        QVERIFY2(cat.unit(s.unit), qPrintable(id));
        QVERIFY2(!s.dangerous || !s.danger.isEmpty(), qPrintable(id + QStringLiteral(": danger")));
        if (s.kind == ValueKind::Action)
            QVERIFY2(s.fixedData.size() == 5, qPrintable(id));
        if (s.kind == ValueKind::Flags)
            QVERIFY2(!cat.digits(s.digitsTable).isEmpty(), qPrintable(id));
        for (const QString &fam : s.families) {
            const FamilyInfo *f = cat.family(fam);
            const auto r = cat.resolve(fam, concrete(s.pattern, *f),
                                       s.readable ? Direction::Read : Direction::Write);
            QVERIFY2(r, qPrintable(id));
            if (s.kind == ValueKind::Enum)
                QVERIFY2(!r->values.isEmpty(), qPrintable(id + QStringLiteral(": values")));
        }
    }
}

void TestCatalog::noFamilyHasTwoEntriesForTheSameCodeAndDirection() {
    const Catalog &cat = Catalog::builtin();
    for (const QString &fam : cat.familyNames()) {
        for (Direction d : {Direction::Read, Direction::Write}) {
            QSet<QByteArray> seen;
            int matches = 0;
            for (const ResolvedCommand &r : cat.expand(fam, d)) {
                QVERIFY2(!seen.contains(r.code), qPrintable(fam + QLatin1Char(' ') + r.code));
                seen.insert(r.code);
                ++matches;
            }
            QVERIFY(matches > 0 || (fam == QLatin1String("SFR") && d == Direction::Read));
        }
    }
}

void TestCatalog::rangesAndStepsAreConsistent() {
    const Catalog &cat = Catalog::builtin();
    for (const QString &fam : cat.familyNames()) {
        for (const ResolvedCommand &r : cat.expand(fam, Direction::Write)) {
            const CommandSpec &s = *r.spec;
            const QString id = fam + QLatin1Char(' ') + QString::fromLatin1(r.code);
            if (s.kind != ValueKind::Number && s.kind != ValueKind::Delay)
                continue;
            QVERIFY2(r.min < r.max, qPrintable(id));
            QVERIFY2(s.step >= 1 && (r.max - r.min) % s.step == 0, qPrintable(id));
            QVERIFY2(validate(r, r.min).isEmpty() && validate(r, r.max).isEmpty(), qPrintable(id));
            QVERIFY2(!validate(r, r.max + s.step).isEmpty(), qPrintable(id));
            if (s.step > 1)
                QVERIFY2(!validate(r, r.min + 1).isEmpty(), qPrintable(id));
            for (int special : s.special.keys())
                QVERIFY2(validate(r, special).isEmpty(), qPrintable(id));
            if (r.factoryDefault)
                QVERIFY2(validate(r, *r.factoryDefault).isEmpty(), qPrintable(id + " default"));
        }
    }
}

void TestCatalog::familiesCarryPortsToolsLimitsAndAddresses() {
    const Catalog &cat = Catalog::builtin();
    QCOMPARE(cat.familyNames(),
             QStringList({"UCR", "ALE", "NAE", "DDE", "DME", "HDE", "DDR", "HDR", "SFR"}));
    QCOMPARE(cat.family("DME")->ports, 4);
    QCOMPARE(cat.family("DDR")->ports, 2);
    QCOMPARE(cat.family("DDR")->tempMax, 450);
    QCOMPARE(cat.family("HDR")->maxPowerW, 270);
    QVERIFY(!cat.family("DDR")->addressedByDefault);
    QCOMPARE(cat.family("SFR")->defaultAddress, 10);
    QCOMPARE(cat.address("robot"), 0);
    QCOMPARE(cat.address("station"), 1);
    QCOMPARE(cat.address("feeder"), 10);
    QCOMPARE(cat.address("extractor"), 20);
    QCOMPARE(cat.table("$toolTable", "UCR").value(9), QStringLiteral("TRA245/TRA470"));
    QCOMPARE(cat.table("$toolTable", "DDR").value(7), QStringLiteral("NT105"));
}

void TestCatalog::resolveRejectsPortsAndToolsTheFamilyDoesNotHave() {
    const Catalog &cat = Catalog::builtin();
    QVERIFY(cat.resolve("DME", "ST4", Direction::Write));
    QVERIFY(!cat.resolve("DDR", "ST3", Direction::Write));
    QVERIFY(!cat.resolve("DME", "ST0", Direction::Write));
    QVERIFY(cat.resolve("UCR", "A19", Direction::Write));
    QVERIFY(!cat.resolve("UCR", "A11", Direction::Write));
    QVERIFY(!cat.resolve("DME", "TTx", Direction::Read));
    QVERIFY(!cat.resolve("DME", "TT1", Direction::Write));
    QVERIFY(!cat.resolve("DDR", "SVR", Direction::Read));
    QVERIFY(!cat.resolve("NOPE", "ST1", Direction::Read));
    const auto a = cat.resolve("DME", "A32", Direction::Write);
    QVERIFY(a);
    QCOMPARE(a->port, 3);
    QCOMPARE(a->tool, 2);
    QCOMPARE(cat.resolve("dme", "st1", Direction::Read)->code, QByteArray("ST1"));
}

void TestCatalog::familyIsFoundFromTheModelName() {
    const Catalog &cat = Catalog::builtin();
    QCOMPARE(cat.familyForModel("DDR"), QStringLiteral("DDR"));
    QCOMPARE(cat.familyForModel(" dme-2c "), QStringLiteral("DME"));
    QCOMPARE(cat.familyForModel("UCR470"), QStringLiteral("UCR"));
    QCOMPARE(cat.familyForModel("XYZ"), QString());
}

void TestCatalog::errorTablesExplainCodesIncludingTheMisprintedOne() {
    const Catalog &cat = Catalog::builtin();
    const Wording w = Wording::Catalog;
    QVERIFY(cat.nakText(5, w).contains("Robot mode"));
    QCOMPARE(cat.nakText(9, w), cat.nakText(99999, w));
    QCOMPARE(cat.portErrorText("DME", 80000, w), cat.portErrorText("DME", 8, w));
    QVERIFY(cat.portErrorText("DDR", 8, w).contains("MOS"));
    QVERIFY(cat.stationErrorText("UCR", 7, w).contains("Warning"));
    QVERIFY(cat.stationErrorText("DDR", 7, w).contains("Unknown"));
    QCOMPARE(cat.severity("portErrorsUcrGroup", 9), QStringLiteral("warning"));
    QCOMPARE(cat.severity("portErrorsUcrGroup", 1), QStringLiteral("error"));
    QVERIFY(cat.feederErrorText(3, w).contains("3"));
}

void TestCatalog::errorTablesThatMeanTheSameShareOneAdvice_data() {
    QTest::addColumn<QString>("family");
    QTest::addColumn<int>("port");
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("sameAsFamily");
    QTest::addColumn<int>("sameAsPort");
    QTest::addColumn<int>("sameAsCode");
    // The robot stations' errors mean what the UCR group's do, code for code.
    for (const QString &robot : kRobot) {
        for (int code = 1; code <= 4; ++code)
            QTest::addRow("%s station %d", qPrintable(robot), code)
                << robot << 0 << code << QStringLiteral("DME") << 0 << code;
        for (int code = 1; code <= 8; ++code)
            QTest::addRow("%s port %d", qPrintable(robot), code)
                << robot << 1 << code << QStringLiteral("DME") << 1 << code;
    }
    // A code the robot station's guide does not list gets the advice for unlisted codes, not
    // what the UCR group's table says for it; a station's and a port's unlisted codes share one.
    QTest::newRow("DDR station 5 is unlisted") << "DDR" << 0 << 5 << "DME" << 0 << 42;
    QTest::newRow("HDR port 9 is unlisted") << "HDR" << 1 << 9 << "DME" << 1 << 42;
    QTest::newRow("a port's unlisted code") << "DME" << 1 << 42 << "DME" << 0 << 42;
}

void TestCatalog::errorTablesThatMeanTheSameShareOneAdvice() {
    QFETCH(QString, family);
    QFETCH(int, port);
    QFETCH(int, code);
    QFETCH(QString, sameAsFamily);
    QFETCH(int, sameAsPort);
    QFETCH(int, sameAsCode);
    const Catalog &cat = Catalog::builtin();
    const auto advice = adviceFor(cat, family, port, code);
    const auto same = adviceFor(cat, sameAsFamily, sameAsPort, sameAsCode);
    QVERIFY(advice && same);
    QVERIFY(!advice->isEmpty());
    QCOMPARE(*advice, *same);
    if (sameAsCode != code) // an unlisted code: the referenced table's text for it is not used
        QVERIFY(advice != adviceFor(cat, sameAsFamily, sameAsPort, code));
}

void TestCatalog::everyAdviceTextIsWrittenOnceInTheCatalog() {
    const QJsonObject advice =
        QJsonDocument::fromJson(tipscope::testing::builtinCatalogFile("families.json"))
            .object()
            .value(QLatin1String("tables"))
            .toObject()
            .value(QLatin1String("advice"))
            .toObject();
    QVERIFY(advice.size() >= 5);
    QMap<QString, QString> written; // text -> where
    for (auto table = advice.begin(); table != advice.end(); ++table) {
        const QJsonObject codes = table.value().toObject();
        for (auto it = codes.begin(); it != codes.end(); ++it) {
            if (it.key() == QLatin1String("adviceFrom"))
                continue;
            const QString where = table.key() + QLatin1Char(' ') + it.key();
            QVERIFY2(!written.contains(it.value().toString()),
                     qPrintable(where + QStringLiteral(" repeats ") +
                                written.value(it.value().toString())));
            written.insert(it.value().toString(), where);
        }
    }
}

void TestCatalog::adviceTakenFromAnotherTableFollowsTheChainAndKeepsItsOwnTexts() {
    const auto cat = catalogWithAdvice(
        R"({"errors":{"adviceFrom":"middle","2":"own two"},)"
        R"("middle":{"adviceFrom":"base","1":"middle one"},)"
        R"("base":{"1":"base one","2":"base two","3":"base three","other":"unlisted"}})");
    QVERIFY2(cat, qPrintable(cat.error()));
    QCOMPARE(adviceFor(*cat, "X", 0, 1).value_or("none"), QStringLiteral("middle one"));
    QCOMPARE(adviceFor(*cat, "X", 0, 2).value_or("none"), QStringLiteral("own two"));
    QCOMPARE(adviceFor(*cat, "X", 0, 3).value_or("none"), QStringLiteral("base three"));
    QCOMPARE(adviceFor(*cat, "X", 0, 7).value_or("none"), QStringLiteral("unlisted"));
    QCOMPARE(adviceFor(*cat, "X", 0, 0).value_or("none"), QString()); // no error
}

void TestCatalog::adviceFromNoTableOrFromItselfIsRefusedWithAReason_data() {
    QTest::addColumn<QByteArray>("advice");
    QTest::addColumn<QString>("reason");
    QTest::newRow("no such table")
        << QByteArray(R"({"errors":{"adviceFrom":"missing","1":"x"}})")
        << "advice for errors takes its texts from 'missing', which is no advice table";
    QTest::newRow("a name that is no text")
        << QByteArray(R"({"errors":{"adviceFrom":3}})")
        << "advice for errors takes its texts from '', which is no advice table";
    QTest::newRow("the end of a chain")
        << QByteArray(R"({"errors":{"adviceFrom":"a"},"a":{"adviceFrom":"b"}})")
        << "advice for a takes its texts from 'b', which is no advice table";
    QTest::newRow("itself") << QByteArray(R"({"errors":{"adviceFrom":"errors"}})")
                            << "advice for errors takes its texts from itself: errors -> errors";
    QTest::newRow("a cycle") << QByteArray(R"({"errors":{"adviceFrom":"a"},"a":{"adviceFrom":"b"},)"
                                           R"("b":{"adviceFrom":"a"}})")
                             << "advice for a takes its texts from itself: a -> b -> a";
}

void TestCatalog::adviceFromNoTableOrFromItselfIsRefusedWithAReason() {
    QFETCH(QByteArray, advice);
    QFETCH(QString, reason);
    const auto cat = catalogWithAdvice(advice);
    QVERIFY(!cat);
    QCOMPARE(cat.error(), reason);
}

void TestCatalog::validationSaysWhatIsAllowed() {
    const Catalog &cat = Catalog::builtin();
    const auto st = *cat.resolve("DME", "ST1", Direction::Write);
    QCOMPARE(validate(st, 350), QString());
    QVERIFY(validate(st, 353).contains("steps of 5"));
    QVERIFY(validate(st, 505).contains("90 to 500"));
    const auto d = *cat.resolve("DME", "D12", Direction::Write);
    QVERIFY(validate(d, 99999).isEmpty());
    QVERIFY(validate(d, 10).contains("disabled"));
    const auto ps = *cat.resolve("DDR", "PS1", Direction::Write);
    QVERIFY(validate(ps, 1).isEmpty());
    QVERIFY(!validate(ps, 10).isEmpty());
    const auto read = *cat.resolve("DME", "TT1", Direction::Read);
    QVERIFY(validate(read, 1).contains("cannot be written"));
    const auto hd = *cat.resolve("DME", "HD1", Direction::Write);
    QCOMPARE(encodeWrite(hd, 160).value(), QByteArray("01.60"));
    QCOMPARE(encodeWrite(hd, 99999).value(), QByteArray("99999"));
    QCOMPARE(parseUserValue(hd, "1.6").value(), 160);
    QCOMPARE(parseUserValue(hd, "disabled").value(), 99999);
    QCOMPARE(parseUserValue(*cat.resolve("DME", "A12", Direction::Write), "-50").value(), -50);
    QVERIFY(!parseUserValue(st, "hot"));
}

void TestCatalog::malformedCatalogDataIsRefusedWithAReason() {
    const auto broken = Catalog::load("{", "{}");
    QVERIFY(!broken);
    QVERIFY(broken.error().contains("families.json"));
    const QByteArray fams = R"({"families":{"X":{"kind":"station"}},"units":{"none":{}}})";
    const auto tooLong =
        Catalog::load(fams, R"({"commands":[{"code":"TOOLONG","access":"r","kind":"number"}]})");
    QVERIFY(!tooLong);
    QVERIFY(tooLong.error().contains("3 characters"));
    QVERIFY(!Catalog::load(
        fams, R"({"commands":[{"code":"AAA","access":"r","kind":"number","families":["Y"]}]})"));
}

void TestCatalog::aRoleFindsOneValueAndOneActionPerPort() {
    const Catalog &cat = Catalog::builtin();
    for (const QString &fam : cat.familyNames()) {
        QSet<QString> seen;
        for (Direction d : {Direction::Read, Direction::Write}) {
            for (const ResolvedCommand &r : cat.expand(fam, d)) {
                if (r.spec->role == Role::None)
                    continue;
                // A value read and written (STx) is one value; its two directions share an entry.
                const QString key = QStringLiteral("%1 %2 port %3")
                                        .arg(r.spec->isAction() ? QStringLiteral("action")
                                                                : QStringLiteral("value"),
                                             roleName(r.spec->role))
                                        .arg(r.port);
                const QString entry = key + QLatin1Char(' ') + QString::fromLatin1(r.code);
                if (seen.contains(entry))
                    continue;
                QVERIFY2(!seen.contains(key), qPrintable(fam + QLatin1Char(' ') + entry));
                QVERIFY2(r.tool < 0, qPrintable(fam + QStringLiteral(" per-tool role ") + entry));
                seen.insert(key);
                seen.insert(entry);
            }
        }
    }
}

void TestCatalog::rolesNameTheCommandsFrontEndsLookFor_data() {
    QTest::addColumn<QString>("family");
    QTest::addColumn<Role>("role");
    QTest::addColumn<int>("port");
    QTest::addColumn<bool>("action");
    QTest::addColumn<QByteArray>("code");
    const struct {
        const char *family;
        Role role;
        int port;
        bool action;
        const char *code;
    } rows[] = {
        {"DME", Role::TipTemperature, 3, false, "TT3"},
        {"DME", Role::Setpoint, 2, false, "ST2"},
        {"DDR", Role::Power, 2, false, "PP2"},
        {"DME", Role::Status, 1, false, "PS1"},
        {"DME", Role::ConnectedTool, 4, false, "CT4"},
        {"DME", Role::TransistorTemperature, 1, false, "QT1"},
        {"DME", Role::TransformerTemperature, 0, false, "TT0"},
        {"DME", Role::Error, 0, false, "SER"},
        {"DME", Role::Error, 2, false, "PE2"},
        {"SFR", Role::Error, 0, false, "ECV"},
        {"SFR", Role::ResetError, 0, true, "ECV"},
        {"DME", Role::Alarm, 1, false, "TA1"},
        {"HDR", Role::HighAlarm, 1, false, "HA1"},
        {"UCR", Role::Fuse, 0, false, "FST"},
        {"SFR", Role::FedLength, 0, false, "FDL"},
        {"SFR", Role::FeedSpeed, 0, false, "SPD"},
        {"SFR", Role::Feeding, 0, false, "FDS"},
        {"ALE", Role::Feeding, 0, false, "FEE"},
        {"ALE", Role::DispensedLength, 1, false, "DL1"},
        {"SFR", Role::Start, 0, true, "SFD"},
        {"ALE", Role::Start, 0, true, "STR"},
        {"DME", Role::SaveToMemory, 0, true, "NVS"},
        {"DDR", Role::ModelName, 0, false, "SMN"},
    };
    for (const auto &r : rows)
        QTest::addRow("%s %s port %d", r.family, qPrintable(roleName(r.role)), r.port)
            << r.family << r.role << r.port << r.action << QByteArray(r.code);
}

void TestCatalog::rolesNameTheCommandsFrontEndsLookFor() {
    QFETCH(QString, family);
    QFETCH(Role, role);
    QFETCH(int, port);
    QFETCH(bool, action);
    QFETCH(QByteArray, code);
    QList<QByteArray> found;
    for (Direction d : {Direction::Read, Direction::Write})
        for (const ResolvedCommand &r : Catalog::builtin().expand(family, d))
            if (r.spec->role == role && r.port == port && r.spec->isAction() == action &&
                !found.contains(r.code))
                found.append(r.code);
    QCOMPARE(found, QList<QByteArray>{code});
}

void TestCatalog::aRoleNamesItsFirstCommandBeforeAFamilyIsKnown() {
    const Catalog &cat = Catalog::builtin();
    QCOMPARE(cat.command(Role::ModelName)->pattern, QStringLiteral("SMN"));
    QCOMPARE(cat.command(Role::Restart)->pattern, QStringLiteral("RST"));
    QVERIFY(!cat.command(Role::Restart, "DDR")); // the robot stations cannot be restarted
    QCOMPARE(cat.command(Role::Error, "SFR")->pattern, QStringLiteral("ECV"));
    QVERIFY(!cat.command(Role::None));
    QVERIFY(!cat.command(Role::ModelName, "NOPE"));
}

void TestCatalog::partialCountersPairWithATotalAndAResetButton() {
    const Catalog &cat = Catalog::builtin();
    int partials = 0;
    for (const CommandSpec &s : cat.commands()) {
        if (!s.partial || s.isAction())
            continue;
        ++partials;
        QVERIFY2(s.group == Group::Counter && !s.quantity.isEmpty(), qPrintable(s.pattern));
        bool total = false, reset = false;
        for (const CommandSpec &o : cat.commands()) {
            total = total || (o.quantity == s.quantity && !o.partial && o.families == s.families);
            reset = reset || (o.pattern == s.pattern && o.isAction() && o.partial &&
                              !o.label.isEmpty() && o.dangerous);
        }
        QVERIFY2(total && reset, qPrintable(s.pattern));
    }
    QCOMPARE(partials, 3); // the SFR's plugged hours, feeding hours and fed length
}

void TestCatalog::unknownRolesAndGroupsAreRefusedWithAReason() {
    const QByteArray fams = R"({"families":{"X":{"kind":"station"}},"units":{"none":{}}})";
    const auto known = Catalog::load(
        fams, R"({"commands":[{"code":"AAA","access":"r","kind":"number","families":["X"],)"
              R"("group":"counter","role":"power"}]})");
    QVERIFY2(known, qPrintable(known.error()));
    const auto role = Catalog::load(
        fams, R"({"commands":[{"code":"AAA","access":"r","kind":"number","families":["X"],)"
              R"("group":"counter","role":"tipTemp"}]})");
    QVERIFY(!role);
    QVERIFY2(role.error().contains("unknown role 'tipTemp'"), qPrintable(role.error()));
    const auto group = Catalog::load(
        fams, R"({"commands":[{"code":"AAA","access":"r","kind":"number","families":["X"],)"
              R"("group":"counters"}]})");
    QVERIFY(!group);
    QVERIFY2(group.error().contains("unknown group 'counters'"), qPrintable(group.error()));
}

void TestCatalog::rolesAndGroupsReadBackTheirNames() {
    for (int i = int(Role::TipTemperature); i <= int(Role::ResetError); ++i)
        QCOMPARE(roleFromName(roleName(Role(i))), std::optional<Role>(Role(i)));
    for (int i = int(Group::Live); i <= int(Group::Actions); ++i)
        QCOMPARE(groupFromName(groupName(Group(i))), std::optional<Group>(Group(i)));
    QVERIFY(roleName(Role::None).isEmpty());
    QVERIFY(!roleFromName(QString()));
}

void TestCatalog::aRoleOnAPortResolvesToItsWireCode_data() {
    QTest::addColumn<QString>("family");
    QTest::addColumn<int>("role");
    QTest::addColumn<int>("port");
    QTest::addColumn<QByteArray>("code"); // empty: none
    QTest::newRow("tip temperature, port 2")
        << "DME" << int(Role::TipTemperature) << 2 << QByteArray("TT2");
    QTest::newRow("power, port 4") << "DME" << int(Role::Power) << 4 << QByteArray("PP4");
    QTest::newRow("the device's own software version")
        << "DME" << int(Role::SoftwareVersion) << 0 << QByteArray("SVR");
    QTest::newRow("a port command without a port")
        << "DME" << int(Role::Setpoint) << 0 << QByteArray();
    QTest::newRow("a device command on a port")
        << "DME" << int(Role::SoftwareVersion) << 1 << QByteArray();
    QTest::newRow("a port the family lacks") << "DME" << int(Role::Setpoint) << 9 << QByteArray();
    QTest::newRow("a port a two-port family lacks")
        << "DDE" << int(Role::Power) << 4 << QByteArray();
    QTest::newRow("a role the family lacks")
        << "SFR" << int(Role::TipTemperature) << 1 << QByteArray();
}

void TestCatalog::aRoleOnAPortResolvesToItsWireCode() {
    QFETCH(QString, family);
    QFETCH(int, role);
    QFETCH(int, port);
    QFETCH(QByteArray, code);
    const auto resolved = Catalog::builtin().resolve(family, Role(role), port, Direction::Read);
    QCOMPARE(resolved ? resolved->code : QByteArray(), code);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestCatalog)

} // namespace tst_catalog
#include "tst_catalog.moc"
