// Discovery finds the simulated devices in probe order, identifies their family and software,
// honours the addressing mode it is given, and reports its progress; identify() names one device
// at any address, or says why it could not.
#include "link/discovery.h"
#include "link/line.h"
#include "link/simtransport.h"
#include "sim/simline.h"
#include "testmain.h"

#include <QSignalSpy>
#include <QTest>

Q_DECLARE_METATYPE(tipscope::link::DeviceInfo)

namespace tst_discovery {

using namespace tipscope::link;
using tipscope::sim::SimLine;
using tipscope::sim::SimStation;

namespace {

constexpr int kWaitMs = 20000; // a generous ceiling for "eventually", never asserted on

enum class Wiring { Demo, Ddr, DmeAt42, UnknownModelAt1 };

std::unique_ptr<SimLine> makeSimLine(Wiring wiring) {
    if (wiring == Wiring::Demo)
        return SimLine::demo(); // DME at 01, SFR at 10
    auto sim = std::make_unique<SimLine>();
    if (wiring == Wiring::Ddr) {
        sim->addDevice(std::make_unique<SimStation>(QStringLiteral("DDR"))); // no addresses
    } else if (wiring == Wiring::DmeAt42) {
        auto dme = std::make_unique<SimStation>(QStringLiteral("DME"), 42);
        dme->setSoftwareVersion(QStringLiteral("1234567"));
        sim->addDevice(std::move(dme));
    } else {
        auto odd = std::make_unique<SimStation>(QStringLiteral("DME"), 1);
        odd->setModelName(QStringLiteral("XQ-9"));
        sim->addDevice(std::move(odd));
    }
    return sim;
}

// An open line to a simulated wiring, ready for discovery.
struct Bench {
    explicit Bench(Wiring wiring)
        : sim(makeSimLine(wiring)) {
        LineSettings s;
        s.kind = LineSettings::Kind::Demo;
        s.queue.turnaroundMs = 20;
        // Low enough that the silence of absent addresses would look like a lost line, were
        // probes counted towards it.
        s.suspectAfterTimeouts = 2;
        line = std::make_unique<Line>(std::make_unique<SimTransport>(*sim), s);
    }

    std::unique_ptr<SimLine> sim;
    std::unique_ptr<Line> line;
};

QString addressesText(const QList<DeviceInfo> &devices) {
    QStringList out;
    for (const DeviceInfo &d : devices)
        out.append(d.addressText());
    return out.join(QLatin1Char(' '));
}

} // namespace

class TestDiscovery : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void demoLineIsTwoIdentifiedDevicesInProbeOrder();
    void ddrLineIsOneDeviceWithoutAddress();
    void aSearchFindsTheDevicesWhoseAnswersCameLate();
    void aSearchAsksBothWays_data();
    void aSearchAsksBothWays();
    void identifyNamesTheDeviceAtAnyAddress_data();
    void identifyNamesTheDeviceAtAnyAddress();
    void identifySaysWhyTheDeviceWasNotIdentified_data();
    void identifySaysWhyTheDeviceWasNotIdentified();
};

void TestDiscovery::demoLineIsTwoIdentifiedDevicesInProbeOrder() {
    Bench b(Wiring::Demo);
    b.line->open();
    QTRY_COMPARE_WITH_TIMEOUT(b.line->state(), Line::State::Open, kWaitMs);
    Discovery discovery(b.line->queue());
    QSignalSpy found(&discovery, &Discovery::deviceFound);
    QVERIFY(found.isValid());
    QSignalSpy finished(&discovery, &Discovery::finished);
    QVERIFY(finished.isValid());

    discovery.start();
    QVERIFY(discovery.isRunning());
    QVERIFY(finished.wait(kWaitMs));
    QVERIFY(!discovery.isRunning());

    const QList<DeviceInfo> devices = discovery.devices();
    QCOMPARE(devices.size(), 2);
    QCOMPARE(devices[0].address, std::optional<int>(1));
    QCOMPARE(devices[0].model, QStringLiteral("DME-2C"));
    QCOMPARE(devices[0].family, QStringLiteral("DME"));
    QCOMPARE(devices[0].softwareVersion, QStringLiteral("9996780"));
    QCOMPARE(devices[1].address, std::optional<int>(10));
    QCOMPARE(devices[1].model, QStringLiteral("SFR-A"));
    QCOMPARE(devices[1].family, QStringLiteral("SFR"));
    QCOMPARE(devices[0].summary(), QStringLiteral("01 DME-2C DME 9996780"));

    QCOMPARE(found.count(), 2);
    QCOMPARE(found.at(0).at(0).value<DeviceInfo>().model, QStringLiteral("DME-2C"));
    QCOMPARE(found.at(1).at(0).value<DeviceInfo>().model, QStringLiteral("SFR-A"));
    QCOMPARE(finished.count(), 1);
}

