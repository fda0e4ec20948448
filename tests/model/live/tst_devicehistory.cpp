// Histories belong to a device, not to an address, and a gap in them is data. End to end through
// real tipscope-sim processes on PTYs: a DME at 01, then a DDE at 01 on another PTY, then the
// DME again keep two histories (samples and event markers) and the DME's continues its own; a
// 25 s unplug leaves a recorded gap that no chart curve and no measurement crosses.
#include "model/analysis/measurements.h"
#include "model/chart/chartevents.h"
#include "model/chart/chartframe.h"
#include "model/live/telemetryrecorder.h"
#include "model/session.h"
#include "testmain.h"

#include "support/ptyfixtures.h"

#include <QTest>
#include <cmath>

namespace tst_devicehistory {

using namespace tipscope;
using namespace tipscope::model;

namespace {
constexpr int kConnectMs = 60000;

// A tipscope-sim of `family` at its factory address on a PTY reached through `link`.
QString startSim(testing::SimProcess &sim, const QString &family, const QString &link) {
    QString error;
    const QString where =
        sim.start({QStringLiteral("--model"), family, QStringLiteral("--link"), link}, &error);
    return where.isEmpty() ? error : QString();
}

Session::Settings serialSettings(const QString &path) {
    Session::Settings settings;
    settings.line.kind = link::LineSettings::Kind::Serial;
    settings.line.serial.portName = path;
    settings.line.reconnectIntervalMs = 500;
    settings.addressing = Session::Addressing::With;
    settings.targetAddress = 1;
    return settings;
}

const TelemetryBuffer *port1History(Session &session) {
    StationModel *station = session.station();
    return station ? session.telemetry().buffer(TelemetryRecorder::keyOf(*station, 1)) : nullptr;
}

// Waits for `more` samples beyond what the port-1 history holds now. Port 1 is looked at, as a
// chart would, so its live values are polled at the live rate.
bool waitForSamples(Session &session, qint64 more) {
    if (!QTest::qWaitFor([&] { return port1History(session) != nullptr; }, kConnectMs))
        return false;
    session.scheduler().setVisiblePorts(session.station(), {1});
    const qint64 start = port1History(session)->totalAppended();
    return QTest::qWaitFor([&] { return port1History(session)->totalAppended() >= start + more; },
                           kConnectMs);
}

ChartChannel port1Channel(Session &session) {
    for (const ChartChannel &c : sessionChannels(session))
        if (c.port == 1)
            return c;
    return {};
}
} // namespace

class TestDeviceHistory : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aDifferentDeviceAtTheSameAddressKeepsItsOwnHistory();
    void anUnplugLeavesAGapThatNoCurveOrMeasurementCrosses();
};

void TestDeviceHistory::aDifferentDeviceAtTheSameAddressKeepsItsOwnHistory() {
    QTemporaryDir dir;
    testing::SimProcess dmeSim;
    testing::SimProcess ddeSim;
    const QString dmePath = dir.filePath(QStringLiteral("dme"));
    const QString ddePath = dir.filePath(QStringLiteral("dde"));
    const QString dmeError = startSim(dmeSim, QStringLiteral("DME"), dmePath);
    QVERIFY2(dmeError.isEmpty(), qPrintable(dmeError));
    const QString ddeError = startSim(ddeSim, QStringLiteral("DDE"), ddePath);
    QVERIFY2(ddeError.isEmpty(), qPrintable(ddeError));

    Session session;
    session.connectTo(serialSettings(dmePath));
    QVERIFY(waitForSamples(session, 5));
    const DeviceIdentity dme = session.station()->identity();
    QCOMPARE(dme.line, dmePath);
    QCOMPARE(dme.address, std::optional<int>(1));
    QVERIFY(dme.model.startsWith(QLatin1String("DME")));
    const TelemetryKey dmeKey = TelemetryRecorder::keyOf(*session.station(), 1);
    // A write gives the DME's port a marker of its own.
    session.station()->logWrite(1, QStringLiteral("written on the DME"));

    session.connectTo(serialSettings(ddePath));
    QVERIFY(waitForSamples(session, 5));
    const DeviceIdentity dde = session.station()->identity();
    QVERIFY(dde.model.startsWith(QLatin1String("DDE")));
    QCOMPARE(dde.address, dme.address); // the same address, another device
    const TelemetryKey ddeKey = TelemetryRecorder::keyOf(*session.station(), 1);
    QVERIFY(ddeKey != dmeKey);
    const qint64 dmeSamples = session.telemetry().buffer(dmeKey)->totalAppended();
    QVERIFY(session.telemetry().buffer(dmeKey)->gaps().isOpen()); // nobody watches it now
    session.station()->logWrite(1, QStringLiteral("written on the DDE"));
    const ChartChannel ddeChannel = port1Channel(session);
    QCOMPARE(ddeChannel.key, ddeKey);
    QCOMPARE(ddeChannel.device, dde);

    session.connectTo(serialSettings(dmePath));
    QVERIFY(waitForSamples(session, 5));
    QCOMPARE(session.station()->identity(), dme);
    QCOMPARE(TelemetryRecorder::keyOf(*session.station(), 1), dmeKey); // its history continues
    const TelemetryBuffer &history = *session.telemetry().buffer(dmeKey);
    QVERIFY(history.totalAppended() > dmeSamples);
    // While the DDE was watched, the DME's history got nothing but a gap.
    QCOMPARE(history.gaps().size(), 1);
    const TelemetryGap away = history.gaps().within(0, std::numeric_limits<qint64>::max()).first();
    QCOMPARE(away.cause, TelemetryGap::Cause::Disconnected);
    const TelemetryBuffer &ddeHistory = *session.telemetry().buffer(ddeKey);
    QVERIFY(ddeHistory.firstTime() >= away.startMs);
    QVERIFY(ddeHistory.lastTime() < *away.endMs);
    QCOMPARE(history.samples(0, away.startMs, *away.endMs).size(), 0);

    // The chart of the DME shows the DME's markers only, and says whose history it is.
    const ChartChannel channel = port1Channel(session);
    QCOMPARE(channel.device, dme);
    ChartEvents markers;
    for (const Event &e : session.eventLog().events())
        markers.addFromLog(e, {channel});
    QStringList texts;
    for (const ChartEvent &e : markers.between(0, std::numeric_limits<qint64>::max(), &channel))
        texts.append(e.text);
    QVERIFY2(texts.contains(QStringLiteral("written on the DME")), qPrintable(texts.join('|')));
    QVERIFY2(!texts.contains(QStringLiteral("written on the DDE")), qPrintable(texts.join('|')));
    // The event log tells the devices apart even where their sources read alike.
    bool ddeEventSeen = false;
    for (const Event &e : session.eventLog().events())
        ddeEventSeen =
            ddeEventSeen || (e.device == dde && e.text == QLatin1String("written on the DDE"));
    QVERIFY(ddeEventSeen);
}

