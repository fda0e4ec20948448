// A workspace of real simulated lines: two serial lines (socat PTY pairs with tipscope-sim on
// them) and a TCP serial server (tipscope-sim --tcp). Every line connects on its own; when one
// simulator dies the other lines keep polling and stay connected, and the dead line retries until
// its simulator is back on the same port, then polls again. Each line's joints are judged by its
// own limits, and its devices carry the names the workspace gives them.
#include "model/workspace/workspace.h"
#include "testmain.h"

#include "support/programrun.h"

#include <QSignalSpy>
#include <QTest>

namespace tst_workspace {

using namespace tipscope;
using namespace tipscope::model;

namespace {
constexpr int kConnectMs = 60000;

WorkspaceLine serialLine(const QString &name, const QString &port) {
    WorkspaceLine l;
    l.name = name;
    l.session.line.kind = link::LineSettings::Kind::Serial;
    l.session.line.serial.portName = port;
    l.deviceNames = {{1, name + QStringLiteral(" station")}};
    return l;
}

WorkspaceLine tcpLine(const QString &name, const QString &where) {
    WorkspaceLine l;
    l.name = name;
    l.session.line.kind = link::LineSettings::Kind::Tcp;
    l.session.line.tcpHost = where.section(QLatin1Char(':'), 0, 0);
    l.session.line.tcpPort = quint16(where.section(QLatin1Char(':'), 1).toUInt());
    l.session.line.reconnectIntervalMs = 300;
    return l;
}

// Samples of a port of the line's station so far (0 before it has one).
qint64 samplesOf(Session &session, int port = 1) {
    if (!session.station())
        return 0;
    const TelemetryBuffer *buffer =
        session.telemetry().buffer(TelemetryRecorder::keyOf(*session.station(), port));
    return buffer ? buffer->totalAppended() : 0;
}

const QStringList kStation = {QStringLiteral("--model"), QStringLiteral("DME")};
} // namespace

class TestWorkspace : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aDeadLineNeitherStopsTheOthersNorStaysDead();
    void eachLineIsJudgedByItsOwnLimitsAndNamesItsDevices();
    void aLineJoinsUnderANewNameAndEveryPortIsWatched();
};

