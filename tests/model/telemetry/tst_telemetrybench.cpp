// The telemetry micro-benchmark runs to the end and prints its four figures in the
// "name: value unit" form tipscope-bench scripts grep for. Only the form is checked, never
// the figures: the machines running the tests are shared and noisy.
#include "model/telemetry/telemetrybench.h"
#include "testmain.h"

#include <QRegularExpression>
#include <QTest>
#include <QTextStream>

namespace tst_telemetrybench {

class TestTelemetryBench : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void benchPrintsItsFourFigures();
};

void TestTelemetryBench::benchPrintsItsFourFigures() {
    QString text;
    QTextStream out(&text);
    tipscope::bench::runTelemetryBench(out);

    const QStringList lines = text.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    const QStringList names = {QStringLiteral("telemetry.bytes_per_sample"),
                               QStringLiteral("telemetry.decimate_full_1920_ms"),
                               QStringLiteral("telemetry.decimate_1min_1920_ms"),
                               QStringLiteral("telemetry.append_ns")};
    const QStringList units = {QStringLiteral("bytes"), QStringLiteral("ms"), QStringLiteral("ms"),
                               QStringLiteral("ns")};
    QCOMPARE(lines.size(), names.size());
    for (int i = 0; i < names.size(); ++i) {
        const QRegularExpression form(QStringLiteral("^%1: ([0-9]+\\.[0-9]+) %2$")
                                          .arg(QRegularExpression::escape(names[i]), units[i]));
        const QRegularExpressionMatch match = form.match(lines[i]);
        QVERIFY2(match.hasMatch(), qPrintable(lines[i]));
    }
    // The one figure with a contract: the store's memory budget.
    const double bytes = lines[0].section(QLatin1Char(' '), 1, 1).toDouble();
    QVERIFY(bytes > 0 && bytes <= 16);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestTelemetryBench)

} // namespace tst_telemetrybench
#include "tst_telemetrybench.moc"
