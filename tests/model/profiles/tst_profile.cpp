// Profiles round-trip, refuse bad files without writing, and apply while polling continues.
#include "model/simfixture.h"
#include "testmain.h"

#include "model/live/pollscheduler.h"
#include "model/profiles/profileapplier.h"

#include <QCryptographicHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

namespace tst_profile {

using namespace tipscope;
using namespace tipscope::model;
using namespace tipscope::testing;

namespace {

ApplyReport run(DeviceModel &d, const Profile &p, ProfileApplier::Mode mode, bool force = false) {
    ProfileApplier applier(d, p, mode, force);
    QSignalSpy done(&applier, &ProfileApplier::finished);
    applier.start();
    if (!done.wait(60000))
        qFatal("profile run did not finish");
    return applier.report();
}

QByteArray profileJson(const QByteArray &family, const QByteArray &values) {
    return "{\"format\":\"tipscope-profile\",\"schema\":1,\"family\":\"" + family +
           "\",\"values\":{" + values + "}}";
}

using Settings = QMap<QByteArray, qint64>;

// MIT <= STx <= MAT on every port of a DME, in `s`; empty when it holds, else what breaks.
QString dmeLimitsBroken(const Settings &s) {
    if (s.value("MIT") > s.value("MAT"))
        return QStringLiteral("MIT %1 > MAT %2").arg(s.value("MIT")).arg(s.value("MAT"));
    for (int port = 1; port <= 4; ++port) {
        const qint64 st = s.value("ST" + QByteArray::number(port));
        if (st < s.value("MIT") || st > s.value("MAT"))
            return QStringLiteral("ST%1 %2 outside %3..%4")
                .arg(port)
                .arg(st)
                .arg(s.value("MIT"))
                .arg(s.value("MAT"));
    }
    return {};
}

void setDevice(sim::SimDevice &dev, const Settings &s) {
    for (auto it = s.begin(); it != s.end(); ++it)
        dev.setSetting(it.key(), it.value());
}

Settings limitSettings(const sim::SimDevice &dev) {
    Settings s;
    for (const QByteArray code : {"MIT", "MAT", "ST1", "ST2", "ST3", "ST4"})
        s.insert(code, dev.setting(code).value_or(-1));
    return s;
}

} // namespace

class TestProfile : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void profileRoundTripsThroughAChangedDevice();
    void aSavedProfileNamesEachValueBesideItsRawDataField_data();
    void aSavedProfileNamesEachValueBesideItsRawDataField();
    void theFirstSchemaAndBareDataFieldsStillLoad();
    void malformedProfilesAreRefusedWithAReason_data();
    void malformedProfilesAreRefusedWithAReason();
    void unreadableOrHugeFilesAreRefused();
    void anotherFamilysProfileIsRefusedUnlessForced();
    void dryRunListsTheFramesAndWritesNothing();
    void limitsAreWrittenInAnOrderTheDeviceAccepts();
    void aProfileThatBreaksALimitIsRefusedWhole_data();
    void aProfileThatBreaksALimitIsRefusedWhole();
    void everyStateBetweenTwoWritesKeepsTheLimits_data();
    void everyStateBetweenTwoWritesKeepsTheLimits();
    void aLimitThatCannotBeReadRefusesTheProfile_data();
    void aLimitThatCannotBeReadRefusesTheProfile();
    void aForcedProfileWithNothingInCommonIsRefused();
    void liveValuesKeepUpdatingWhileAProfileIsApplied();
};

