// tipscope-cli against a misbehaving device and a bad wire: the real binary and tipscope-sim over
// a socat PTY pair (or TCP). Every case ends with the exit status the manual promises and a
// message that says what happened.
#include "fullbacklog.h"
#include "programrun.h"
#include "testmain.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

namespace tst_cliwire {

using namespace tipscope::testing;

namespace {

constexpr int kSlowApplyMs = 300000;

ProgramRun runCli(const QStringList &args) {
    return runProgram(QStringLiteral("tipscope-cli"), args);
}

} // namespace

class TestCliWire : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void unreadableDataFieldIsExitFourForReadAndDump_data();
    void unreadableDataFieldIsExitFourForReadAndDump();
    void unreadableDataFieldIsRetriedLikeABadBcc();
    void lateAnswersAreNeverTakenForTheReadBack_data();
    void lateAnswersAreNeverTakenForTheReadBack();
    void tcpServerThatNeverAcceptsIsExitFiveAfterTheConnectTimeout();
    void aNakForWritesOnlyLetsTheDeviceBeFoundAndRefusesTheWrite_data();
    void aNakForWritesOnlyLetsTheDeviceBeFoundAndRefusesTheWrite();
    void junkInsteadOfAnAnswerIsExitFourWithItsSize();

private:
    QString startSim(const QStringList &simArgs) {
        QString error;
        const QString port = m_line.start(simArgs, &error);
        if (port.isEmpty())
            qWarning("%s", qPrintable(error));
        return port;
    }
    SimOnSocat m_line;
};

void TestCliWire::unreadableDataFieldIsExitFourForReadAndDump_data() {
    QTest::addColumn<QStringList>("command");
    QTest::newRow("read") << QStringList{"read", "ST1"};
    QTest::newRow("read --raw") << QStringList{"read", "--raw", "ST1"};
    QTest::newRow("dump") << QStringList{"dump"};
    QTest::newRow("dump --json") << QStringList{"dump", "--json"};
}

void TestCliWire::unreadableDataFieldIsExitFourForReadAndDump() {
    QFETCH(QStringList, command);
    const QString port = startSim({"--model", "DME", "--bad-data", "1"});
    QVERIFY(!port.isEmpty());
    const ProgramRun r = runCli(QStringList{"--port", port, "--addr", "00:01"} + command);
    QCOMPARE(r.exitCode, 4);
    const QString said = r.out + r.err;
    QVERIFY2(said.contains(QStringLiteral("unreadable data field '?BAD?' in the answer after 3 "
                                          "attempts")),
             qPrintable(said));
    // Nothing unreadable is printed as if it were a value.
    QVERIFY2(!r.out.contains(QStringLiteral("ST1 ?BAD?")) &&
                 !r.out.contains(QStringLiteral("\"data\": \"?BAD?\"")),
             qPrintable(r.out));
}

void TestCliWire::unreadableDataFieldIsRetriedLikeABadBcc() {
    const QString port = startSim({"--model", "DME", "--bad-data", "0.4", "--seed", "5"});
    QVERIFY(!port.isEmpty());
    const ProgramRun r = runCli({"--port", port, "--addr", "00:01", "--retries", "8", "read", "ST1",
                                 "ST2", "ST3", "ST4", "TT1", "HD1"});
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(r.out.count(QStringLiteral("350 °C")), 4);
    const QString stats = m_line.sim().command(QStringLiteral("stats"));
    QVERIFY2(!stats.contains(QStringLiteral(" bad-data 0 ")), qPrintable(stats));
}

void TestCliWire::lateAnswersAreNeverTakenForTheReadBack_data() {
    // The answer budget of an addressed read at 19200 baud: about 20 ms on the wire plus the
    // default turnaround of 100 ms.
    QTest::addColumn<int>("latencyMs");
    QTest::newRow("at the answer budget") << 120;
    QTest::newRow("twice the answer budget") << 250;
}