// A loaded PC: every answer comes after the probe's two attempts gave up (the queue's
// turnaround here is 20 ms), so each arrives as a frame nobody asked for, during the next probe.
// It names a device at its address all the same; the search asks it again, patiently.
void TestDiscovery::aSearchFindsTheDevicesWhoseAnswersCameLate() {
    Bench b(Wiring::Demo);
    tipscope::sim::SimFaults faults;
    faults.latencyMs = 120;
    b.sim->setFaults(faults);
    b.line->open();
    QTRY_COMPARE_WITH_TIMEOUT(b.line->state(), Line::State::Open, kWaitMs);
    Discovery discovery(b.line->queue());
    QSignalSpy finished(&discovery, &Discovery::finished);
    QVERIFY(finished.isValid());

    discovery.start();
    QVERIFY(finished.wait(kWaitMs));
    QVERIFY2(b.line->queue().stats().stray > 0, "no answer came late: the test proves nothing");
    QCOMPARE(addressesText(discovery.devices()), QStringLiteral("01 10"));
    QCOMPARE(discovery.devices().at(0).summary(), QStringLiteral("01 DME-2C DME 9996780"));
    QCOMPARE(discovery.devices().at(1).model, QStringLiteral("SFR-A"));
    QCOMPARE(finished.count(), 1);
}

void TestDiscovery::ddrLineIsOneDeviceWithoutAddress() {
    Bench b(Wiring::Ddr);
    b.line->open();
    QTRY_COMPARE_WITH_TIMEOUT(b.line->state(), Line::State::Open, kWaitMs);
    Discovery discovery(b.line->queue());
    QSignalSpy finished(&discovery, &Discovery::finished);
    QVERIFY(finished.isValid());

    discovery.start();
    QVERIFY(finished.wait(kWaitMs));

    const QList<DeviceInfo> devices = discovery.devices();
    QCOMPARE(devices.size(), 1);
    QCOMPARE(devices[0].address, std::nullopt);
    QCOMPARE(devices[0].addressText(), QStringLiteral("--"));
    QCOMPARE(devices[0].model, QStringLiteral("DDR"));
    QCOMPARE(devices[0].family, QStringLiteral("DDR"));
}

// The factory addresses (station, feeder, extractor) and the device without addresses: four
// probes, whichever way the line's devices answer.
void TestDiscovery::aSearchAsksBothWays_data() {
    QTest::addColumn<int>("wiring");
    QTest::addColumn<QString>("expected"); // addresses in probe order
    QTest::addColumn<int>("probes");
    QTest::newRow("demo") << int(Wiring::Demo) << "01 10" << 4;
    QTest::newRow("ddr") << int(Wiring::Ddr) << "--" << 4;
}

void TestDiscovery::aSearchAsksBothWays() {
    QFETCH(int, wiring);
    QFETCH(QString, expected);
    QFETCH(int, probes);

    Bench b(static_cast<Wiring>(wiring));
    b.line->open();
    QTRY_COMPARE_WITH_TIMEOUT(b.line->state(), Line::State::Open, kWaitMs);
    Discovery discovery(b.line->queue());
    QSignalSpy progress(&discovery, &Discovery::progress);
    QVERIFY(progress.isValid());
    QSignalSpy finished(&discovery, &Discovery::finished);
    QVERIFY(finished.isValid());

    discovery.start();
    QVERIFY(finished.wait(kWaitMs));

    QCOMPARE(addressesText(discovery.devices()), expected);
    QCOMPARE(b.line->state(), Line::State::Open);
    QCOMPARE(b.line->reconnects(), 0);
    QCOMPARE(progress.count(), probes);
    for (int i = 0; i < progress.count(); ++i) {
        QCOMPARE(progress.at(i).at(0).toInt(), i + 1);
        QCOMPARE(progress.at(i).at(1).toInt(), probes);
    }
}

void TestDiscovery::identifyNamesTheDeviceAtAnyAddress_data() {
    QTest::addColumn<int>("wiring");
    QTest::addColumn<int>("address"); // -1: the device without addresses
    QTest::addColumn<QString>("summary");
    QTest::addColumn<int>("latencyMs"); // the device's own turnaround

    QTest::newRow("feeder at its factory address")
        << int(Wiring::Demo) << 10 << QStringLiteral("10 SFR-A SFR -") << 0; // no R-SVR
    QTest::newRow("station where no search looks")
        << int(Wiring::DmeAt42) << 42 << QStringLiteral("42 DME-2C DME 1234567") << 0;
    QTest::newRow("device without addresses")
        << int(Wiring::Ddr) << -1 << QStringLiteral("-- DDR DDR -") << 0;
    // A loaded PC, or a converter that wakes up with the line, can make the first answers late.
    // The queue's own turnaround here is 20 ms: its three attempts are all over before this
    // device answers, so only the named device's own patience finds it.
    QTest::newRow("station that answers late")
        << int(Wiring::DmeAt42) << 42 << QStringLiteral("42 DME-2C DME 1234567") << 300;
}