void TestProfile::profileRoundTripsThroughAChangedDevice() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    st->refreshAll();
    f.settle();
    QStringList missing;
    const Profile saved = Profile::capture(*st, &missing);
    QVERIFY(missing.isEmpty());
    QVERIFY(saved.values.size() > 100);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("dme.json"));
    const auto written = saved.save(path);
    QVERIFY2(written.ok(), qPrintable(written.error()));
    const auto loaded = Profile::load(path);
    QVERIFY2(loaded.ok(), qPrintable(loaded.error()));
    QCOMPARE(loaded->values.size(), saved.values.size());
    QCOMPARE(loaded->family, QStringLiteral("DME"));

    sim::SimStation *dev = f.simLine->station();
    dev->setSetting("ST1", 300);
    dev->setSetting("A12", 10);
    dev->setSetting("H31", 99999);
    dev->setSetting("HD4", 160);
    const ApplyReport diff = run(*st, *loaded, ProfileApplier::Mode::Diff);
    QCOMPARE(diff.differences.size(), 4);
    QVERIFY2(
        diff.text().contains(QStringLiteral("ST1 Selected temperature, port 1: 300 °C → 350 °C")),
        qPrintable(diff.text()));
    EventLog log;
    st->setEventLog(&log);
    const ApplyReport applied = run(*st, *loaded, ProfileApplier::Mode::Apply);
    QVERIFY2(applied.ok(), qPrintable(applied.text()));
    QCOMPARE(applied.written.size(), 4);
    QCOMPARE(dev->setting("H31").value(), 10);
    QCOMPARE(run(*st, *loaded, ProfileApplier::Mode::Diff).differences.size(), 0);

    // The apply is one event for the journal: the profile's hash and every change.
    const QList<Event> events = log.events();
    const auto apply = std::find_if(events.cbegin(), events.cend(), [](const Event &e) {
        return e.kind == Event::Kind::ProfileApply;
    });
    QVERIFY(apply != events.cend());
    QCOMPARE(std::count_if(events.cbegin(), events.cend(),
                           [](const Event &e) { return e.kind == Event::Kind::ProfileApply; }),
             1); // the diffs are not applies
    const QString hash = QString::fromLatin1(
        QCryptographicHash::hash(loaded->toJson(), QCryptographicHash::Sha256).toHex());
    QCOMPARE(apply->details.value(QStringLiteral("profileSha256")).toString(), hash);
    const QJsonArray changes = apply->details.value(QStringLiteral("changes")).toArray();
    QCOMPARE(changes.size(), 4);
    QCOMPARE(changes.first().toObject().value(QStringLiteral("ok")).toBool(), true);
    QVERIFY2(apply->text.startsWith(
                 QStringLiteral("profile %1 applied: 4 changed, 0 failed").arg(hash.left(12))),
             qPrintable(apply->text));
    QCOMPARE(apply->device, st->identity());
}

void TestProfile::aSavedProfileNamesEachValueBesideItsRawDataField_data() {
    QTest::addColumn<QString>("code");
    QTest::addColumn<QString>("raw");
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("value");
    QTest::newRow("a port's setting") << "ST1"
                                      << "00350"
                                      << "Selected temperature, port 1"
                                      << "350 °C";
    QTest::newRow("a tool's setting") << "H12"
                                      << "00010"
                                      << "Hibernation delay, T245/T470 (TR245/TR470), port 1"
                                      << "10 min";
    QTest::newRow("a special value") << "HD1"
                                     << "99999"
                                     << "High alarm delay, port 1"
                                     << "disabled";
    QTest::newRow("the station's") << "MAT"
                                   << "00480"
                                   << "Maximum temperature"
                                   << "480 °C";
}

void TestProfile::aSavedProfileNamesEachValueBesideItsRawDataField() {
    QFETCH(QString, code);
    QFETCH(QString, raw);
    QFETCH(QString, name);
    QFETCH(QString, value);
    SimFixture f(singleDevice(QStringLiteral("DME")));
    f.simLine->station()->setSetting("MAT", 480);
    f.simLine->station()->setSetting("H12", 10);
    auto st = f.station();
    st->setTemperatureUnit(TemperatureUnit::Fahrenheit); // the file stays in °C
    st->refreshAll();
    f.settle();
    const Profile saved = Profile::capture(*st);
    const QJsonObject values =
        QJsonDocument::fromJson(saved.toJson()).object().value(QStringLiteral("values")).toObject();
    QCOMPARE(QJsonDocument::fromJson(saved.toJson()).object().value(QStringLiteral("schema")),
             QJsonValue(2));
    const QJsonObject entry = values.value(code).toObject();
    QCOMPARE(entry.value(QStringLiteral("raw")).toString(), raw);
    QCOMPARE(entry.value(QStringLiteral("name")).toString(), name);
    QCOMPARE(entry.value(QStringLiteral("value")).toString(), value);
    // Read back, the raw data field is what counts, the notes come along.
    const auto loaded = Profile::fromJson(saved.toJson());
    QVERIFY2(loaded.ok(), qPrintable(loaded.error()));
    QVERIFY(loaded->values.contains(qMakePair(code.toLatin1(), raw.toLatin1())));
    QCOMPARE(loaded->notes.value(code.toLatin1()).name, name);
}

