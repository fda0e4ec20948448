// Telemetry keeps one buffer per key, created on first use, and tells views about new samples
// through one coalesced signal rather than one per sample. No timing is asserted: a burst is
// appended without returning to the event loop, so it must be reported by a single emission.
#include "model/telemetry/telemetry.h"
#include "testmain.h"

#include <QSignalSpy>
#include <QTest>

namespace tst_telemetry {

using namespace tipscope::model;

namespace {

const QStringList kPortSeries = {QStringLiteral("tip"), QStringLiteral("setpoint"),
                                 QStringLiteral("power"), QStringLiteral("status")};
const QString kPort1 = QStringLiteral("01/port1");
const QString kFeeder = QStringLiteral("10/feeder");

} // namespace

class TestTelemetry : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void bufferIsCreatedOnFirstUseWithTheGivenSeries();
    void existingBufferKeepsItsSeries();
    void appendToAnUnknownKeyIsRefused();
    void burstOfAppendsIsCoalescedIntoFewSignals();
    void signalNamesOnlyTheBuffersThatChanged();
    void refusedSamplesDoNotSignal();
    void signalRateIsClampedToASaneRange_data();
    void signalRateIsClampedToASaneRange();
};

void TestTelemetry::bufferIsCreatedOnFirstUseWithTheGivenSeries() {
    Telemetry telemetry;
    QVERIFY(!telemetry.buffer(kPort1));
    const TelemetryBuffer &created = telemetry.ensureBuffer(kPort1, kPortSeries, 500);
    QCOMPARE(created.seriesNames(), kPortSeries);
    QCOMPARE(created.capacity(), 500);
    QCOMPARE(telemetry.buffer(kPort1), &created);
    telemetry.ensureBuffer(kFeeder, {QStringLiteral("status")});
    QCOMPARE(telemetry.keys(), QStringList({kPort1, kFeeder}));

    QCOMPARE(telemetry.append(kPort1, 100, {350, 350, 120, 0}), AppendResult::Accepted);
    QCOMPARE(created.size(), 1);
    QCOMPARE(created.valueAt(2, 100)->value, 120);
}

void TestTelemetry::existingBufferKeepsItsSeries() {
    Telemetry telemetry;
    const TelemetryBuffer &first = telemetry.ensureBuffer(kPort1, kPortSeries, 500);
    QTest::ignoreMessage(QtWarningMsg, QRegularExpression(QStringLiteral("already exists")));
    const TelemetryBuffer &again = telemetry.ensureBuffer(kPort1, {QStringLiteral("tip")}, 10);
    QCOMPARE(&again, &first);
    QCOMPARE(again.seriesNames(), kPortSeries);
    QCOMPARE(again.capacity(), 500);
}

void TestTelemetry::appendToAnUnknownKeyIsRefused() {
    Telemetry telemetry;
    QCOMPARE(telemetry.append(kPort1, 1, {1, 2, 3, 4}), AppendResult::UnknownKey);
    QVERIFY(telemetry.keys().isEmpty());
}

void TestTelemetry::burstOfAppendsIsCoalescedIntoFewSignals() {
    Telemetry telemetry;
    QSignalSpy spy(&telemetry, &Telemetry::samplesAdded);
    QVERIFY(spy.isValid());
    telemetry.ensureBuffer(kPort1, kPortSeries);
    for (int i = 0; i < 1000; ++i)
        QCOMPARE(telemetry.append(kPort1, i * 100, {350 + i % 3, 350, 100, 0}),
                 AppendResult::Accepted);

    QTRY_VERIFY(spy.count() >= 1);
    QVERIFY(spy.count() < 1000);
    // The whole burst came before the event loop ran, so one emission covers it.
    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy.first().first().toStringList(), QStringList{kPort1});
}

void TestTelemetry::signalNamesOnlyTheBuffersThatChanged() {
    Telemetry telemetry;
    QSignalSpy spy(&telemetry, &Telemetry::samplesAdded);
    QVERIFY(spy.isValid());
    telemetry.ensureBuffer(kPort1, kPortSeries);
    telemetry.ensureBuffer(kFeeder, {QStringLiteral("status")});
    telemetry.append(kFeeder, 1, {3});
    QTRY_COMPARE(spy.count(), 1);
    QCOMPARE(spy.takeFirst().first().toStringList(), QStringList{kFeeder});

    telemetry.append(kPort1, 2, {1, 2, 3, 4});
    telemetry.append(kFeeder, 2, {4});
    QTRY_COMPARE(spy.count(), 1);
    QCOMPARE(spy.takeFirst().first().toStringList(), QStringList({kPort1, kFeeder}));
}

void TestTelemetry::refusedSamplesDoNotSignal() {
    Telemetry telemetry;
    // A quick timer, so that waiting for a signal that must not come costs little.
    telemetry.setMaxSignalsPerSecond(1000);
    QSignalSpy spy(&telemetry, &Telemetry::samplesAdded);
    QVERIFY(spy.isValid());
    telemetry.ensureBuffer(kPort1, {QStringLiteral("tip")});
    telemetry.append(kPort1, 100, {1});
    QTRY_COMPARE(spy.count(), 1);

    QCOMPARE(telemetry.append(kPort1, 50, {2}), AppendResult::OutOfOrder);
    QCOMPARE(telemetry.append(kPort1, 150, {2, 3}), AppendResult::WrongValueCount);
    QCOMPARE(telemetry.append(kFeeder, 150, {2}), AppendResult::UnknownKey);
    QTest::qWait(50);
    QCOMPARE(spy.count(), 1);
}

void TestTelemetry::signalRateIsClampedToASaneRange_data() {
    QTest::addColumn<int>("asked");
    QTest::addColumn<int>("kept");

    QTest::newRow("default") << Telemetry::kDefaultMaxSignalsPerSecond << 20;
    QTest::newRow("zero") << 0 << 1;
    QTest::newRow("negative") << -5 << 1;
    QTest::newRow("above a millisecond timer") << 5000 << 1000;
}

void TestTelemetry::signalRateIsClampedToASaneRange() {
    QFETCH(int, asked);
    QFETCH(int, kept);
    Telemetry telemetry;
    telemetry.setMaxSignalsPerSecond(asked);
    QCOMPARE(telemetry.maxSignalsPerSecond(), kept);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestTelemetry)

} // namespace tst_telemetry
#include "tst_telemetry.moc"