void TestDeviceHistory::anUnplugLeavesAGapThatNoCurveOrMeasurementCrosses() {
    QTemporaryDir dir;
    testing::SimProcess sim;
    const QString path = dir.filePath(QStringLiteral("dme"));
    const QString error = startSim(sim, QStringLiteral("DME"), path);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    Session session;
    session.connectTo(serialSettings(path));
    QVERIFY(waitForSamples(session, 5));
    const TelemetryKey key = TelemetryRecorder::keyOf(*session.station(), 1);
    const TelemetryBuffer &history = *session.telemetry().buffer(key);

    QCOMPARE(sim.command(QStringLiteral("unplug")), QStringLiteral("ok"));
    QVERIFY(QTest::qWaitFor([&] { return history.gaps().isOpen(); }, kConnectMs));
    const qint64 lastBefore = history.lastTime();
    QTest::qWait(25'000);
    QVERIFY(!sim.command(QStringLiteral("plug")).startsWith(QLatin1String("error")));
    QVERIFY(waitForSamples(session, 5));

    QCOMPARE(history.gaps().size(), 1);
    const TelemetryGap gap = history.gaps().within(0, std::numeric_limits<qint64>::max()).first();
    QVERIFY(gap.startMs > lastBefore);
    QVERIFY(gap.endMs);
    QVERIFY2(*gap.endMs - gap.startMs >= 25'000,
             qPrintable(QString::number(*gap.endMs - gap.startMs)));

    // Drawn at a scale where the gap is hundreds of pixels wide, no line joins its two sides.
    const qint64 t0 = history.firstTime();
    const qint64 t1 = history.lastTime() + 1;
    const ChartChannel channel = port1Channel(session);
    const QList<ChartTrace> traces = tracesFor({channel}, {0}, TemperatureUnit::Celsius);
    const ChartFrame frame = buildFrame(session.telemetry(), {channel}, traces, t0, t1, 2000);
    for (const QList<QPointF> &points : frame.points) {
        QVERIFY(!points.isEmpty());
        for (qsizetype i = 1; i < points.size(); ++i) {
            const QPointF a = points.at(i - 1);
            const QPointF b = points.at(i);
            if (std::isfinite(a.y()) && std::isfinite(b.y()))
                QVERIFY2(!(a.x() <= lastBefore && b.x() >= *gap.endMs), "a curve crosses the gap");
        }
    }
    const PortMeasurements m = Measurements::measurePort(history, t0, t1, 5);
    for (const HeatUp &h : m.heatUps)
        QVERIFY(!(h.startMs < gap.startMs && h.reachedMs && *h.reachedMs >= *gap.endMs));
    for (const Recovery &r : m.recoveries)
        QVERIFY(!(r.startMs < gap.startMs && r.recoveredMs && *r.recoveredMs >= *gap.endMs));
    QVERIFY(!readoutAt(session.telemetry(), {channel}, traces, gap.startMs + 12'000).at(0).valid);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestDeviceHistory)

} // namespace tst_devicehistory
#include "tst_devicehistory.moc"
