// tipscope-bench refuses an option value it cannot measure with, before measuring anything: a
// negative size, a count below one, a number that is not finite. Before, `--mb -5`, `--joints -1`
// and `--noise nan` were clamped or taken without a word, and the figures printed under the
// value asked for were another value's.
#include "programrun.h"
#include "testmain.h"

#include <QTest>

namespace tst_badbench {

using namespace tipscope::testing;

class TestBadBench : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aValueOutOfRangeIsRefusedBeforeAnyFigure_data();
    void aValueOutOfRangeIsRefusedBeforeAnyFigure();
};

void TestBadBench::aValueOutOfRangeIsRefusedBeforeAnyFigure_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("said");
    QTest::newRow("replay --mb -5") << QStringList{"replay", "--mb", "-5"}
                                    << "--mb takes a whole number from 1 to 1000, not '-5'";
    QTest::newRow("joints --joints -1")
        << QStringList{"joints", "--joints", "-1"} << "--joints takes a whole number from 1 to";
    QTest::newRow("joints --noise nan") << QStringList{"joints", "--noise", "nan"}
                                        << "--noise takes a number from 0 to 50, not 'nan'";
    QTest::newRow("joints --noise without a value")
        << QStringList{"joints", "--noise"} << "--noise takes a number from 0 to 50, not ''";
    QTest::newRow("joints --wire --minutes 0")
        << QStringList{"joints", "--wire", "--minutes", "0"} << "--minutes takes a number from";
    QTest::newRow("joints --wire --per-minute inf")
        << QStringList{"joints", "--wire", "--per-minute", "inf"} << "--per-minute takes";
    QTest::newRow("fleet-memory --hz -1") << QStringList{"fleet-memory", "--hz", "-1"}
                                          << "--hz takes a number from 0 to 1000, not '-1'";
    QTest::newRow("fleet-memory --stations 1e9")
        << QStringList{"fleet-memory", "--stations", "1e9"} << "--stations takes a whole number";
    QTest::newRow("fleet --chunk-ms -3") << QStringList{"fleet", "--chunk-ms", "-3"}
                                         << "--chunk-ms takes a whole number from 0 to 1000";
    QTest::newRow("chart --seconds soon")
        << QStringList{"chart", "--seconds", "soon"} << "--seconds takes a whole number from 1 to";
}

void TestBadBench::aValueOutOfRangeIsRefusedBeforeAnyFigure() {
    QFETCH(QStringList, args);
    QFETCH(QString, said);
    const ProgramRun r = runProgram(QStringLiteral("tipscope-bench"), args, 60'000);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(said), qPrintable(r.err));
    // Only the machine context, which every run prints first; no figure of the subcommand.
    for (const QString &line : r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts))
        QVERIFY2(line.startsWith(QStringLiteral("bench.")), qPrintable(line));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestBadBench)

} // namespace tst_badbench
#include "tst_badbench.moc"
