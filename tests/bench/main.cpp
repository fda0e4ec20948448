// tipscope-bench: performance figures of TipScope against tipscope-sim.
//
// A dispatcher over subcommands: `tipscope-bench SUBCOMMAND [options]`. Each subcommand is a
// function taking the arguments after its name and returning the exit status; add one by adding
// a row to kSubcommands. Every run first prints the machine context (bench.* lines), then the
// subcommand's figures, one "name: value unit" per line.
#include "benchsupport.h"
#include "cfxbench.h"
#include "chartbench.h"
#include "fleetbench.h"
#include "fleetlivebench.h"
#include "guibench.h"
#include "jointbench.h"
#include "journalbench.h"
#include "linkbench.h"
#include "mqttbench.h"
#include "plantbench.h"
#include "replaybench.h"
#include "soakbench.h"

#include <QApplication>
#include <QTextStream>
#include <algorithm>
#include <memory>

namespace {

struct Subcommand {
    const char *name;
    const char *summary;
    int (*run)(const QStringList &args);
    // Builds widgets: runs under a QApplication, offscreen unless QT_QPA_PLATFORM names one.
    bool needsWidgets = false;
};

const Subcommand kSubcommands[] = {
    {"link", "link throughput, write latency under polling and detection time (--seconds N)",
     tipscope::bench::runLinkBench},
    {"soak", "fault-injection soak: writes with read-back under faults and unplugs (--minutes N)",
     tipscope::bench::runSoakBench},
    {"chart", "chart redraw over a day of 4 ports, naive chart, memory, GUI CPU (--seconds N)",
     tipscope::bench::runChartBench, true},
    {"gui",
     "each view of the window on a paced line making joints: transactions against the wire "
     "limit, CPU (--seconds N)",
     tipscope::bench::runGuiBench, true},
    {"journal", "journal inserts under polling, a year's file: size and queries (--rows N)",
     tipscope::bench::runJournalBench},
    {"joints",
     "joint detection: precision, recall, recovery error at two poll periods (--joints N, --noise "
     "K), or through the wire from the simulator, per shape set and front end (--wire --minutes "
     "M --sets demo,varied,slow --frontends core,core_fixed,cli,cli_5000,agent)",
     tipscope::bench::runJointBench},
    {"mqtt", "MQTT client: idle CPU and wake-ups, QoS 1 messages a second (--seconds N)",
     tipscope::bench::runMqttBench},
    {"replay", "reading recordings: speed and memory over file size (--mb N, --no-fifo)",
     tipscope::bench::runReplayBench},
    {"fleet-memory",
     "a day of 32 stations' telemetry at the demo's rates: tiered and single-tier memory "
     "(--seconds N, --hz R, --stations S, --hours H)",
     tipscope::bench::runFleetBench},
    {"fleet",
     "32 paced simulators in one workspace with the fleet overview shown: GUI CPU, transactions "
     "against the wire limit, tile latency, a day's memory (--stations N, --minutes M)",
     tipscope::bench::runFleetLiveBench, true},
    {"plant",
     "simulated stations, tipscope-agent and a Mosquitto broker: agent CPU, live latency, "
     "messages a second, a broker outage's backlog and its drain, joints lost (--stations N, "
     "--seconds S, --outage-s O)",
     tipscope::bench::runPlantBench},
    {"cfx",
     "simulated stations, tipscope-agent with IPC-CFX and a RabbitMQ node, boards changing: "
     "agent CPU with CFX on and off, latency to the consumer, an outage's drain, a SIGKILL, "
     "messages lost and duplicated (--stations N, --seconds S, --outage-s O, --board-s B)",
     tipscope::bench::runCfxBench},
};

void printUsage(QTextStream &s) {
    s << "usage: tipscope-bench SUBCOMMAND [options]   (SUBCOMMAND --help for its options)\n\n"
         "subcommands:\n";
    for (const Subcommand &c : kSubcommands)
        s << "  " << QString::fromLatin1(c.name).leftJustified(13) << c.summary << '\n';
    s.flush();
}

bool asksForHelp(const QStringList &args) {
    return args.contains(QStringLiteral("-h")) || args.contains(QStringLiteral("--help"));
}

} // namespace

int main(int argc, char *argv[]) {
    // Only the widget subcommands get a QApplication; the others need no display at all.
    const auto chosen =
        std::find_if(std::begin(kSubcommands), std::end(kSubcommands), [&](const Subcommand &c) {
            return argc > 1 && qstrcmp(argv[1], c.name) == 0;
        });
    const bool widgets = chosen != std::end(kSubcommands) && chosen->needsWidgets;
    if (widgets && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    const std::unique_ptr<QCoreApplication> application =
        widgets ? std::make_unique<QApplication>(argc, argv)
                : std::make_unique<QCoreApplication>(argc, argv);
    QCoreApplication &app = *application;
    QCoreApplication::setApplicationName(QStringLiteral("tipscope-bench"));
    // The bench lives beside tipscope-sim in bin/, not two folders below it like the tests.
    if (qEnvironmentVariableIsEmpty("TIPSCOPE_BIN_DIR"))
        qputenv("TIPSCOPE_BIN_DIR", QCoreApplication::applicationDirPath().toLocal8Bit());

    const QStringList args = app.arguments().mid(1);
    if (args.isEmpty() || args.first() == QLatin1String("-h") ||
        args.first() == QLatin1String("--help")) {
        QTextStream out(stdout);
        printUsage(out);
        return args.isEmpty() ? 1 : 0;
    }
    for (const Subcommand &c : kSubcommands) {
        if (args.first() != QLatin1String(c.name))
            continue;
        const QStringList rest = args.mid(1);
        if (!asksForHelp(rest))
            tipscope::bench::printMachineContext();
        return c.run(rest);
    }
    QTextStream err(stderr);
    err << "tipscope-bench: unknown subcommand '" << args.first() << "'\n";
    printUsage(err);
    return 1;
}
