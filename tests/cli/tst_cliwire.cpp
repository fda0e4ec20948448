// tipscope-cli against a misbehaving device and a bad wire: the real binary and tipscope-sim over
// a socat PTY pair (or TCP). Every case ends with the exit status the manual promises and a
// message that says what happened.
#include "programrun.h"

#include <QtTest>

using namespace tipscope::testing;

namespace {

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
    QVERIFY2(!stats.endsWith(QStringLiteral("bad-data 0")), qPrintable(stats));
}

QTEST_GUILESS_MAIN(TestCliWire)
#include "tst_cliwire.moc"
