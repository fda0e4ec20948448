// TelemetryRecorder against the simulator: a port's sample waits for the values it carries, is
// stamped at the instant its tip reading describes (not when the answer was decoded), never
// before the sample before it, and a tip that got no answer leaves a gap.
#include "model/live/telemetryrecorder.h"
#include "model/simfixture.h"
#include "testmain.h"

namespace tst_telemetryrecorder {

using namespace tipscope;
using namespace tipscope::model;
using namespace tipscope::protocol;
using namespace tipscope::testing;

namespace {
constexpr qint64 kT0 = 1'700'000'000'000;

// A DME on a simulated line, its port 1 recorded on a clock the test sets.
struct RecordedPort {
    SimFixture f{singleDevice(QStringLiteral("DME"))};
    std::unique_ptr<StationModel> station = f.station();
    Telemetry telemetry;
    qint64 now = kT0;
    TelemetryRecorder recorder{telemetry, [this] { return now; }};
    PortModel *port = station->port(1);
    Parameter *tip = port->parameter(Role::TipTemperature);

    RecordedPort() { recorder.watch(station.get()); }
    [[nodiscard]] const TelemetryBuffer *buffer() const {
        return telemetry.buffer(TelemetryRecorder::keyOf(*station, 1));
    }
    // Reads what a sample carries besides the tip, and waits for the answers.
    void readCarriedValues() {
        for (const Role role :
             {Role::Status, Role::Setpoint, Role::Power, Role::TransistorTemperature})
            port->parameter(role)->refresh();
        station->parameter(Role::TransformerTemperature)->refresh();
        f.settle();
    }
};
} // namespace

class TestTelemetryRecorder : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aSampleWaitsForTheValuesItCarries();
    void aSampleIsStampedAtTheInstantItsReadingDescribes();
    void aTipThatGetsNoAnswerLeavesAGap();
};

void TestTelemetryRecorder::aSampleWaitsForTheValuesItCarries() {
    RecordedPort r;
    // A tip alone would be drawn against a setpoint and a power of 0: no sample yet.
    r.tip->refresh();
    r.f.settle();
    QCOMPARE(r.buffer()->size(), 0);
    r.readCarriedValues();
    r.tip->refresh();
    r.f.settle();
    QCOMPARE(r.buffer()->size(), 1);
}

// The answer's bytes take their time on the wire and the event loop its own after them: a
// reading decoded now describes the tip of a few milliseconds ago, and a joint's start is
// measured against the station's moments. A stamp that would fall before the last sample keeps
// the order instead: every query binary-searches on time.
void TestTelemetryRecorder::aSampleIsStampedAtTheInstantItsReadingDescribes() {
    RecordedPort r;
    r.readCarriedValues();
    const TelemetryBuffer *buffer = r.buffer();
    r.tip->deviceReported("00350", 38.4);
    QCOMPARE(buffer->size(), 1);
    QCOMPARE(buffer->lastTime(), kT0 - 38);
    r.now = kT0 + 100;
    r.tip->deviceReported("00349", 0);
    QCOMPARE(buffer->lastTime(), kT0 + 100);
    r.now = kT0 + 150;
    r.tip->deviceReported("00348", 500); // would be before the last sample
    QCOMPARE(buffer->size(), 3);
    QCOMPARE(buffer->lastTime(), kT0 + 100);
    QCOMPARE(buffer->outOfOrderCount(), 0);

    // Read through the wire: the sample is older than the moment its answer was decoded.
    qint64 decodedAt = 0;
    connect(r.tip, &Parameter::updated, this, [&] { decodedAt = r.now; });
    r.now = kT0 + 1000;
    r.tip->refresh();
    QTRY_COMPARE(buffer->size(), 4);
    QCOMPARE(decodedAt, kT0 + 1000);
    QCOMPARE(buffer->lastTime(), kT0 + 1000 - std::llround(r.tip->reportedAgeMs()));
}

void TestTelemetryRecorder::aTipThatGetsNoAnswerLeavesAGap() {
    RecordedPort r;
    r.readCarriedValues();
    r.tip->refresh();
    r.f.settle();
    QCOMPARE(r.buffer()->size(), 1);
    QCOMPARE(r.buffer()->gaps().size(), 0);
    sim::SimFaults refuse;
    refuse.nakCode = 4;
    r.f.simLine->setFaults(refuse);
    r.now = kT0 + 500;
    r.tip->refresh();
    r.f.settle();
    QCOMPARE(r.buffer()->gaps().size(), 1);
    QVERIFY(r.buffer()->gaps().isOpen());
}

TIPSCOPE_TEST_MAIN(TestTelemetryRecorder)

} // namespace tst_telemetryrecorder
#include "tst_telemetryrecorder.moc"
