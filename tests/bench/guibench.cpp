#include "guibench.h"

#include "benchsupport.h"
#include "simstations.h"

#include "charts/chartspage.h"
#include "mainwindow.h"
#include "model/appsettings.h"
#include "pages/page.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QHash>
#include <QPaintEvent>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTextStream>
#include <algorithm>
#include <optional>

namespace tipscope::bench {

namespace {

constexpr int kConnectMs = 60000;
// Discovery and the first reading of every setting stay out of the figures.
constexpr int kWarmupMs = 8000;
// A view just shown asks for what it draws (a page's settings, the charts' history): the figures
// start once that has passed, so they say what the view costs while it stays on screen.
constexpr int kSettleMs = 3000;

struct View {
    QString name; // in the figures' names
    QString page; // the page's title
    std::optional<gui::ChartsPage::Layout> layout;
};

// Counts the paint events widgets get, by class, to see which view repaints what.
class PaintCounter : public QObject {
public:
    bool eventFilter(QObject *watched, QEvent *event) override {
        if (event->type() == QEvent::Paint && watched->isWidgetType()) {
            ++total;
            byClass[QString::fromLatin1(watched->metaObject()->className())] += 1;
            const QRect r = static_cast<QPaintEvent *>(event)->rect();
            pixels += qint64(r.width()) * r.height();
        }
        return false;
    }
    qint64 total = 0;
    qint64 pixels = 0;
    QHash<QString, qint64> byClass;
};

struct Counts {
    qint64 answered = 0;
    qint64 bytes = 0;
    qint64 timeouts = 0;
    qint64 cpuUs = 0;
};

Counts countsOf(gui::MainWindow &window) {
    const link::LinkStats &stats = window.session().line()->queue().stats();
    return {stats.answered, stats.sentBytes + stats.receivedBytes, stats.timeouts, selfCpuUs()};
}

} // namespace

int runGuiBench(const QStringList &args) {
    if (args.contains(QStringLiteral("--help")) || args.contains(QStringLiteral("-h"))) {
        QTextStream(stdout)
            << "Usage: tipscope-bench gui [--seconds N] [--views NAME,...]\n"
               "A simulated DME on a TCP line paced at 19200 baud, making joints on every port,\n"
               "in the main window at 1280x720; each page, and the Charts page overlaid and one\n"
               "pane per port, shown for N seconds (default 20): the line's transactions against\n"
               "what its wire carries, and the window's CPU. --views measures only those named,\n"
               "in that order (overview, settings, counters, errors, console, charts_overlaid,\n"
               "charts_per_port, joints).\n";
        return 0;
    }
    const std::optional<qint64> secondsOption = wholeOption(args, "--seconds", 20, 1, 3600);
    if (!secondsOption)
        return 2;
    const int seconds = int(*secondsOption);
    // Test mode: the bench's window must not read or overwrite the user's settings.
    QStandardPaths::setTestModeEnabled(true);
    std::vector<SimStation> sims = startSimStations(1, [](int) {
        return QStringList{QStringLiteral("--model"),
                           QStringLiteral("DME"),
                           QStringLiteral("--tcp"),
                           QStringLiteral("127.0.0.1:0"),
                           QStringLiteral("--pace"),
                           QString::number(kPaceBaud),
                           QStringLiteral("--joints-per-minute"),
                           QStringLiteral("12"),
                           QStringLiteral("--joint-shapes"),
                           QStringLiteral("varied")};
    });
    if (sims.empty())
        return 1;
    gui::MainWindow window;
    window.resize(1280, 720);
    window.show();
    model::AppSettings line;
    line.kind = model::AppSettings::Kind::Tcp;
    line.tcpAddress = sims.front().address;
    window.connectWith(line);
    if (!runUntil([&] { return window.session().state() == model::Session::State::Connected; },
                  kConnectMs)) {
        printError(QStringLiteral("the simulated line at %1 did not connect").arg(line.tcpAddress));
        return 1;
    }
    waitMs(kWarmupMs);

    using Layout = gui::ChartsPage::Layout;
    const QList<View> views = {
        {QStringLiteral("overview"), QStringLiteral("Overview"), {}},
        {QStringLiteral("settings"), QStringLiteral("Settings"), {}},
        {QStringLiteral("counters"), QStringLiteral("Counters"), {}},
        {QStringLiteral("errors"), QStringLiteral("Errors"), {}},
        {QStringLiteral("console"), QStringLiteral("Console"), {}},
        {QStringLiteral("charts_overlaid"), QStringLiteral("Charts"), Layout::Overlaid},
        {QStringLiteral("charts_per_port"), QStringLiteral("Charts"), Layout::PerPort},
        {QStringLiteral("joints"), QStringLiteral("Joints"), {}},
    };
    const QStringList only =
        optionValue(args, "--views", QString()).split(QLatin1Char(','), Qt::SkipEmptyParts);
    for (const QString &name : only)
        if (std::none_of(views.begin(), views.end(),
                         [&](const View &v) { return v.name == name; })) {
            printError(QStringLiteral("--views: no view \"%1\"").arg(name));
            return 2;
        }
    // In the order asked for: a view's cost may depend on what was shown before it.
    QList<View> chosen = views;
    if (!only.isEmpty()) {
        chosen.clear();
        for (const QString &name : only)
            chosen.append(*std::find_if(views.begin(), views.end(),
                                        [&](const View &v) { return v.name == name; }));
    }
    PaintCounter paints;
    qApp->installEventFilter(&paints);
    double worst = 1;
    for (const View &view : std::as_const(chosen)) {
        gui::Page *page = window.page(view.page);
        if (!page) {
            printError(QStringLiteral("the window has no page \"%1\"").arg(view.page));
            return 1;
        }
        if (view.layout)
            if (auto *charts = qobject_cast<gui::ChartsPage *>(page))
                charts->setPaneLayout(*view.layout);
        window.pages().setCurrentWidget(page);
        waitMs(kSettleMs);
        const Counts before = countsOf(window);
        paints.total = paints.pixels = 0;
        paints.byClass.clear();
        QElapsedTimer wall;
        wall.start();
        waitMs(seconds * 1000);
        const Counts after = countsOf(window);
        const double elapsedS = double(wall.nsecsElapsed()) / 1e9;
        const qint64 answered = after.answered - before.answered;
        const qint64 bytes = after.bytes - before.bytes;
        const double rate = double(answered) / elapsedS;
        const double limit = pacedWireLimitTxPerS(answered, bytes);
        const double ratio = limit > 0 ? rate / limit : 0;
        worst = std::min(worst, ratio);
        const QString prefix = QStringLiteral("gui.%1.").arg(view.name);
        printFigure(prefix + QStringLiteral("tx_per_s"), rate, QStringLiteral("tx/s"));
        printFigure(prefix + QStringLiteral("wire_limit_tx_per_s"), limit, QStringLiteral("tx/s"));
        printFigure(prefix + QStringLiteral("rate_ratio"), ratio, QString(), 3);
        printFigure(prefix + QStringLiteral("cpu_percent"),
                    double(after.cpuUs - before.cpuUs) / (elapsedS * 1e6) * 100,
                    QStringLiteral("% of one core"));
        printFigure(prefix + QStringLiteral("timeouts"), double(after.timeouts - before.timeouts),
                    QString(), 0);
        printFigure(prefix + QStringLiteral("paints_per_s"), double(paints.total) / elapsedS,
                    QStringLiteral("/s"));
        printFigure(prefix + QStringLiteral("painted_mpx_per_s"),
                    double(paints.pixels) / elapsedS / 1e6, QStringLiteral("Mpx/s"), 2);
        QList<QPair<qint64, QString>> top;
        for (auto it = paints.byClass.cbegin(); it != paints.byClass.cend(); ++it)
            top.append({it.value(), it.key()});
        std::sort(top.begin(), top.end(), std::greater<>());
        QStringList most;
        for (qsizetype i = 0; i < top.size() && i < 5; ++i)
            most.append(QStringLiteral("%1 %2/s")
                            .arg(top.at(i).second)
                            .arg(double(top.at(i).first) / elapsedS, 0, 'f', 1));
        printNote(QStringLiteral("%1: paints %2").arg(view.name, most.join(QStringLiteral(", "))));
    }
    printFigure(QStringLiteral("gui.worst_rate_ratio"), worst, QString(), 3);
    return 0;
}

} // namespace tipscope::bench
