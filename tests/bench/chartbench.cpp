#include "chartbench.h"

#include "benchsupport.h"
#include "naivechart.h"

#include "charts/chartspage.h"
#include "charts/chartwidget.h"
#include "mainwindow.h"
#include "model/appsettings.h"
#include "model/chart/chartframe.h"
#include "model/device/stationmodel.h"
#include "model/session.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTextStream>
#include <QTimer>
#include <algorithm>
#include <memory>

namespace tipscope::bench {

namespace {

using gui::ChartWidget;
using model::ChartAxis;
using model::ChartChannel;
using model::ChartTrace;
using model::Telemetry;

constexpr int kPorts = 4;
constexpr int kSamples = model::TelemetryBuffer::kDefaultCapacity; // a day at 10 Hz
constexpr int kPlotWidth = 1920;
constexpr int kRuns = 9;
constexpr qint64 kStartMs = 1'700'000'000'000;
constexpr qint64 kStepMs = 100;
constexpr qint64 kDayMs = kSamples * kStepMs;

// Peak resident set (VmHWM) in MB, from /proc/self/status; 0 if unreadable.
double peakRssMb() {
    QFile f(QStringLiteral("/proc/self/status"));
    if (!f.open(QIODevice::ReadOnly | QIODevice::Text))
        return 0;
    for (QByteArray line = f.readLine(); !line.isEmpty(); line = f.readLine())
        if (line.startsWith("VmHWM:"))
            return line.mid(6).trimmed().split(' ').first().toDouble() / 1024;
    return 0;
}

// The series of a live port buffer (Session's).
const QStringList kSeries = {QStringLiteral("tip"),        QStringLiteral("setpoint"),
                             QStringLiteral("power"),      QStringLiteral("status"),
                             QStringLiteral("transistor"), QStringLiteral("transformer")};

// A working day: heat-up, noise, a dip now and then under load, so extremes are not trivial.
// The hardware temperatures follow the power, read every 2 s as the status values are.
void fill(Telemetry &telemetry, QList<ChartChannel> &channels) {
    const QStringList &series = kSeries;
    for (int p = 1; p <= kPorts; ++p) {
        ChartChannel c;
        c.key = QStringLiteral("01/port%1").arg(p);
        c.id = QStringLiteral("port%1").arg(p);
        c.port = p;
        c.series = series;
        // One tier: the day at full rate, so the figures stay comparable with earlier runs
        // (tipscope-bench fleet-memory measures the tiered buffers).
        telemetry.ensureBuffer(c.key, series, kSamples);
        channels.append(c);
    }
    quint32 random = 1;
    QList<qint32> tips(kPorts, 25);
    QList<qint32> transistors(kPorts, 30);
    qint32 transformer = 35;
    for (int i = 0; i < kSamples; ++i) {
        const bool statusRead = i % 20 == 0;
        qint32 totalPower = 0;
        for (int p = 0; p < kPorts; ++p) {
            random = random * 1664525u + 1013904223u;
            qint32 &tip = tips[p];
            tip = std::min(350, tip + 5) + int((random >> 28) % 5) - 2;
            if ((random >> 8) % 1000 == 0)
                tip -= 40;
            const qint32 power = std::clamp((350 - tip) * 40, 0, 1000);
            totalPower += power;
            if (statusRead)
                transistors[p] = 30 + power * 3 / 100;
            telemetry.append(channels.at(p).key, kStartMs + i * kStepMs,
                             {tip, 350, power, tip < 340 ? 1 : 0, transistors.at(p), transformer});
        }
        if (statusRead)
            transformer = 35 + totalPower / 100;
    }
}

// Counts the paints of the chart's surface, so an update is timed with exactly one paint.
class PaintCounter : public QObject {
public:
    int paints = 0;

protected:
    bool eventFilter(QObject *watched, QEvent *event) override {
        if (event->type() == QEvent::Paint)
            ++paints;
        return QObject::eventFilter(watched, event);
    }
};

struct ChartRig {
    ChartWidget widget;
    PaintCounter counter;

