// RecordingLoader reads on a thread of its own and hands the recording over in the caller's
// thread, reports progress, and can be cancelled or deleted while a FIFO sends nothing.
#include "support/fifowriter.h"
#include "testmain.h"

#include "model/recording/recordingloader.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

namespace tst_recordingloader {

using namespace tipscope::model;

namespace {
constexpr qint64 kT0 = 1'700'000'000'000;

QByteArray recording(int rows) {
    QByteArray csv = "# TipScope chart data, format 1\ntime,port1 tip [°C],events\n";
    for (int i = 0; i < rows; ++i)
        csv += QDateTime::fromMSecsSinceEpoch(kT0 + i * 100, Qt::UTC)
                   .toString(Qt::ISODateWithMs)
                   .toUtf8() +
               ",350,\n";
    return csv;
}
} // namespace

class TestRecordingLoader : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void theRecordingIsReadOffThisThreadAndHandedOverHere();
    void aBadFileFinishesWithTheReason();
    void aCancelFinishesTheLoadWhileAFifoSendsNothing();
    void aLoaderDeletedWhileReadingStopsItsThread();
};

void TestRecordingLoader::theRecordingIsReadOffThisThreadAndHandedOverHere() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("rec.csv"));
    const QByteArray csv = recording(100'000);
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    QCOMPARE(file.write(csv), csv.size());
    file.close();
    RecordingLoader loader;
    QSignalSpy finished(&loader, &RecordingLoader::finished);
    QSignalSpy progress(&loader, &RecordingLoader::progress);
    QVERIFY(finished.isValid() && progress.isValid());
    loader.start(path);
    QVERIFY(loader.isRunning());
    QCOMPARE(loader.totalBytes(), csv.size());
    QVERIFY(finished.wait(30'000));
    QCOMPARE(finished.first().first().toString(), QString());
    QVERIFY(!loader.isRunning());
    QVERIFY(!progress.isEmpty());
    QCOMPARE(progress.last().at(0).toLongLong(), csv.size());
    QCOMPARE(progress.last().at(1).toLongLong(), csv.size());
    const auto replay = loader.takeRecording();
    QVERIFY(replay);
    QCOMPARE(replay->rows, 100'000);
    QCOMPARE(replay->telemetry->thread(), QThread::currentThread());
    QCOMPARE(replay->telemetry->buffer(QStringLiteral("port1"))->size(), 100'000);
    QVERIFY(!loader.takeRecording()); // once
}

void TestRecordingLoader::aBadFileFinishesWithTheReason() {
    QTemporaryDir dir;
    RecordingLoader loader;
    QSignalSpy finished(&loader, &RecordingLoader::finished);
    QVERIFY(finished.isValid());
    loader.start(dir.filePath(QStringLiteral("missing.csv")));
    QVERIFY(finished.wait(10'000));
    QVERIFY2(finished.first().first().toString().startsWith(QStringLiteral("missing.csv, ")),
             qPrintable(finished.first().first().toString()));
    QVERIFY(!loader.wasCancelled());
    QVERIFY(!loader.takeRecording());
}

void TestRecordingLoader::aCancelFinishesTheLoadWhileAFifoSendsNothing() {
#ifdef Q_OS_UNIX
    QTemporaryDir dir;
    FifoWriter writer(dir, recording(10), false);
    QVERIFY(writer.ok());
    RecordingLoader loader;
    QSignalSpy finished(&loader, &RecordingLoader::finished);
    QSignalSpy progress(&loader, &RecordingLoader::progress);
    QVERIFY(finished.isValid() && progress.isValid());
    loader.start(writer.path());
    QCOMPARE(loader.totalBytes(), 0); // a FIFO says nothing of its size
    QTRY_VERIFY_WITH_TIMEOUT(writer.written() > 0 && loader.bytesRead() == writer.written(),
                             10'000);
    QVERIFY(!finished.wait(300)); // still waiting for more
    loader.cancel();
    QVERIFY(finished.wait(10'000));
    QVERIFY2(finished.first().first().toString().endsWith(ChartCsvReader::cancelledText()),
             qPrintable(finished.first().first().toString()));
    QVERIFY(loader.wasCancelled());
    QVERIFY(!progress.isEmpty());
#else
    QSKIP("FIFOs are a Unix thing");
#endif
}

void TestRecordingLoader::aLoaderDeletedWhileReadingStopsItsThread() {
#ifdef Q_OS_UNIX
    QTemporaryDir dir;
    FifoWriter writer(dir, recording(10), false);
    QVERIFY(writer.ok());
    auto loader = std::make_unique<RecordingLoader>();
    loader->start(writer.path());
    QTRY_VERIFY_WITH_TIMEOUT(writer.written() > 0 && loader->bytesRead() == writer.written(),
                             10'000);
    loader.reset(); // returns once the thread noticed; a hang here fails on the test's timeout
#else
    QSKIP("FIFOs are a Unix thing");
#endif
}

TIPSCOPE_TEST_GUILESS_MAIN(TestRecordingLoader)

} // namespace tst_recordingloader
#include "tst_recordingloader.moc"