void TestProfile::theFirstSchemaAndBareDataFieldsStillLoad() {
    const auto first = Profile::fromJson(profileJson("DME", R"("ST1":"00300")"));
    QVERIFY2(first.ok(), qPrintable(first.error()));
    QCOMPARE(first->values, (QList<QPair<QByteArray, QByteArray>>{{"ST1", "00300"}}));
    const auto mixed = Profile::fromJson(
        R"({"format":"tipscope-profile","schema":2,"family":"DME","values":{"ST1":"00300",
            "ST2":{"raw":"00320","name":"a note that is not applied","value":"999 °C"}}})");
    QVERIFY2(mixed.ok(), qPrintable(mixed.error()));
    QCOMPARE(mixed->values,
             (QList<QPair<QByteArray, QByteArray>>{{"ST1", "00300"}, {"ST2", "00320"}}));
}

void TestProfile::malformedProfilesAreRefusedWithAReason_data() {
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("expected");
    QTest::newRow("not json") << QByteArray("{\"format\": ") << "not a valid JSON";
    QTest::newRow("empty") << QByteArray("") << "not a valid JSON";
    QTest::newRow("wrong format") << QByteArray("{\"format\":\"x\"}") << "not a TipScope profile";
    QTest::newRow("array") << QByteArray("[1,2]") << "not a TipScope profile";
    QTest::newRow("newer schema") << QByteArray("{\"format\":\"tipscope-profile\",\"schema\":3}")
                                  << "schema 3";
    QTest::newRow("unknown family")
        << profileJson("XYZ", "\"ST1\":\"00350\"") << "unknown device family";
    QTest::newRow("no values") << profileJson("DME", "") << "no values";
    QTest::newRow("off step") << profileJson("DME", "\"ST1\":\"00353\"") << "steps of 5";
    QTest::newRow("out of range") << profileJson("DME", "\"A12\":\"00051\"") << "A12";
    QTest::newRow("no such port") << profileJson("DME", "\"ST9\":\"00350\"") << "not a setting";
    QTest::newRow("read-only") << profileJson("DME", "\"TT1\":\"00350\"") << "not a setting";
    QTest::newRow("status") << profileJson("DME", "\"PS1\":\"00000\"") << "not a setting";
    QTest::newRow("number not string") << profileJson("DME", "\"ST1\":350") << "in quotes";
    QTest::newRow("garbage data") << profileJson("DME", "\"ST1\":\"3x0\"")
                                  << "not a valid data field";
    QTest::newRow("non-ascii") << profileJson("DME", "\"ST1\":\"\xc3\xa9\xc3\xa9\"")
                               << "not a valid data field";
}

void TestProfile::malformedProfilesAreRefusedWithAReason() {
    QFETCH(QByteArray, json);
    QFETCH(QString, expected);
    const auto p = Profile::fromJson(json);
    QVERIFY(!p.ok());
    QVERIFY2(p.error().contains(expected), qPrintable(p.error()));
}

void TestProfile::unreadableOrHugeFilesAreRefused() {
    QTemporaryDir dir;
    const auto missing = Profile::load(dir.filePath(QStringLiteral("missing.json")));
    QVERIFY(!missing.ok());
    QVERIFY(missing.error().contains(QStringLiteral("cannot read")));
    QFile huge(dir.filePath(QStringLiteral("huge.json")));
    QVERIFY(huge.open(QIODevice::WriteOnly));
    huge.write(QByteArray(kMaxProfileBytes + 10, ' '));
    huge.close();
    const auto tooBig = Profile::load(huge.fileName());
    QVERIFY(!tooBig.ok());
    QVERIFY(tooBig.error().contains(QStringLiteral("at most")));
    QFile binary(dir.filePath(QStringLiteral("bin.json")));
    QVERIFY(binary.open(QIODevice::WriteOnly));
    binary.write(QByteArray("\xff\xfe\x00\x01garbage", 12));
    binary.close();
    QVERIFY(!Profile::load(binary.fileName()).ok());
}