    explicit ChartRig(const QList<ChartTrace> &traces) {
        QList<gui::ChartSeriesStyle> styles;
        for (const ChartTrace &t : traces)
            styles.append({t.name, t.color, t.style, t.format.axis});
        widget.setSeries(styles);
        widget.setAxisTitle(ChartAxis::Left, QStringLiteral("Temperature (°C)"));
        widget.setAxisTitle(ChartAxis::Right, QStringLiteral("Power (%)"));
        widget.resize(kPlotWidth + 200, 700);
        widget.show();
        widget.plotSurface()->installEventFilter(&counter);
        widget.setTimeRange(kStartMs, kStartMs + kDayMs);
        // The plot is what is 1920 px wide, not the widget: grow it until it is.
        for (int i = 0; i < 5 && widget.plotWidth() != kPlotWidth; ++i) {
            QCoreApplication::processEvents();
            widget.resize(widget.width() + kPlotWidth - widget.plotWidth(), widget.height());
            QCoreApplication::processEvents();
        }
    }

    // Points in, layout, and one full paint: what the screen needs before it shows the update.
    // `shownMs` receives the time when the chart had the points, before the paint.
    double show(const QList<QList<QPointF>> &points, qint64 t0, qint64 t1, QElapsedTimer &timer,
                double *shownMs = nullptr) {
        counter.paints = 0;
        widget.showData(gui::ChartData{t0, t1, 0, 400, 0, 100, points});
        if (shownMs)
            *shownMs = double(timer.nsecsElapsed()) / 1e6;
        QCoreApplication::processEvents(); // layout, and the paint of the update on screen
        if (counter.paints == 0)
            widget.plotSurface()->repaint();
        return double(timer.nsecsElapsed()) / 1e6;
    }
};

// Median of kRuns decimated updates of [t0, t1); each run moves the window by a millisecond so
// nothing is skipped as unchanged.
struct UpdateTimes {
    double totalMs = 0;
    double decimateMs = 0; // the part spent asking the telemetry
    double seriesMs = 0;   // handing the points to the chart
    double paintMs = 0;    // layout and paint
    qint64 points = 0;
};

UpdateTimes medianUpdate(ChartRig &rig, const Telemetry &telemetry, const QList<ChartChannel> &cs,
                         const QList<ChartTrace> &traces, qint64 t0, qint64 t1) {
    QList<double> totals, decimations, handovers, paints;
    UpdateTimes result;
    for (int run = 0; run <= kRuns; ++run) {
        QElapsedTimer timer;
        timer.start();
        const model::ChartFrame frame =
            model::buildFrame(telemetry, cs, traces, t0 - run, t1 - run, rig.widget.plotWidth());
        const double decimated = double(timer.nsecsElapsed()) / 1e6;
        double shown = 0;
        const double ms = rig.show(frame.points, t0 - run, t1 - run, timer, &shown);
        if (run > 0) { // the first run warms caches and fonts
            totals.append(ms);
            decimations.append(decimated);
            handovers.append(shown - decimated);
            paints.append(ms - shown);
        }
        result.points = frame.pointCount;
    }
    result.totalMs = quantile(totals, 0.5);
    result.decimateMs = quantile(decimations, 0.5);
    result.seriesMs = quantile(handovers, 0.5);
    result.paintMs = quantile(paints, 0.5);
    return result;
}

// The same day handed to the naive chart, every sample of every series.
double naiveUpdateMs(const Telemetry &telemetry, const QList<ChartChannel> &cs,
                     const QList<ChartTrace> &traces, int width, int height) {
    QList<NaiveSeries> series;
    for (const ChartTrace &t : traces)
        series.append({t.name, t.color, t.style, t.format.axis == ChartAxis::Right});
    NaiveChart chart(series, width, height);
    QElapsedTimer timer; // reading the samples out is part of the naive way, as decimating is ours
    timer.start();
    QList<QList<QPointF>> points;
    for (const ChartTrace &t : traces) {
        const model::TelemetryBuffer *b = telemetry.buffer(cs.at(t.channel).key);
        QList<QPointF> all;
        all.reserve(b->size());
        for (const auto &s : b->samples(b->seriesIndex(t.series), kStartMs, kStartMs + kDayMs))
            all.append(QPointF(double(s.timeMs), t.format.toDisplay(s.value)));
        points.append(all);
    }
    const double gathered = double(timer.nsecsElapsed()) / 1e6;
    return gathered + chart.showMs(points, kStartMs, kStartMs + kDayMs);
}

// CPU share of this process, in percent of one core, over `seconds` with `page` shown.
double cpuPercent(gui::MainWindow &window, gui::Page *page, int seconds) {
    window.pages().setCurrentWidget(page);
    waitMs(3000); // the poll rates follow the page; let them settle
    const qint64 cpu = selfCpuUs();
    QElapsedTimer wall;
    wall.start();
    waitMs(seconds * 1000);
    return double(selfCpuUs() - cpu) / (double(wall.nsecsElapsed()) / 1e3) * 100;
}

// The demo line, its models and the chart's telemetry without any window: the share of the
// GUI's CPU that no widget can save (the in-process simulator, the link, the parameters).
double sessionCpuPercent(int seconds) {
    model::Session session;
    const model::AppSettings demo = [] {
        model::AppSettings a;
        a.kind = model::AppSettings::Kind::Demo;
        return a;
    }();
    session.scheduler().setInterval(model::PollClass::Live, demo.liveMs);
    session.scheduler().setInterval(model::PollClass::Status, demo.statusMs);
    session.scheduler().setInterval(model::PollClass::Counter, demo.counterMs);
    QObject::connect(&session, &model::Session::devicesChanged, &session, [&session] {
        for (model::DeviceModel *d : session.devices())
            if (qobject_cast<model::StationModel *>(d))
                session.scheduler().setVisiblePorts(d, {1, 2, 3, 4});
    });
    session.connectTo(*demo.sessionSettings());
    for (int i = 0; i < 300 && session.state() != model::Session::State::Connected; ++i)
        waitMs(100);
    waitMs(6000); // discovery, the first reading of every setting, the ports heating up
    const qint64 cpu = selfCpuUs();
    QElapsedTimer wall;
    wall.start();
    waitMs(seconds * 1000);
    return double(selfCpuUs() - cpu) / (double(wall.nsecsElapsed()) / 1e3) * 100;
}

int runGuiCpu(int seconds, bool baseline) {
    // Test mode: the bench's main window must not read or overwrite the user's settings.
    QStandardPaths::setTestModeEnabled(true);
    if (baseline)
        printFigure(QStringLiteral("gui.session_cpu_percent"), sessionCpuPercent(seconds),
                    QStringLiteral("%"), 2);
    gui::MainWindow window;
    window.resize(1360, 860);
    window.show();
    model::AppSettings demo;
    demo.kind = model::AppSettings::Kind::Demo;
    window.connectWith(demo);
    for (int i = 0; i < 300 && window.session().state() != model::Session::State::Connected; ++i)
        waitMs(100);
    auto *charts = qobject_cast<gui::ChartsPage *>(window.page(QStringLiteral("Charts")));
    gui::Page *overview = window.page(QStringLiteral("Overview"));
    if (window.session().state() != model::Session::State::Connected || !charts || !overview) {
        printError(QStringLiteral("the demo line did not connect, or a page is missing"));
        return 1;
    }
    waitMs(3000); // the ports heat up
    // The demo's simulator, line and models run in this process too: the Overview page, which
    // also polls all four ports, is the baseline the chart adds to.
    const double base = baseline ? cpuPercent(window, overview, seconds) : 0;
    const qint64 redraws = charts->redrawCount();
    const qint64 answered = window.session().line()->queue().stats().answered;
    QElapsedTimer wall;
    wall.start();
    const double withChart = cpuPercent(window, charts, seconds);
    const double elapsedS = double(wall.elapsed()) / 1e3;
    printFigure(QStringLiteral("gui.cpu_percent"), withChart, QStringLiteral("%"), 2);
    if (baseline) {
        printFigure(QStringLiteral("gui.cpu_overview_percent"), base, QStringLiteral("%"), 2);
        printFigure(QStringLiteral("gui.chart_cpu_percent"), withChart - base, QStringLiteral("%"),
                    2);
    }
    printFigure(QStringLiteral("gui.redraws_per_s"),
                double(charts->redrawCount() - redraws) / elapsedS, QStringLiteral("/s"));
    printFigure(QStringLiteral("gui.transactions_per_s"),
                double(window.session().line()->queue().stats().answered - answered) / elapsedS,
                QStringLiteral("/s"));
    return 0;
}

} // namespace

int runChartBench(const QStringList &args) {
    if (args.contains(QStringLiteral("--help")) || args.contains(QStringLiteral("-h"))) {
        QTextStream(stdout)
            << "Usage: tipscope-bench chart [--seconds N] [--no-gui | --gui-only | "
               "--session-only]\n"
               "                            [--no-baseline]\n"
               "                            [--no-naive] [--png-day FILE] [--png FILE]\n"
               "Chart redraw over a day of 4 ports at 1920 px, the naive chart, memory, and the\n"
               "GUI's CPU share with the demo line live (each CPU run N seconds, default 60).\n"
               "--png-day and --png save the chart of the day and of the minute as images.\n";
        return 0;
    }
    const auto option = [&args](const char *name, const QString &fallback) {
        return optionValue(args, name, fallback);
    };
    const std::optional<qint64> secondsOption = wholeOption(args, "--seconds", 60, 1, 86'400);
    if (!secondsOption)
        return 2;
    const int seconds = int(*secondsOption);
    const bool baseline = !args.contains(QStringLiteral("--no-baseline"));
    if (args.contains(QStringLiteral("--session-only"))) {
        printFigure(QStringLiteral("gui.session_cpu_percent"), sessionCpuPercent(seconds),
                    QStringLiteral("%"), 2);
        return 0;
    }
    if (args.contains(QStringLiteral("--gui-only")))
        return runGuiCpu(seconds, baseline);
    printFigure(QStringLiteral("memory.peak_rss_start_mb"), peakRssMb(), QStringLiteral("MB"));
    {
        Telemetry telemetry;
        QList<ChartChannel> channels;
        fill(telemetry, channels);
        qint64 bytes = 0;
        for (const ChartChannel &c : std::as_const(channels))
            bytes += telemetry.buffer(c.key)->memoryBytes();
        printFigure(QStringLiteral("telemetry.bytes_per_sample"),
                    double(bytes) / (double(kSamples) * kPorts * double(kSeries.size())),
                    QStringLiteral("B"), 2);
        printFigure(QStringLiteral("telemetry.memory_mb"), double(bytes) / (1 << 20),
                    QStringLiteral("MB"));
        printFigure(QStringLiteral("memory.peak_rss_telemetry_mb"), peakRssMb(),
                    QStringLiteral("MB"));

        const QList<ChartTrace> traces =
            model::tracesFor(channels, {0, 1, 2, 3}, model::TemperatureUnit::Celsius);
        double full = 0;
        int width = 0;
        int height = 0;
        {
            ChartRig rig(traces);
            width = rig.widget.width();
            height = rig.widget.height();
            printFigure(QStringLiteral("chart.plot_width_px"), rig.widget.plotWidth(),
                        QStringLiteral("px"), 0);
            const UpdateTimes day =
                medianUpdate(rig, telemetry, channels, traces, kStartMs, kStartMs + kDayMs);
            full = day.totalMs;
            printFigure(QStringLiteral("chart.redraw_full_ms"), day.totalMs, QStringLiteral("ms"),
                        2);
            printFigure(QStringLiteral("chart.decimate_full_ms"), day.decimateMs,
                        QStringLiteral("ms"), 2);
            printFigure(QStringLiteral("chart.series_full_ms"), day.seriesMs, QStringLiteral("ms"),
                        2);
            printFigure(QStringLiteral("chart.paint_full_ms"), day.paintMs, QStringLiteral("ms"),
                        2);
            printFigure(QStringLiteral("chart.points_full"), double(day.points),
                        QStringLiteral("points"), 0);
            if (const QString png = option("--png-day", QString()); !png.isEmpty())
                rig.widget.toImage().save(png);
            const qint64 middle = kStartMs + kDayMs / 2;
            const UpdateTimes minute =
                medianUpdate(rig, telemetry, channels, traces, middle, middle + 60'000);
            if (const QString png = option("--png", QString()); !png.isEmpty())
                rig.widget.toImage().save(png); // the last update: a minute of the day
            printFigure(QStringLiteral("chart.redraw_1min_ms"), minute.totalMs,
                        QStringLiteral("ms"), 2);
            printFigure(QStringLiteral("chart.decimate_1min_ms"), minute.decimateMs,
                        QStringLiteral("ms"), 2);
            printFigure(QStringLiteral("memory.peak_rss_chart_mb"), peakRssMb(),
                        QStringLiteral("MB"));
        }
        if (!args.contains(QStringLiteral("--no-naive"))) {
            printNote(QStringLiteral("naive chart: %1 points, this takes a while")
                          .arg(qint64(kSamples) * traces.size()));
            const double naive = naiveUpdateMs(telemetry, channels, traces, width, height);
            printFigure(QStringLiteral("chart.naive_redraw_full_ms"), naive, QStringLiteral("ms"));
            printFigure(QStringLiteral("chart.speedup"), naive / full, QStringLiteral("x"));
            printFigure(QStringLiteral("memory.peak_rss_naive_mb"), peakRssMb(),
                        QStringLiteral("MB"));
        }
    }
    if (args.contains(QStringLiteral("--no-gui")))
        return 0;
    return runGuiCpu(seconds, baseline);
}

} // namespace tipscope::bench
