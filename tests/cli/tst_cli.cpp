// tipscope-cli end to end: the real binary, a socat PTY pair, and tipscope-sim on the other end.
#include "programrun.h"
#include "testmain.h"

#include <QFile>
#include <QRegularExpression>
#include <QTest>

namespace tst_cli {

using namespace tipscope::testing;

namespace {

using Run = ProgramRun;

Run runCli(const QStringList &args, int timeoutMs = 30000, const QString &folder = {}) {
    QProcess p;
    p.setWorkingDirectory(folder);
    p.start(binaryPath(QStringLiteral("tipscope-cli")), args);
    return finishProcess(p, timeoutMs);
}

} // namespace

class TestCli : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void detectFindsAddressedStationAndFeederOnOneLine();
    void detectFindsAStationWithoutAddresses();
    void readPrintsValuesWithUnits();
    void writeIsReadBackAndTheSimulatorHoldsTheValue();
    void negativeValuesAndCommandOptionsAfterTheCommandParse();
    void feederLengthsAndSpeedsAreInMillimetres();
    void refusedValueNeverReachesTheWire();
    void nakIsExitThreeWithTheCodesMeaning();
    void garbageBeforeAnswersIsSkipped();
    void corruptedAnswersAreRetried();
    void silentDeviceIsExitFour();
    void nonexistentPortIsExitFiveWithAReason();
    void aPortPathWithASlashIsTakenFromTheCurrentFolder();
    void sendPrintsTheAnswerInHexAndDecoded();
    void monitorSurvivesAnUnplugAndResumesSayingSoOnce();
    void usageErrorsAreExitOne();
    void profileSavesDiffsAndAppliesWithReadBack();

private:
    // Starts the simulator on one end of a fresh socat pair; returns the host end.
    QString startSim(const QStringList &simArgs);
    std::unique_ptr<SocatPair> m_pair;
    std::unique_ptr<SimProcess> m_sim;
};

QString TestCli::startSim(const QStringList &simArgs) {
    m_sim.reset();
    m_pair = std::make_unique<SocatPair>();
    QString error;
    if (!m_pair->start(&error))
        return {};
    m_sim = std::make_unique<SimProcess>();
    if (m_sim->start(simArgs + QStringList{QStringLiteral("--device"), m_pair->deviceEnd()}, &error)
            .isEmpty())
        return {};
    return m_pair->hostEnd();
}

void TestCli::detectFindsAddressedStationAndFeederOnOneLine() {
    const QString port = startSim({"--model", "DDE", "--feeder"});
    QVERIFY(!port.isEmpty());
    const Run r = runCli({"--port", port, "detect"});
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(r.out, QStringLiteral("01 DDE-2C DDE 9996780\n10 SFR-A SFR -\n"));
    const Run j = runCli({"--port", port, "detect", "--json"});
    QCOMPARE(j.exitCode, 0);
    QVERIFY(j.out.contains(QStringLiteral("\"family\": \"SFR\"")));
}

void TestCli::detectFindsAStationWithoutAddresses() {
    const QString port = startSim({"--model", "DDR"});
    QVERIFY(!port.isEmpty());
    const Run r = runCli({"--port", port, "detect"});
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(r.out, QStringLiteral("-- DDR DDR -\n"));
}

void TestCli::readPrintsValuesWithUnits() {
    const QString port = startSim({"--model", "DME", "--feeder"});
    QVERIFY(!port.isEmpty());
    const Run r = runCli({"--port", port, "read", "ST2", "HD1", "D12", "CT1", "LEN", "SMN"});
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(r.out.split('\n'), QStringList({"ST2 350 °C", "HD1 disabled", "D12 0 min",
                                             "CT1 1 T210", "LEN 20.0 mm", "SMN DME-2C", ""}));
    const Run raw = runCli({"--port", port, "--addr", "00:01", "read", "--raw", "ST2"});
    QCOMPARE(raw.out, QStringLiteral("ST2 00350\n"));
}

void TestCli::writeIsReadBackAndTheSimulatorHoldsTheValue() {
    const QString port = startSim({"--model", "DME"});
    QVERIFY(!port.isEmpty());
    const Run w = runCli({"--port", port, "write", "ST3", "400"});
    QCOMPARE(w.exitCode, 0);
    QCOMPARE(w.out, QStringLiteral("ST3 400 °C (verified)\n"));
    const Run r = runCli({"--port", port, "--addr", "00:01", "read", "--raw", "ST3"});
    QCOMPARE(r.out, QStringLiteral("ST3 00400\n"));
    QVERIFY(m_sim->command("stats").contains(QStringLiteral("writes 1 ")));
    const Run d = runCli({"--port", port, "write", "HD2", "1.6"});
    QCOMPARE(d.exitCode, 0);
    QCOMPARE(d.out, QStringLiteral("HD2 1.60 s (verified)\n"));
}