// The device applies every write, but answers late: a timed-out request's answer is still on its
// way when the next request of the same code goes out (the frames carry no sequence number). A
// profile apply reads every setting, then writes and reads back what differs; taking one
// request's answer for another's reported writes failed with the value from before them.
void TestCliWire::lateAnswersAreNeverTakenForTheReadBack() {
    QFETCH(int, latencyMs);
    const QString port = startSim({"--model", "DME"});
    QVERIFY(!port.isEmpty());
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("p.json"));
    QCOMPARE(runCli({"--port", port, "--addr", "00:01", "profile", "save", file}).exitCode, 0);
    const QMap<QString, QString> changes{
        {"ST1", "00360"}, {"ST2", "00365"}, {"ST3", "00370"}, {"ST4", "00375"}, {"A11", "00010"},
        {"A21", "00011"}, {"A31", "00012"}, {"A41", "00013"}, {"A12", "00014"}, {"A22", "00015"}};
    QFile f(file);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QJsonObject profile = QJsonDocument::fromJson(f.readAll()).object();
    f.close();
    QJsonObject values = profile.value(QStringLiteral("values")).toObject();
    const QJsonObject before = values;
    for (auto it = changes.cbegin(); it != changes.cend(); ++it)
        values.insert(it.key(), it.value());
    profile.insert(QStringLiteral("values"), values);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(QJsonDocument(profile).toJson());
    f.close();

    QCOMPARE(m_line.sim().command(QStringLiteral("latency %1").arg(latencyMs)),
             QStringLiteral("ok"));
    // Every answer late, every read waits out its late answer: on a loaded machine this apply
    // takes minutes, and it is its outcome that is checked here, not its time.
    const ProgramRun r =
        runProgram(QStringLiteral("tipscope-cli"),
                   {"--port", port, "--addr", "00:01", "profile", "apply", file}, kSlowApplyMs);
    // Each write is verified, or (if every retry's answer came late, as on a loaded machine)
    // fails for want of one; never for an answer that was another's: an old value, or a write's
    // empty answer taken for a read.
    QVERIFY2(r.exitCode != -1 && r.out.contains(QStringLiteral(" already right, ")),
             qPrintable(r.out + r.err));
    // On a loaded machine enough answers in a row can come too late for the line to take the
    // station for gone (Line::Settings::suspectAfterTimeouts) and reconnect: the writes queued
    // then are not sent, the one on the wire then fails with the line, and the CLI says once why
    // the line dropped.
    const bool droppedUnanswered =
        r.err.contains(QStringLiteral("the line was dropped during the apply: no answer to "));
    QStringList unanswered;
    QStringList notSent;
    for (const QString &line : r.out.split(QLatin1Char('\n'))) {
        const QString code = line.section(QLatin1Char(' '), 1, 1);
        const bool verified = line.startsWith(QStringLiteral("changed "));
        const bool noAnswer = line.startsWith(QStringLiteral("FAILED ")) &&
                              line.contains(QStringLiteral(": no answer after "));
        const bool dropped =
            droppedUnanswered && line.startsWith(QStringLiteral("FAILED ")) &&
            line.endsWith(QStringLiteral(": not written: not sent: the line is not connected"));
        // The request on the wire when the line was dropped: it may have been carried out.
        const bool lostOnTheWire = droppedUnanswered &&
                                   line.startsWith(QStringLiteral("FAILED ")) &&
                                   line.contains(QStringLiteral(": the line was lost: "));
        if (changes.contains(code)) {
            QVERIFY2(verified || noAnswer || dropped || lostOnTheWire, qPrintable(r.out + r.err));
            if (noAnswer || lostOnTheWire)
                unanswered.append(code);
            if (dropped)
                notSent.append(code);
        }
        QVERIFY2(!line.contains(QStringLiteral("the device reports")) &&
                     !line.contains(QStringLiteral("unreadable data field")),
                 qPrintable(r.out));
    }
    // A verified write holds on the device. A setting whose read or write got no answer on a
    // loaded machine may not have been written (its read failed first) or may have been (the
    // CLI says "the device may have carried it out"): it holds the old value or the new one,
    // never a third. One never sent holds the old value.
    const QString onDevice =
        m_line.sim().command(QStringLiteral("get ") + changes.keys().join(QLatin1Char(' ')));
    for (auto it = changes.cbegin(); it != changes.cend(); ++it) {
        const QString now = QStringLiteral("%1=%2").arg(it.key()).arg(it.value().toInt());
        // A saved profile holds each value as {"name", "raw", "value"}.
        QVERIFY2(before.value(it.key()).toObject().contains(QStringLiteral("raw")),
                 qPrintable(it.key()));
        const QString old = QStringLiteral("%1=%2").arg(it.key()).arg(
            before.value(it.key()).toObject().value(QStringLiteral("raw")).toString().toInt());
        const QStringList fields = onDevice.split(QLatin1Char(' '));
        const bool held = notSent.contains(it.key()) ? fields.contains(old)
                          : unanswered.contains(it.key())
                              ? fields.contains(now) || fields.contains(old)
                              : fields.contains(now);
        if (!held) // Qt Test cuts a long message: the whole report, to tell which case it was
            qWarning().noquote() << r.out << r.err;
        QVERIFY2(
            held,
            qPrintable(QStringLiteral("%1 on the device: %2\n%3").arg(it.key(), onDevice, r.out)));
    }
}