void TestProfile::anotherFamilysProfileIsRefusedUnlessForced() {
    SimFixture f(singleDevice(QStringLiteral("DDR")));
    auto st = f.station();
    const auto p = Profile::fromJson(
        profileJson("DME", "\"ST1\":\"00300\",\"ST4\":\"00300\",\"HD1\":\"01.00\""));
    QVERIFY2(p.ok(), qPrintable(p.error()));
    const ApplyReport refused = run(*st, *p, ProfileApplier::Mode::Apply);
    QVERIFY(refused.refused);
    QVERIFY(refused.reason.contains(QStringLiteral("DME")));
    // Refused, yet compared: what it would change, and what it skips, by name and why.
    QCOMPARE(refused.differences.size(), 1);
    QCOMPARE(refused.differences.first().name, QStringLiteral("Selected temperature, port 1"));
    QCOMPARE(refused.skippedCodes(), QStringList({"HD1", "ST4"}));
    QVERIFY2(refused.skipped.first().name.contains(QStringLiteral("port 1")) &&
                 refused.skipped.last().reason.contains(QStringLiteral("DDR")),
             qPrintable(refused.text()));
    QVERIFY2(refused.text().contains(QStringLiteral("2 skipped")), qPrintable(refused.text()));
    f.settle();
    QCOMPARE(f.simLine->stats().writeRequests, 0);
    const ApplyReport forced = run(*st, *p, ProfileApplier::Mode::Apply, true);
    QVERIFY2(forced.ok(), qPrintable(forced.text()));
    QCOMPARE(forced.skippedCodes(), QStringList({"HD1", "ST4"})); // JSON objects come back sorted
    QCOMPARE(f.simLine->station()->setting("ST1").value(), 300);
}

void TestProfile::dryRunListsTheFramesAndWritesNothing() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    const auto p = Profile::fromJson(profileJson("DME", "\"ST1\":\"00300\",\"MAT\":\"00500\""));
    const ApplyReport dry = run(*st, *p, ProfileApplier::Mode::DryRun);
    QCOMPARE(dry.frames.size(), 1);
    QVERIFY2(dry.frames.first().contains(QStringLiteral("00→01 W ST1 00300")),
             qPrintable(dry.frames.first()));
    QVERIFY(dry.frames.first().startsWith(QStringLiteral("02 30 30 30 31 57")));
    // The count says what the run would do, not what it wrote (nothing).
    QVERIFY2(dry.text().endsWith(QStringLiteral("\n1 would change, 1 already right")),
             qPrintable(dry.text()));
    f.settle();
    QCOMPARE(f.simLine->stats().writeRequests, 0);
}

void TestProfile::limitsAreWrittenInAnOrderTheDeviceAccepts() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    f.simLine->station()->setSetting("MAT", 200);
    f.simLine->station()->setSetting("MIT", 150);
    f.simLine->station()->setSetting("ST1", 200);
    const auto p = Profile::fromJson(
        profileJson("DME", "\"ST1\":\"00400\",\"MIT\":\"00300\",\"MAT\":\"00450\""));
    const ApplyReport r = run(*st, *p, ProfileApplier::Mode::Apply);
    QVERIFY2(r.ok(), qPrintable(r.text()));
    QCOMPARE(f.simLine->station()->setting("ST1").value(), 400);
    QCOMPARE(f.simLine->station()->setting("MIT").value(), 300);
}

void TestProfile::aProfileThatBreaksALimitIsRefusedWhole_data() {
    QTest::addColumn<Settings>("device");
    QTest::addColumn<QByteArray>("values");
    QTest::addColumn<QStringList>("named"); // what the refusal must say
    const Settings factory{{"MIT", 90},  {"MAT", 500}, {"ST1", 350},
                           {"ST2", 350}, {"ST3", 350}, {"ST4", 350}};
    Settings st1At450 = factory;
    st1At450["ST1"] = 450;
    QTest::newRow("MAT below ST1, both in the profile")
        << factory << QByteArray(R"("MAT":"00400","A11":"00005","ST1":"00450")")
        << QStringList{"ST1 450 °C (in the profile) is above MAT 400 °C (in the profile)"};
    QTest::newRow("ST1 already 450 on the device, the profile sets it too")
        << st1At450 << QByteArray(R"("MAT":"00400","ST1":"00450")")
        << QStringList{"ST1 450 °C (in the profile) is above MAT 400 °C (in the profile)"};
    QTest::newRow("ST1 450 on the device, the profile leaves it alone")
        << st1At450 << QByteArray(R"("MAT":"00400","A11":"00005")")
        << QStringList{"ST1 450 °C (on the device now) is above MAT 400 °C (in the profile)"};
    QTest::newRow("MIT above MAT in the profile")
        << factory << QByteArray(R"("MIT":"00400","MAT":"00300")")
        << QStringList{"MIT 400 °C (in the profile) is above MAT 300 °C (in the profile)"};
    QTest::newRow("MIT above every port's selected temperature on the device")
        << factory << QByteArray(R"("MIT":"00400")")
        << QStringList{"MIT 400 °C (in the profile) is above ST1 350 °C (on the device now)",
                       "ST4 350 °C (on the device now)"};
    QTest::newRow("ST2 below the device's MIT")
        << Settings{{"MIT", 200}} << QByteArray(R"("ST2":"00150")")
        << QStringList{"MIT 200 °C (on the device now) is above ST2 150 °C (in the profile)"};
}