void TestWorkspace::aDeadLineNeitherStopsTheOthersNorStaysDead() {
    testing::SimOnSocat serialA, serialB;
    testing::SimProcess server;
    QString error;
    const QString portA = serialA.start(kStation, &error);
    if (portA.isEmpty() && error.contains(QStringLiteral("socat is not installed")))
        QSKIP(qPrintable(error));
    QVERIFY2(!portA.isEmpty(), qPrintable(error));
    const QString portB = serialB.start(kStation, &error);
    QVERIFY2(!portB.isEmpty(), qPrintable(error));
    const QString where = server.start(
        kStation + QStringList{QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:0")}, &error);
    QVERIFY2(!where.isEmpty(), qPrintable(error));

    WorkspaceFile file;
    file.lines = {serialLine(QStringLiteral("cell-1"), portA),
                  serialLine(QStringLiteral("cell-2"), portB),
                  tcpLine(QStringLiteral("wave-1"), where)};
    Workspace workspace;
    QSignalSpy states(&workspace, &Workspace::lineStateChanged);
    QVERIFY(states.isValid());
    workspace.open(file);
    QCOMPARE(workspace.count(), 3);
    for (int i = 0; i < workspace.count(); ++i)
        QVERIFY(workspace.session(i)->scheduler().fillsWire());
    Session &a = *workspace.session(0), &b = *workspace.session(1), &tcp = *workspace.session(2);
    for (Session *s : {&a, &b, &tcp}) {
        QTRY_VERIFY_WITH_TIMEOUT(s->state() == Session::State::Connected && s->station(),
                                 kConnectMs);
        QTRY_VERIFY_WITH_TIMEOUT(samplesOf(*s) > 0, kConnectMs);
    }

    server.stop();
    QTRY_COMPARE_WITH_TIMEOUT(tcp.state(), Session::State::Retrying, kConnectMs);
    QVERIFY(!tcp.station()->isLineUp());
    bool reportedWithIndex = false;
    for (const QList<QVariant> &s : std::as_const(states))
        reportedWithIndex |=
            s.at(0).toInt() == 2 && s.at(1).value<Session::State>() == Session::State::Retrying;
    QVERIFY(reportedWithIndex);
    // While it is down, the others poll on: each gets fresh samples and stays connected.
    const qint64 aBefore = samplesOf(a), bBefore = samplesOf(b), tcpDown = samplesOf(tcp);
    QTRY_VERIFY_WITH_TIMEOUT(samplesOf(a) > aBefore + 5 && samplesOf(b) > bBefore + 5, kConnectMs);
    QCOMPARE(a.state(), Session::State::Connected);
    QCOMPARE(b.state(), Session::State::Connected);
    QVERIFY(a.station()->isLineUp() && b.station()->isLineUp());
    QCOMPARE(tcp.state(), Session::State::Retrying);
    QCOMPARE(samplesOf(tcp), tcpDown);

    // Back on the same port: the line reconnects by itself and polls again.
    testing::SimProcess again;
    const QString whereAgain =
        again.start(kStation + QStringList{QStringLiteral("--tcp"), where}, &error);
    QVERIFY2(whereAgain == where, qPrintable(error + whereAgain));
    QTRY_COMPARE_WITH_TIMEOUT(tcp.state(), Session::State::Connected, kConnectMs);
    QVERIFY(tcp.station()->isLineUp());
    QTRY_VERIFY_WITH_TIMEOUT(samplesOf(tcp) > tcpDown + 5, kConnectMs);
    QCOMPARE(a.state(), Session::State::Connected);
    QCOMPARE(b.state(), Session::State::Connected);
}

void TestWorkspace::eachLineIsJudgedByItsOwnLimitsAndNamesItsDevices() {
    testing::SimOnSocat serial;
    QString error;
    const QString port = serial.start(kStation, &error);
    if (port.isEmpty() && error.contains(QStringLiteral("socat is not installed")))
        QSKIP(qPrintable(error));
    QVERIFY2(!port.isEmpty(), qPrintable(error));
    WorkspaceLine own = serialLine(QStringLiteral("cell-1"), port);
    JointLimits strict;
    strict.maxRecoveryMs = 1500;
    own.jointLimits = JointLimitRules(strict);
    // A second line to nowhere: it never connects, and never holds up the first.
    WorkspaceLine nowhere = tcpLine(QStringLiteral("cell-2"), QStringLiteral("127.0.0.1:1"));
    WorkspaceFile file;
    file.lines = {own, nowhere};
    Workspace workspace;
    JointLimits shared;
    shared.maxRecoveryMs = 9000;
    workspace.setSharedLimits(JointLimitRules(shared));
    QSignalSpy lines(&workspace, &Workspace::linesChanged);
    QVERIFY(lines.isValid());
    workspace.open(file);
    QCOMPARE(lines.count(), 1);
    QCOMPARE(workspace.indexOf(QStringLiteral("cell-2")), 1);
    QCOMPARE(workspace.indexOf(QStringLiteral("cell-9")), -1);
    QCOMPARE(workspace.session(0)->joints().rules().defaults().maxRecoveryMs, qint64(1500));
    QCOMPARE(workspace.session(1)->joints().rules().defaults().maxRecoveryMs, qint64(9000));
    QTRY_VERIFY_WITH_TIMEOUT(workspace.session(0)->station(), kConnectMs);
    QCOMPARE(workspace.deviceName(0, *workspace.session(0)->station()),
             QStringLiteral("cell-1 station"));
    QVERIFY(workspace.session(1)->state() != Session::State::Connected);
    workspace.close();
    QCOMPARE(workspace.count(), 0);
    QCOMPARE(lines.count(), 2);
}

// A line added to those open connects while the first carries on; a name in use, or none, is
// refused and adds nothing. A workspace watches a fleet: every port of every station is polled
// live, with no page asking for it.
void TestWorkspace::aLineJoinsUnderANewNameAndEveryPortIsWatched() {
    WorkspaceLine demo;
    demo.name = QStringLiteral("cell-1");
    demo.session.line.kind = link::LineSettings::Kind::Demo;
    demo.session.demoPaced = false;
    WorkspaceFile file;
    file.lines = {demo};
    Workspace workspace;
    workspace.open(file);
    QTRY_VERIFY_WITH_TIMEOUT(workspace.session(0)->station(), kConnectMs);
    Session &first = *workspace.session(0);

    QSignalSpy lines(&workspace, &Workspace::linesChanged);
    QVERIFY(lines.isValid());
    const auto same = workspace.addLine(demo);
    QVERIFY(!same.ok());
    QVERIFY2(same.error().contains(QStringLiteral("cell-1")), qPrintable(same.error()));
    WorkspaceLine unnamed = demo;
    unnamed.name = QStringLiteral("  ");
    QVERIFY(!workspace.addLine(unnamed).ok());
    QCOMPARE(workspace.count(), 1);
    QCOMPARE(lines.count(), 0);

    WorkspaceLine second = demo;
    second.name = QStringLiteral("cell-2");
    QVERIFY(workspace.addLine(second).ok());
    QCOMPARE(workspace.count(), 2);
    QCOMPARE(lines.count(), 1);
    QCOMPARE(workspace.indexOf(QStringLiteral("cell-2")), 1);
    QCOMPARE(workspace.session(0), &first); // the first line was left as it was
    QCOMPARE(first.state(), Session::State::Connected);
    QTRY_VERIFY_WITH_TIMEOUT(workspace.session(1)->station(), kConnectMs);

    // The scheduler polls a port nobody shows at the status interval; a workspace's ports are
    // all at the live one: port 4's tip is read as often as port 1's.
    for (Session *s : {&first, workspace.session(1)}) {
        s->scheduler().setInterval(PollClass::Live, 100);
        s->scheduler().setInterval(PollClass::Status, 600000);
        const qint64 before = samplesOf(*s, 4);
        QTRY_VERIFY_WITH_TIMEOUT(samplesOf(*s, 4) > before + 10, kConnectMs);
    }
}

TIPSCOPE_TEST_GUILESS_MAIN(TestWorkspace)

} // namespace tst_workspace
#include "tst_workspace.moc"
