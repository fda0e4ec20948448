#include "fleetbench.h"

#include "benchsupport.h"
#include "fleetday.h"

#include "model/appsettings.h"
#include "model/device/stationmodel.h"
#include "model/session.h"

#include <QElapsedTimer>
#include <QTextStream>

namespace tipscope::bench {

namespace {

// The demo line with every port shown, as the Charts page has it: samples per second of each
// channel over `seconds`, after the ports have heated up.
ChannelRates demoRates(int seconds) {
    model::Session session;
    model::AppSettings demo;
    demo.kind = model::AppSettings::Kind::Demo;
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
    const auto counts = [&session] { return channelSamples(session.telemetry()); };
    const auto before = counts();
    QElapsedTimer wall;
    wall.start();
    waitMs(seconds * 1000);
    const auto after = counts();
    const double elapsed = double(wall.elapsed()) / 1000;
    ChannelRates rates{};
    for (size_t c = 0; c < rates.size(); ++c)
        rates[c] = double(after[c] - before[c]) / elapsed;
    return rates;
}

} // namespace

int runFleetBench(const QStringList &args) {
    if (args.contains(QStringLiteral("--help")) || args.contains(QStringLiteral("-h"))) {
        QTextStream(stdout)
            << "Usage: tipscope-bench fleet-memory [--seconds N] [--hz R] [--stations S] "
               "[--hours H]\n"
               "A day (H hours, default 24) of S stations (default 32) of four ports and a "
               "feeder\n"
               "at the rates the demo line achieves (measured over N seconds, default 30; --hz "
               "R\n"
               "takes R for every channel): tiered memory, single-tier memory, decimation.\n";
        return 0;
    }
    const std::optional<qint64> secondsOption = wholeOption(args, "--seconds", 30, 1, 86'400);
    const std::optional<double> hzOption = numberOption(args, "--hz", 0, 0, 1000);
    const std::optional<qint64> stationsOption = wholeOption(args, "--stations", 32, 1, 1000);
    const std::optional<qint64> hoursOption = wholeOption(args, "--hours", 24, 1, 24 * 366);
    if (!secondsOption || !hzOption || !stationsOption || !hoursOption)
        return 2;
    const int seconds = int(*secondsOption);
    const double hz = *hzOption;
    const int stations = int(*stationsOption);
    const qint64 hours = *hoursOption;

    ChannelRates rates{};
    if (hz > 0)
        rates.fill(hz);
    else
        rates = demoRates(seconds);
    for (int c = 0; c <= kFleetPorts; ++c) {
        printFigure(QStringLiteral("fleet.demo_%1_hz").arg(fleetChannelName(c)), rates[size_t(c)],
                    QStringLiteral("Hz"), 2);
        if (rates[size_t(c)] <= 0) {
            printError(QStringLiteral("no samples from the demo's %1").arg(fleetChannelName(c)));
            return 1;
        }
    }

    printDayMemory(rates, stations, hours);
    return 0;
}

} // namespace tipscope::bench