void TestProfile::aProfileThatBreaksALimitIsRefusedWhole() {
    QFETCH(Settings, device);
    QFETCH(QByteArray, values);
    QFETCH(QStringList, named);
    SimFixture f(singleDevice(QStringLiteral("DME")));
    sim::SimDevice &dev = *f.simLine->station();
    setDevice(dev, device);
    const Settings before = limitSettings(dev);
    auto st = f.station();
    const auto p = Profile::fromJson(profileJson("DME", values));
    QVERIFY2(p.ok(), qPrintable(p.error()));
    for (const auto mode :
         {ProfileApplier::Mode::Diff, ProfileApplier::Mode::DryRun, ProfileApplier::Mode::Apply}) {
        const ApplyReport r = run(*st, *p, mode);
        QVERIFY(!r.ok());
        const QString said = r.conflicts.join(QLatin1Char('\n'));
        for (const QString &n : named)
            QVERIFY2(said.contains(n), qPrintable(said));
        QCOMPARE(r.refused, mode != ProfileApplier::Mode::Diff);
        QVERIFY(r.frames.isEmpty() && r.written.isEmpty());
        if (r.refused)
            QVERIFY2(r.text().contains(QStringLiteral("nothing was written")) &&
                         r.text().contains(named.first()),
                     qPrintable(r.text()));
    }
    f.settle();
    QCOMPARE(f.simLine->stats().writeRequests, 0);
    QCOMPARE(limitSettings(dev), before);
}

void TestProfile::everyStateBetweenTwoWritesKeepsTheLimits_data() {
    QTest::addColumn<Settings>("device");
    QTest::addColumn<QByteArray>("values");
    QTest::newRow("raise both limits above the selected temperatures")
        << Settings{{"MIT", 150}, {"MAT", 200}, {"ST1", 200},
                    {"ST2", 150}, {"ST3", 200}, {"ST4", 200}}
        << QByteArray(R"("ST1":"00400","ST2":"00300","MIT":"00300","MAT":"00450",)"
                      R"("ST3":"00300","ST4":"00450")");
    QTest::newRow("narrow both limits around new selected temperatures")
        << Settings{{"MIT", 100}, {"MAT", 500}, {"ST1", 480},
                    {"ST2", 120}, {"ST3", 300}, {"ST4", 300}}
        << QByteArray(R"("MAT":"00400","MIT":"00200","ST1":"00350","ST2":"00250")");
    QTest::newRow("move the window down past its old minimum")
        << Settings{{"MIT", 300}, {"MAT", 450}, {"ST1", 400},
                    {"ST2", 300}, {"ST3", 300}, {"ST4", 300}}
        << QByteArray(R"("MAT":"00250","MIT":"00100","ST1":"00200","ST2":"00150",)"
                      R"("ST3":"00250","ST4":"00100")");
}

void TestProfile::everyStateBetweenTwoWritesKeepsTheLimits() {
    QFETCH(Settings, device);
    QFETCH(QByteArray, values);
    SimFixture f(singleDevice(QStringLiteral("DME")));
    sim::SimDevice &dev = *f.simLine->station();
    setDevice(dev, device);
    auto st = f.station();
    const auto p = Profile::fromJson(profileJson("DME", values));
    QVERIFY2(p.ok(), qPrintable(p.error()));
    const ApplyReport dry = run(*st, *p, ProfileApplier::Mode::DryRun);
    QVERIFY2(dry.conflicts.isEmpty() && !dry.refused, qPrintable(dry.text()));
    const ApplyReport r = run(*st, *p, ProfileApplier::Mode::Apply);
    QVERIFY2(r.ok(), qPrintable(r.text()));
    // Replay what the device accepted, in its order, and look at every state in between.
    Settings s = device;
    QCOMPARE(dev.acceptedWrites().size(), p->values.size());
    for (int i = 0; i < dev.acceptedWrites().size(); ++i) {
        const QString w = dev.acceptedWrites().at(i);
        s[w.section(QLatin1Char('='), 0, 0).toLatin1()] =
            w.section(QLatin1Char('='), 1).toLongLong();
        const QString broken = dmeLimitsBroken(s);
        QVERIFY2(broken.isEmpty(), qPrintable(QStringLiteral("after %1: %2").arg(w, broken)));
        QVERIFY2(dry.frames.at(i).contains(QString(w).replace(QLatin1Char('='), QLatin1Char(' '))),
                 qPrintable(QStringLiteral("the dry run listed %1 where %2 was written")
                                .arg(dry.frames.at(i), w)));
    }
}