void TestCli::negativeValuesAndCommandOptionsAfterTheCommandParse() {
    const QString port = startSim({"--model", "DME", "--feeder"});
    QVERIFY(!port.isEmpty());
    const Run a = runCli({"--port", port, "write", "A12", "-50"});
    QCOMPARE(a.exitCode, 0);
    QCOMPARE(a.out, QStringLiteral("A12 -50 °C (verified)\n"));
    const Run len = runCli({"--port", port, "write", "LEN", "--raw", "00150"});
    QCOMPARE(len.exitCode, 0);
    QCOMPARE(len.out, QStringLiteral("LEN 15.0 mm (verified)\n"));
}

// Lengths and speeds read and are written in mm and mm/s, as the GUI shows them; the wire still
// carries tenths of a millimetre, and a value finer than that is refused, not rounded.
void TestCli::feederLengthsAndSpeedsAreInMillimetres() {
    const QString port = startSim({"--model", "DME", "--feeder"});
    QVERIFY(!port.isEmpty());
    const Run r = runCli({"--port", port, "read", "LEN", "SPD", "FDL"});
    QCOMPARE(r.exitCode, 0);
    const QStringList lines = r.out.split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 3);
    QVERIFY2(lines.at(0) == QStringLiteral("LEN 20.0 mm"), qPrintable(r.out));
    QVERIFY2(
        QRegularExpression(QStringLiteral("^SPD \\d+\\.\\d mm/s$")).match(lines.at(1)).hasMatch(),
        qPrintable(r.out));
    QVERIFY2(
        QRegularExpression(QStringLiteral("^FDL \\d+\\.\\d mm$")).match(lines.at(2)).hasMatch(),
        qPrintable(r.out));
    for (const QStringList &typed : {QStringList{"LEN", "12.5"}, QStringList{"LEN", "12.5mm"}}) {
        const Run w = runCli(QStringList{"--port", port, "write"} + typed);
        QCOMPARE(w.exitCode, 0);
        QCOMPARE(w.out, QStringLiteral("LEN 12.5 mm (verified)\n"));
    }
    QCOMPARE(runCli({"--port", port, "--addr", "00:10", "read", "--raw", "LEN"}).out,
             QStringLiteral("LEN 00125\n"));
    const Run speed = runCli({"--port", port, "write", "SPD", "7.5"});
    QCOMPARE(speed.exitCode, 0);
    QCOMPARE(speed.out, QStringLiteral("SPD 7.5 mm/s (verified)\n"));
    const Run finer = runCli({"--port", port, "write", "LEN", "12.55"});
    QCOMPARE(finer.exitCode, 2);
    QVERIFY2(finer.err.contains(QStringLiteral("nothing was sent")), qPrintable(finer.err));
    QCOMPARE(runCli({"--port", port, "--addr", "00:10", "read", "--raw", "LEN"}).out,
             QStringLiteral("LEN 00125\n"));
}

void TestCli::refusedValueNeverReachesTheWire() {
    const QString port = startSim({"--model", "DME"});
    QVERIFY(!port.isEmpty());
    for (const QStringList &bad :
         {QStringList{"ST1", "353"}, QStringList{"ST1", "505"}, QStringList{"A12", "51"},
          QStringList{"H12", "7"}, QStringList{"D12", "hot"}, QStringList{"TT1", "100"},
          QStringList{"PS1", "2"}, QStringList{"HD1", "1.234"}}) {
        const Run r = runCli(QStringList{"--port", port, "write"} + bad);
        QVERIFY2(r.exitCode == 2, qPrintable(bad.join(' ') + ": " + r.err));
        QVERIFY2(r.err.contains(QStringLiteral("nothing was sent")) ||
                     r.err.contains(QStringLiteral("accepts writes")),
                 qPrintable(r.err));
    }
    const QString stats = m_sim->command("stats");
    QVERIFY2(stats.contains(QStringLiteral("writes 0 ")), qPrintable(stats));
}

void TestCli::nakIsExitThreeWithTheCodesMeaning() {
    const QString port = startSim({"--model", "DME", "--nak", "4"});
    QVERIFY(!port.isEmpty());
    const Run r = runCli({"--port", port, "--addr", "00:01", "read", "ST1"});
    QCOMPARE(r.exitCode, 3);
    QVERIFY2(r.err.contains(QStringLiteral("NAK 00004")) && r.err.contains("Control error"),
             qPrintable(r.err));
}

void TestCli::garbageBeforeAnswersIsSkipped() {
    const QString port = startSim({"--model", "DME", "--garbage", "1"});
    QVERIFY(!port.isEmpty());
    const Run r = runCli({"--port", port, "read", "ST1", "ST2", "ST3"});
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(r.out.count(QStringLiteral("350 °C")), 3);
}

