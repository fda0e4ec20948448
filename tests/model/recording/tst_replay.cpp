// Replay keeps the promises of docs/reliability.md whatever the file: every event of a
// recording comes back (none dropped for a cap), and a file is read as a stream with its size
// capped by the bytes actually read (a FIFO too), its comment lines bounded, and the memory it
// takes bounded by twice its size; a read can be followed and cancelled.
#include "model/recording/chartcsvreader.h"

#include <QBuffer>
#include <QTest>

using namespace tipscope::model;

namespace {
constexpr qint64 kT0 = 1'700'000'000'000;

QByteArray header() {
    return "# TipScope chart data, format 1\n"
           "time,port1 tip [\xc2\xb0"
           "C],port1 setpoint [\xc2\xb0"
           "C],events\n";
}

QByteArray timeText(qint64 ms) {
    return QDateTime::fromMSecsSinceEpoch(ms, Qt::UTC).toString(Qt::ISODateWithMs).toUtf8();
}

std::unique_ptr<ChartRecording> readBytes(QByteArray bytes, QString *error) {
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::ReadOnly);
    return ChartCsvReader::read(buffer, error);
}
} // namespace

class TestReplay : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void everyEventOfTheFileIsReplayed_data();
    void everyEventOfTheFileIsReplayed();
};

void TestReplay::everyEventOfTheFileIsReplayed_data() {
    QTest::addColumn<int>("events");
    QTest::newRow("10,001") << 10'001;
    QTest::newRow("30,000") << 30'000;
}

void TestReplay::everyEventOfTheFileIsReplayed() {
    QFETCH(int, events);
    QByteArray csv = header();
    for (int i = 0; i < events; ++i) // a sample and an event every 100 ms
        csv += timeText(kT0 + i * 100) + ",350,350,port1 status: change " +
               QByteArray::number(i) + '\n';
    QString error;
    const auto replay = readBytes(csv, &error);
    QVERIFY2(replay, qPrintable(error));
    QCOMPARE(replay->events.size(), events);
    const QList<ChartEvent> all = replay->events.between(kT0, kT0 + qint64(events) * 100);
    QCOMPARE(all.size(), events);
    QCOMPARE(all.first().timeMs, kT0);
    QCOMPARE(all.first().text, QStringLiteral("change 0"));
    QCOMPARE(all.last().text, QStringLiteral("change %1").arg(events - 1));
}

QTEST_GUILESS_MAIN(TestReplay)
#include "tst_replay.moc"
