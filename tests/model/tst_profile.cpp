// Profiles round-trip, refuse bad files without writing, and apply while polling continues.
#include "simfixture.h"

#include "model/pollscheduler.h"
#include "model/profileapplier.h"

#include <QTemporaryDir>

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

} // namespace

class TestProfile : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void profileRoundTripsThroughAChangedDevice();
    void malformedProfilesAreRefusedWithAReason_data();
    void malformedProfilesAreRefusedWithAReason();
    void unreadableOrHugeFilesAreRefused();
    void anotherFamilysProfileIsRefusedUnlessForced();
    void dryRunListsTheFramesAndWritesNothing();
    void limitsAreWrittenInAnOrderTheDeviceAccepts();
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
    QString error;
    QVERIFY2(saved.save(path, &error), qPrintable(error));
    const auto loaded = Profile::load(path, &error);
    QVERIFY2(loaded, qPrintable(error));
    QCOMPARE(loaded->values.size(), saved.values.size());
    QCOMPARE(loaded->family, QStringLiteral("DME"));

    sim::SimStation *dev = f.simLine->station();
    dev->setSetting("ST1", 300);
    dev->setSetting("A12", 10);
    dev->setSetting("H31", 99999);
    dev->setSetting("HD4", 160);
    const ApplyReport diff = run(*st, *loaded, ProfileApplier::Mode::Diff);
    QCOMPARE(diff.differences.size(), 4);
    QVERIFY(diff.text().contains(QStringLiteral("ST1 Selected temperature: 300 °C → 350 °C")));
    const ApplyReport applied = run(*st, *loaded, ProfileApplier::Mode::Apply);
    QVERIFY2(applied.ok(), qPrintable(applied.text()));
    QCOMPARE(applied.written.size(), 4);
    QCOMPARE(dev->setting("H31").value(), 10);
    QCOMPARE(run(*st, *loaded, ProfileApplier::Mode::Diff).differences.size(), 0);
}

void TestProfile::malformedProfilesAreRefusedWithAReason_data() {
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("expected");
    QTest::newRow("not json") << QByteArray("{\"format\": ") << "not a valid JSON";
    QTest::newRow("empty") << QByteArray("") << "not a valid JSON";
    QTest::newRow("wrong format") << QByteArray("{\"format\":\"x\"}") << "not a TipScope profile";
    QTest::newRow("array") << QByteArray("[1,2]") << "not a TipScope profile";
    QTest::newRow("newer schema") << QByteArray("{\"format\":\"tipscope-profile\",\"schema\":2}")
                                  << "schema 2";
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
    QString error;
    QVERIFY(!Profile::fromJson(json, &error));
    QVERIFY2(error.contains(expected), qPrintable(error));
}

void TestProfile::unreadableOrHugeFilesAreRefused() {
    QTemporaryDir dir;
    QString error;
    QVERIFY(!Profile::load(dir.filePath(QStringLiteral("missing.json")), &error));
    QVERIFY(error.contains(QStringLiteral("cannot read")));
    QFile huge(dir.filePath(QStringLiteral("huge.json")));
    QVERIFY(huge.open(QIODevice::WriteOnly));
    huge.write(QByteArray(kMaxProfileBytes + 10, ' '));
    huge.close();
    QVERIFY(!Profile::load(huge.fileName(), &error));
    QVERIFY(error.contains(QStringLiteral("at most")));
    QFile binary(dir.filePath(QStringLiteral("bin.json")));
    QVERIFY(binary.open(QIODevice::WriteOnly));
    binary.write(QByteArray("\xff\xfe\x00\x01garbage", 12));
    binary.close();
    QVERIFY(!Profile::load(binary.fileName(), &error));
}

void TestProfile::anotherFamilysProfileIsRefusedUnlessForced() {
    SimFixture f(singleDevice(QStringLiteral("DDR")));
    auto st = f.station();
    QString error;
    const auto p = Profile::fromJson(
        profileJson("DME", "\"ST1\":\"00300\",\"ST4\":\"00300\",\"HD1\":\"01.00\""), &error);
    QVERIFY2(p, qPrintable(error));
    const ApplyReport refused = run(*st, *p, ProfileApplier::Mode::Apply);
    QVERIFY(refused.refused);
    QVERIFY(refused.reason.contains(QStringLiteral("DME")));
    f.settle();
    QCOMPARE(f.simLine->stats().writeRequests, 0);
    const ApplyReport forced = run(*st, *p, ProfileApplier::Mode::Apply, true);
    QVERIFY2(forced.ok(), qPrintable(forced.text()));
    QCOMPARE(forced.skipped, QStringList({"HD1", "ST4"})); // JSON objects come back sorted
    QCOMPARE(f.simLine->station()->setting("ST1").value(), 300);
}

void TestProfile::dryRunListsTheFramesAndWritesNothing() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    QString error;
    const auto p =
        Profile::fromJson(profileJson("DME", "\"ST1\":\"00300\",\"MAT\":\"00500\""), &error);
    const ApplyReport dry = run(*st, *p, ProfileApplier::Mode::DryRun);
    QCOMPARE(dry.frames.size(), 1);
    QVERIFY2(dry.frames.first().contains(QStringLiteral("00→01 W ST1 00300")),
             qPrintable(dry.frames.first()));
    QVERIFY(dry.frames.first().startsWith(QStringLiteral("02 30 30 30 31 57")));
    f.settle();
    QCOMPARE(f.simLine->stats().writeRequests, 0);
}

void TestProfile::limitsAreWrittenInAnOrderTheDeviceAccepts() {
    SimFixture f(singleDevice(QStringLiteral("DME")));
    auto st = f.station();
    f.simLine->station()->setSetting("MAT", 200);
    f.simLine->station()->setSetting("MIT", 150);
    f.simLine->station()->setSetting("ST1", 200);
    QString error;
    const auto p = Profile::fromJson(
        profileJson("DME", "\"ST1\":\"00400\",\"MIT\":\"00300\",\"MAT\":\"00450\""), &error);
    const ApplyReport r = run(*st, *p, ProfileApplier::Mode::Apply);
    QVERIFY2(r.ok(), qPrintable(r.text()));
    QCOMPARE(f.simLine->station()->setting("ST1").value(), 400);
    QCOMPARE(f.simLine->station()->setting("MIT").value(), 300);
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
            updates[port->number()].insert(port->param("TT")->lastUpdate().toMSecsSinceEpoch());
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

QTEST_GUILESS_MAIN(TestProfile)
#include "tst_profile.moc"