void TestCli::corruptedAnswersAreRetried() {
    const QString port = startSim({"--model", "DME", "--corrupt", "0.4", "--seed", "3"});
    QVERIFY(!port.isEmpty());
    const Run r = runCli({"--port", port, "--addr", "00:01", "--retries", "8", "--verbose", "read",
                          "ST1", "ST2", "ST3", "ST4"});
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(r.out.count(QStringLiteral("350 °C")), 4);
    QVERIFY2(r.err.count(QStringLiteral("TX ")) > 4, "expected at least one retry");
}

void TestCli::silentDeviceIsExitFour() {
    const QString port = startSim({"--model", "DME", "--drop", "1"});
    QVERIFY(!port.isEmpty());
    const Run r = runCli({"--port", port, "--addr", "00:01", "--timeout", "50", "read", "ST1"});
    QCOMPARE(r.exitCode, 4);
    const Run d = runCli({"--port", port, "--timeout", "50", "detect"});
    QCOMPARE(d.exitCode, 4);
    QVERIFY(d.err.contains(QStringLiteral("no device answered")));
}

void TestCli::nonexistentPortIsExitFiveWithAReason() {
    const Run r = runCli({"--port", "/dev/tipscope-no-such-port", "read", "ST1"});
    QCOMPARE(r.exitCode, 5);
    QVERIFY2(r.err.contains(QStringLiteral("no such port"), Qt::CaseInsensitive),
             qPrintable(r.err));
}

void TestCli::aPortPathWithASlashIsTakenFromTheCurrentFolder() {
    // Qt alone would look for "pair/host" under /dev; a person means the path from here.
    const QString port = startSim({"--model", "DME"});
    QVERIFY(!port.isEmpty());
    const QFileInfo host(port);
    const QString relative = host.dir().dirName() + QStringLiteral("/host");
    const QString folder = QFileInfo(host.dir().path()).path();
    // What is checked is where the port is found, not how fast the simulator answers: the
    // device gets a second, as a loaded machine's simulator may need.
    const Run r = runCli({"--port", relative, "--timeout", "1000", "read", "ST1"}, 30000, folder);
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QCOMPARE(r.out, QStringLiteral("ST1 350 °C\n"));
    const Run missing = runCli({"--port", "no-such-folder/ttyX", "read", "ST1"}, 30000, folder);
    QCOMPARE(missing.exitCode, 5);
    QVERIFY2(missing.err.contains(QStringLiteral("./no-such-folder/ttyX")) &&
                 !missing.err.contains(QStringLiteral("/dev/no-such-folder")),
             qPrintable(missing.err));
}

void TestCli::sendPrintsTheAnswerInHexAndDecoded() {
    const QString port = startSim({"--model", "DME"});
    QVERIFY(!port.isEmpty());
    const Run r = runCli({"--port", port, "send", "02 30 30 30 31 52 53 4D 4E 03 02"});
    QCOMPARE(r.exitCode, 0);
    QVERIFY2(r.out.contains(QStringLiteral("RX 02 30 31 30 30 41 53 4D 4E")) &&
                 r.out.contains(QStringLiteral("01→00 A SMN DME-2C")),
             qPrintable(r.out));
    const Run bad = runCli({"--port", port, "send", "02 3G"});
    QCOMPARE(bad.exitCode, 2);
}

void TestCli::monitorSurvivesAnUnplugAndResumesSayingSoOnce() {
    QTemporaryDir dir;
    const QString link = dir.filePath(QStringLiteral("station"));
    SimProcess sim;
    QString error;
    QVERIFY2(!sim.start({"--model", "DME", "--pty", "--link", link}, &error).isEmpty(),
             qPrintable(error));
    QProcess cli;
    // A timeout a loaded machine meets: at 50 ms, five answers in a row came late beside a
    // sanitizer build, and the line was rightly said lost a second time.
    cli.start(binaryPath(QStringLiteral("tipscope-cli")),
              {"--port", link, "--addr", "00:01", "--timeout", "250", "monitor", "--interval",
               "200", "--duration", "9"});
    QVERIFY(cli.waitForStarted());
    QByteArray outBytes;
    QByteArray errBytes;
    const auto read = [&] {
        outBytes += cli.readAllStandardOutput();
        errBytes += cli.readAllStandardError();
    };
    // Unplugged once the monitor prints values (the cable is there when it starts: else it is
    // exit 5, as for a port that does not exist), plugged again once it said it retries.
    QTRY_VERIFY2_WITH_TIMEOUT((read(), outBytes.contains("/350")), qPrintable(errBytes), 8000);
    QCOMPARE(sim.command(QStringLiteral("unplug")), QStringLiteral("ok"));
    QTRY_VERIFY2_WITH_TIMEOUT((read(), errBytes.contains("retrying")), qPrintable(errBytes), 8000);
    QVERIFY(sim.command(QStringLiteral("plug")).startsWith(QStringLiteral("/dev/pts/")));
    QVERIFY(cli.waitForFinished(20000));
    read();
    const QString out = QString::fromUtf8(outBytes);
    const QString err = QString::fromUtf8(errBytes);
    QVERIFY2(cli.exitCode() == 0, qPrintable(err));
    QVERIFY2(err.contains(QStringLiteral("retrying")), qPrintable(err));
    // Said once each, not at every retry.
    QVERIFY2(err.count(QStringLiteral("# disconnected")) == 1, qPrintable(err));
    QVERIFY2(err.count(QStringLiteral("# reconnected to ")) == 1, qPrintable(err));
    const QStringList lines = out.split('\n', Qt::SkipEmptyParts);
    QVERIFY(lines.size() > 10);
    QVERIFY2(lines.last().contains(QStringLiteral("/350 °C")), qPrintable(lines.last()));
    QVERIFY2(out.contains(QStringLiteral("P1 --")),
             "expected cycles without answers while unplugged");
}