void TestProfile::aLimitThatCannotBeReadRefusesTheProfile_data() {
    QTest::addColumn<bool>("polledBefore");
    QTest::newRow("never read") << false;
    // A value from an earlier poll is not the device's state now: it must not count.
    QTest::newRow("read by an earlier poll") << true;
}

void TestProfile::aLimitThatCannotBeReadRefusesTheProfile() {
    QFETCH(bool, polledBefore);
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    if (polledBefore) {
        st->refreshAll();
        f.settle();
        QCOMPARE(st->parameter("MAT")->number(), 500);
    }
    const auto p = Profile::fromJson(profileJson("DME", R"("ST1":"00400")"));
    QVERIFY2(p.ok(), qPrintable(p.error()));
    sim::SimFaults faults;
    faults.nakCode = 4;
    f.simLine->setFaults(faults);
    const ApplyReport r = run(*st, *p, ProfileApplier::Mode::Apply);
    QVERIFY(r.refused);
    QVERIFY2(r.reason.contains(QStringLiteral("is not known (the device did not answer)")),
             qPrintable(r.reason));
    f.settle();
    QCOMPARE(f.simLine->stats().writeRequests, 0);
}

void TestProfile::aForcedProfileWithNothingInCommonIsRefused() {
    SimFixture f(singleDevice(QStringLiteral("DDR")));
    auto st = f.station();
    // The DDR has two ports and no alarm delays: nothing here exists on it.
    const auto p = Profile::fromJson(profileJson("DME", R"("ST4":"00300","HD1":"01.00")"));
    QVERIFY2(p.ok(), qPrintable(p.error()));
    const ApplyReport r = run(*st, *p, ProfileApplier::Mode::Apply, true);
    QVERIFY(r.refused);
    QVERIFY(!r.ok());
    QVERIFY2(r.text().contains(QStringLiteral("none of the profile's settings")) &&
                 r.text().contains(QStringLiteral("HD1 ST4")),
             qPrintable(r.text()));
    f.settle();
    QCOMPARE(f.simLine->stats().writeRequests, 0);
}

void TestProfile::liveValuesKeepUpdatingWhileAProfileIsApplied() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    f.simLine->setClockRunning(true);
    f.simLine->setBaud(19200); // a real wire's pace, so the apply takes as long as on a station
    auto st = f.station();
    st->refreshAll();
    f.settle();
    Profile p = Profile::capture(*st);
    for (auto &entry : p.values)
        if (entry.first.startsWith('A') || entry.first.startsWith('S'))
            entry.second = entry.first.startsWith('A') ? "00005" : "00200";
    PollScheduler scheduler;
    scheduler.addDevice(st.get());
    scheduler.setVisiblePorts(st.get(), {1, 2, 3, 4});
    scheduler.setInterval(PollClass::Live, 100);
    scheduler.start();
    QMap<int, QSet<qint64>> updates;
    QTimer sampler;
    connect(&sampler, &QTimer::timeout, this, [&] {
        for (PortModel *port : st->ports())
            updates[port->number()].insert(
                port->parameter(protocol::Role::TipTemperature)->lastUpdate().toMSecsSinceEpoch());
    });
    sampler.start(50);
    const ApplyReport r = run(*st, p, ProfileApplier::Mode::Apply);
    sampler.stop();
    QVERIFY2(r.ok(), qPrintable(r.text()));
    QVERIFY(r.written.size() > 60);
    for (int port = 1; port <= 4; ++port)
        QVERIFY2(updates.value(port).size() >= 3,
                 qPrintable(QStringLiteral("port %1 updated %2 times")
                                .arg(port)
                                .arg(updates.value(port).size())));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestProfile)

} // namespace tst_profile
#include "tst_profile.moc"
