// A recording played as a line: its samples reach the session's telemetry as recorded (gaps
// stay gaps), its joints are found by the session's joint watcher with the recording's device
// and tools, a joint cut by the recording's end is incomplete, a rest is not a joint, and a file
// that cannot be played says why. A workspace line of kind "recording" is played by the
// workspace, found beside the workspace file.
#include "jointrecording.h"
#include "testmain.h"

#include "model/recording/recordingplayback.h"
#include "model/workspace/linetile.h"
#include "model/workspace/workspace.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

namespace tst_recordingplayback {

using namespace tipscope;
using namespace tipscope::model;

namespace {

// Plays `path` into `session` and keeps the joints it finds.
QList<JointRecord> play(Session &session, const QString &path) {
    QList<JointRecord> joints;
    QObject::connect(&session.joints(), &JointWatcher::jointEnded, &session,
                     [&joints](const JointRecord &j) { joints.append(j); });
    Session::Settings settings;
    settings.recordingPath = path;
    session.connectTo(settings);
    QSignalSpy finished(RecordingPlayback::start(session), &RecordingPlayback::finished);
    if (!finished.wait(30'000))
        qWarning("the playback did not finish");
    return joints;
}

const JointRecord *nearest(const QList<JointRecord> &found, const sim::SimJoint &truth) {
    const JointRecord *best = nullptr;
    for (const JointRecord &j : found)
        if (j.port == truth.port &&
            (!best || qAbs(j.startMs - truth.startMs) < qAbs(best->startMs - truth.startMs)))
            best = &j;
    return best;
}

} // namespace

class TestRecordingPlayback : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void aRecordingIsPlayedAsTheLinesSamplesAndJoints();
    void aFileThatCannotBePlayedSaysWhy_data();
    void aFileThatCannotBePlayedSaysWhy();
    void aWorkspaceLinePlaysTheRecordingBesideIt();

private:
    QTemporaryDir m_dir;
    QString m_recording;
    testing::RecordedJoints m_truth;
};

void TestRecordingPlayback::initTestCase() {
    QVERIFY(m_dir.isValid());
    m_recording = m_dir.filePath(QStringLiteral("joints.csv"));
    QString error;
    QVERIFY2(testing::writeJointRecording(m_recording, &m_truth, &error), qPrintable(error));
}

void TestRecordingPlayback::aRecordingIsPlayedAsTheLinesSamplesAndJoints() {
    Session session;
    QSignalSpy states(&session, &Session::stateChanged);
    const QList<JointRecord> found = play(session, m_recording);

    // Connecting (reading), Connected (playing), Disconnected (played), with what was played.
    QCOMPARE(session.state(), Session::State::Disconnected);
    QVERIFY2(session.stateText().contains(QStringLiteral("joints.csv played")),
             qPrintable(session.stateText()));
    QVERIFY(std::any_of(states.cbegin(), states.cend(), [](const QList<QVariant> &s) {
        return s.at(0).value<Session::State>() == Session::State::Connected;
    }));
    QVERIFY(session.devices().isEmpty());

    // Every recorded sample, under the recording's device; port 3's silence is a gap.
    const DeviceIdentity device{QStringLiteral("recording ") +
                                    QFileInfo(m_recording).absoluteFilePath(),
                                1, QStringLiteral("DDE-4C"), QStringLiteral("9996780")};
    qint64 samples = 0;
    for (int port = 1; port <= 4; ++port) {
        const TelemetryBuffer *buffer =
            session.telemetry().buffer(TelemetryRecorder::keyOf(device, port));
        QVERIFY2(buffer, qPrintable(TelemetryRecorder::keyOf(device, port)));
        samples += buffer->totalAppended();
        QCOMPARE(buffer->gaps().within(m_truth.firstMs, m_truth.lastMs + 1).size(),
                 port == 3 ? 1 : 0);
    }
    QCOMPARE(samples, qint64(m_truth.samples));

    // Each joint made is found once, on its port, with its device and tool; the rest in the
    // stand is not a joint; the joint the recording cuts short is incomplete.
    QCOMPARE(found.size(), m_truth.made.size());
    for (const sim::SimJoint &truth : std::as_const(m_truth.made)) {
        const JointRecord *j = nearest(found, truth);
        QVERIFY2(j, qPrintable(QStringLiteral("port %1 at %2").arg(truth.port).arg(truth.startMs)));
        QCOMPARE(j->device, device);
        QCOMPARE(j->tool, truth.port % 2 ? QStringLiteral("T245") : QStringLiteral("T210"));
        // The samples are 70-130 ms apart in whole degrees: a fit across them does better.
        QVERIFY2(qAbs(j->startMs - truth.startMs) <= 130,
                 qPrintable(QStringLiteral("port %1: start %2 ms off")
                                .arg(truth.port)
                                .arg(j->startMs - truth.startMs)));
        const bool cutShort = truth.startMs + truth.recoveryMs > m_truth.lastMs;
        QCOMPARE(j->verdict == JointVerdict::Incomplete, cutShort);
        if (cutShort) // the recording ends before the tip reached its lowest
            continue;
        QVERIFY2(qAbs(j->dipDepth - truth.depthK) <= 3.0,
                 qPrintable(QStringLiteral("port %1: dip %2 K, made %3 K")
                                .arg(truth.port)
                                .arg(j->dipDepth)
                                .arg(truth.depthK)));
        if (j->recoveryMs)
            QVERIFY2(qAbs(*j->recoveryMs - truth.recoveryMs) <= 250,
                     qPrintable(QStringLiteral("port %1: recovery %2 ms, made %3 ms")
                                    .arg(truth.port)
                                    .arg(*j->recoveryMs)
                                    .arg(truth.recoveryMs)));
    }
}

void TestRecordingPlayback::aFileThatCannotBePlayedSaysWhy_data() {
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QString>("why");
    QTest::newRow("not a recording") << QByteArray("hello\n") << QStringLiteral("cannot be played");
    QTest::newRow("only a feeder") << QByteArray("# TipScope chart data, format 1\n"
                                                 "time,feeder fed [mm],events\n"
                                                 "2026-05-28T10:00:00.000Z,12,\n")
                                   << QStringLiteral("holds no station port");
}

void TestRecordingPlayback::aFileThatCannotBePlayedSaysWhy() {
    QFETCH(QByteArray, content);
    QFETCH(QString, why);
    const QString path = m_dir.filePath(QStringLiteral("bad.csv"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(content);
    file.close();
    Session session;
    QVERIFY(play(session, path).isEmpty());
    QCOMPARE(session.state(), Session::State::Failed);
    QVERIFY2(session.stateText().contains(why), qPrintable(session.stateText()));
    QVERIFY(session.stateText().contains(QStringLiteral("bad.csv")));
}

void TestRecordingPlayback::aWorkspaceLinePlaysTheRecordingBesideIt() {
    const QString path = m_dir.filePath(QStringLiteral("replay.json"));
    const QJsonObject line{{QStringLiteral("name"), QStringLiteral("replayed")},
                           {QStringLiteral("connection"),
                            QJsonObject{{QStringLiteral("kind"), QStringLiteral("recording")},
                                        {QStringLiteral("path"), QStringLiteral("joints.csv")}}}};
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(
        QJsonDocument(QJsonObject{{QStringLiteral("format"), QStringLiteral("tipscope-workspace")},
                                  {QStringLiteral("version"), 1},
                                  {QStringLiteral("lines"), QJsonArray{line}}})
            .toJson());
    file.close();
    const auto loaded = WorkspaceFile::load(path);
    QVERIFY2(loaded, qPrintable(loaded.error()));
    QCOMPARE(loaded->lines.first().session.recordingPath,
             QFileInfo(m_recording).absoluteFilePath());
    // Written back as it was read.
    const QJsonObject written = workspaceLineToJson(loaded->lines.first());
    QCOMPARE(written.value(QStringLiteral("connection")).toObject().value(QStringLiteral("kind")),
             QJsonValue(QStringLiteral("recording")));
    // A recording line must name its file.
    QJsonObject nameless = line;
    nameless.insert(QStringLiteral("connection"),
                    QJsonObject{{QStringLiteral("kind"), QStringLiteral("recording")}});
    const auto refused = workspaceLineFromJson(nameless);
    QVERIFY(!refused);
    QVERIFY2(refused.error().contains(QStringLiteral("connection.path")),
             qPrintable(refused.error()));

    // Run from another folder: the recording is still found beside the workspace.
    QVERIFY(QDir::setCurrent(QDir::tempPath()));
    Workspace workspace;
    int joints = 0;
    workspace.open(loaded.value());
    QCOMPARE(workspace.count(), 1);
    Session &session = *workspace.session(0);
    QVERIFY(session.isPlayback());
    connect(&session.joints(), &JointWatcher::jointEnded, this, [&joints] { ++joints; });
    QTRY_COMPARE_WITH_TIMEOUT(session.state(), Session::State::Disconnected, 30'000);
    QCOMPARE(joints, m_truth.made.size());
    // On the fleet overview a played recording is no line down: it needs no attention, and
    // says how it went.
    const FleetTileState tile = LineTile(workspace, 0).state();
    QCOMPARE(tile.deviceName, QStringLiteral("Recording"));
    QVERIFY(!tile.needsAttention());
    QVERIFY(!tile.problems.isEmpty());
    QVERIFY2(tile.problems.first().text.contains(QStringLiteral("played")),
             qPrintable(tile.problems.first().text));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestRecordingPlayback)

} // namespace tst_recordingplayback
#include "tst_recordingplayback.moc"