void TestCli::usageErrorsAreExitOne() {
    QCOMPARE(runCli({"--demo", "frobnicate"}).exitCode, 1);
    QCOMPARE(runCli({"--demo", "read", "--json"}).exitCode, 1);
    QCOMPARE(runCli({"--port", "a", "--tcp", "b:1", "read", "ST1"}).exitCode, 1);
    QCOMPARE(runCli({"--addr", "00:100", "--demo", "read", "ST1"}).exitCode, 1);
    QCOMPARE(runCli({"read", "ST1"}).exitCode, 1);
    const Run v = runCli({"--version"});
    QCOMPARE(v.exitCode, 0);
    QVERIFY(v.out.startsWith(QStringLiteral("tipscope-cli ")));
    QVERIFY(runCli({"--help"}).out.contains(QStringLiteral("Exit codes")));
}

void TestCli::profileSavesDiffsAndAppliesWithReadBack() {
    const QString port = startSim({"--model", "DDR"});
    QVERIFY(!port.isEmpty());
    // Each command reads every setting (about 150): on a loaded test machine one of them can miss
    // the default turnaround three times, which is not what this test is about.
    const auto runCli = [](const QStringList &args) {
        return tst_cli::runCli(QStringList{"--timeout", "1000", "--retries", "5"} + args);
    };
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("ddr.json"));
    const Run saved = runCli({"--port", port, "profile", "save", file});
    QCOMPARE(saved.exitCode, 0);
    QVERIFY2(saved.out.contains(QStringLiteral("saved")), qPrintable(saved.out + saved.err));
    QCOMPARE(runCli({"--port", port, "write", "PLM", "800"}).exitCode, 0);
    QCOMPARE(runCli({"--port", port, "write", "A22", "-5"}).exitCode, 0);
    const Run diff = runCli({"--port", port, "profile", "diff", file});
    QCOMPARE(diff.exitCode, 0);
    QVERIFY2(diff.out.contains(QStringLiteral("2 differences")), qPrintable(diff.out));
    const Run dry = runCli({"--port", port, "profile", "apply", "--dry-run", file});
    QVERIFY2(dry.out.contains(QStringLiteral("would send 02 57 50 4C 4D 30 31 30 30 30")),
             qPrintable(dry.out + dry.err));
    const Run applied = runCli({"--port", port, "profile", "apply", file});
    QCOMPARE(applied.exitCode, 0);
    QVERIFY2(applied.out.contains(QStringLiteral("2 changed")), qPrintable(applied.out));
    const Run again = runCli({"--port", port, "profile", "diff", file});
    QVERIFY2(again.out.contains(QStringLiteral("0 differences")),
             qPrintable(again.out + again.err));

    QFile bad(dir.filePath(QStringLiteral("bad.json")));
    QVERIFY(bad.open(QIODevice::WriteOnly));
    bad.write(
        R"({"format":"tipscope-profile","schema":1,"family":"DDR","values":{"PLM":"01001"}})");
    bad.close();
    const QString before = m_sim->command("stats");
    const Run refused = runCli({"--port", port, "profile", "apply", bad.fileName()});
    QCOMPARE(refused.exitCode, 2);
    QVERIFY2(refused.err.contains(QStringLiteral("PLM")), qPrintable(refused.err));
    const QString after = m_sim->command("stats");
    QCOMPARE(after.section(QStringLiteral("writes "), 1).section(' ', 0, 0),
             before.section(QStringLiteral("writes "), 1).section(' ', 0, 0));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestCli)

} // namespace tst_cli
#include "tst_cli.moc"