void TestDiscovery::identifyNamesTheDeviceAtAnyAddress() {
    QFETCH(int, wiring);
    QFETCH(int, address);
    QFETCH(QString, summary);
    QFETCH(int, latencyMs);

    Bench b(static_cast<Wiring>(wiring));
    tipscope::sim::SimFaults faults;
    faults.latencyMs = latencyMs;
    b.sim->setFaults(faults);
    b.line->open();
    QTRY_COMPARE_WITH_TIMEOUT(b.line->state(), Line::State::Open, kWaitMs);
    Discovery discovery(b.line->queue());
    QSignalSpy finished(&discovery, &Discovery::finished);
    QVERIFY(finished.isValid());

    discovery.identify(address < 0 ? std::nullopt : std::optional<int>(address));
    QVERIFY(discovery.isRunning());
    QVERIFY(finished.wait(kWaitMs));

    QVERIFY(discovery.identification().has_value());
    const Identification &found = *discovery.identification();
    QVERIFY2(found.ok(), qPrintable(found.ok() ? QString() : found.error().reason));
    QCOMPARE(found.value().summary(), summary);
    QCOMPARE(b.line->queue().stats().retries, 0);
    QCOMPARE(discovery.devices().size(), 1);
    QCOMPARE(discovery.devices().at(0).summary(), summary);
    QCOMPARE(finished.count(), 1);
}

void TestDiscovery::identifySaysWhyTheDeviceWasNotIdentified_data() {
    QTest::addColumn<int>("wiring");
    QTest::addColumn<int>("address");
    QTest::addColumn<int>("nakCode");
    QTest::addColumn<double>("corruptShare");
    QTest::addColumn<int>("seed"); // of the simulator's faults
    QTest::addColumn<int>("kind");
    QTest::addColumn<int>("replyError");
    QTest::addColumn<QString>("model");

    const int unanswered = int(IdentifyFailure::Kind::Unanswered);
    QTest::newRow("nobody at the address") << int(Wiring::Demo) << 42 << 0 << 0.0 << 1 << unanswered
                                           << int(ReplyError::Timeout) << QString();
    QTest::newRow("the device refuses") << int(Wiring::Demo) << 1 << 5 << 0.0 << 1 << unanswered
                                        << int(ReplyError::Nak) << QString();
    // Seed 4: the last attempt's answer arrives whole but garbled (a cut-short one is silence).
    QTest::newRow("every answer corrupted") << int(Wiring::Demo) << 1 << 0 << 1.0 << 4 << unanswered
                                            << int(ReplyError::Corrupted) << QString();
    QTest::newRow("a model of no known family") << int(Wiring::UnknownModelAt1) << 1 << 0 << 0.0
                                                << 1 << int(IdentifyFailure::Kind::UnknownModel)
                                                << int(ReplyError::None) << QStringLiteral("XQ-9");
}

void TestDiscovery::identifySaysWhyTheDeviceWasNotIdentified() {
    QFETCH(int, wiring);
    QFETCH(int, address);
    QFETCH(int, nakCode);
    QFETCH(double, corruptShare);
    QFETCH(int, seed);
    QFETCH(int, kind);
    QFETCH(int, replyError);
    QFETCH(QString, model);

    Bench b(static_cast<Wiring>(wiring));
    tipscope::sim::SimFaults faults;
    faults.nakCode = nakCode;
    faults.corruptShare = corruptShare;
    faults.seed = quint32(seed);
    b.sim->setFaults(faults);
    b.line->open();
    QTRY_COMPARE_WITH_TIMEOUT(b.line->state(), Line::State::Open, kWaitMs);
    Discovery discovery(b.line->queue());
    QSignalSpy finished(&discovery, &Discovery::finished);
    QVERIFY(finished.isValid());

    discovery.identify(address);
    QVERIFY(finished.wait(kWaitMs));

    QVERIFY(discovery.identification().has_value());
    const Identification &found = *discovery.identification();
    QVERIFY(!found.ok());
    QCOMPARE(int(found.error().kind), kind);
    QCOMPARE(int(found.error().replyError), replyError);
    QCOMPARE(found.error().model, model);
    // A reply's failure carries its reason for people; an unknown model names itself instead.
    QCOMPARE(found.error().reason.isEmpty(), replyError == int(ReplyError::None));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestDiscovery)

} // namespace tst_discovery
#include "tst_discovery.moc"