// A serial device server whose accept queue is full held the CLI for the system's own connect
// limit (a minute and more). The connection has 5 s.
void TestCliWire::tcpServerThatNeverAcceptsIsExitFiveAfterTheConnectTimeout() {
    FullBacklog server;
    QVERIFY(server.port() != 0);
    const ProgramRun r = runProgram(QStringLiteral("tipscope-cli"),
                                    {"--tcp", QStringLiteral("127.0.0.1:%1").arg(server.port()),
                                     "--addr", "00:01", "read", "ST1"},
                                    30000);
    QCOMPARE(r.exitCode, 5);
    QVERIFY2(r.err.contains(QStringLiteral("no connection within 5 s")), qPrintable(r.err));
}

void TestCliWire::aNakForWritesOnlyLetsTheDeviceBeFoundAndRefusesTheWrite_data() {
    QTest::addColumn<QString>("nakFor");
    QTest::newRow("writes") << QStringLiteral("writes");
    QTest::newRow("one command") << QStringLiteral("ST1");
}

// `--nak CODE` alone NAKs identification too, so no write could be tried against it.
void TestCliWire::aNakForWritesOnlyLetsTheDeviceBeFoundAndRefusesTheWrite() {
    QFETCH(QString, nakFor);
    const QString port = startSim({"--model", "DME", "--nak", "3", "--nak-for", nakFor});
    QVERIFY(!port.isEmpty());
    // Patient with the reads before the write (the device's limits), which a machine running
    // tests side by side can delay past the default turnaround: a NAK comes at once all the same.
    const ProgramRun w =
        runCli({"--port", port, "--timeout", "1000", "--retries", "5", "write", "ST1", "400"});
    QVERIFY2(w.exitCode == 3, qPrintable(QStringLiteral("exit %1: %2").arg(w.exitCode).arg(w.err)));
    QVERIFY2(w.err.contains(QStringLiteral("NAK 00003")), qPrintable(w.err));
    const ProgramRun r = runCli({"--port", port, "read", "ST2"});
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(r.out, QStringLiteral("ST2 350 °C\n"));
}

// A device (or a wrong baud rate) that sends 10 MB of junk was reported as "no answer".
void TestCliWire::junkInsteadOfAnAnswerIsExitFourWithItsSize() {
    QTcpServer device;
    QVERIFY(device.listen(QHostAddress::LocalHost));
    bool sent = false;
    connect(&device, &QTcpServer::newConnection, this, [&] {
        QTcpSocket *s = device.nextPendingConnection();
        connect(s, &QTcpSocket::readyRead, s, [s, &sent] {
            s->readAll();
            if (!std::exchange(sent, true))
                s->write(QByteArray(10 << 20, 'x'));
        });
    });
    QProcess cli; // asynchronous: this test's event loop is the device
    cli.start(binaryPath(QStringLiteral("tipscope-cli")),
              {"--tcp", QStringLiteral("127.0.0.1:%1").arg(device.serverPort()), "--addr", "00:01",
               "read", "ST1"});
    QTRY_VERIFY_WITH_TIMEOUT(cli.state() == QProcess::NotRunning, 60000);
    QCOMPARE(cli.exitCode(), 4);
    const QString err = QString::fromUtf8(cli.readAllStandardError());
    QVERIFY2(err.contains(QStringLiteral("no answer after 3 attempts; ")) &&
                 err.contains(QStringLiteral(" bytes of garbage came instead")),
             qPrintable(err));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestCliWire)

} // namespace tst_cliwire
#include "tst_cliwire.moc"
