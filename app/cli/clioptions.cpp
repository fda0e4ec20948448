#include "clioptions.h"

#include "base/elide.h"
#include "link/ports/devicepath.h"
#include "link/tcptransport.h"

namespace tipscope::cli {

namespace {

const QStringList kCommands = {
    QStringLiteral("detect"),   QStringLiteral("read"),    QStringLiteral("write"),
    QStringLiteral("send"),     QStringLiteral("monitor"), QStringLiteral("dump"),
    QStringLiteral("commands"), QStringLiteral("profile"), QStringLiteral("record"),
    QStringLiteral("measure"),  QStringLiteral("joints"),  QStringLiteral("context"),
    QStringLiteral("limits"),   QStringLiteral("journal"), QStringLiteral("board")};
// Commands that read or write files only, and need no device.
const QStringList kOffline = {QStringLiteral("commands"), QStringLiteral("measure"),
                              QStringLiteral("joints"),   QStringLiteral("context"),
                              QStringLiteral("limits"),   QStringLiteral("journal"),
                              QStringLiteral("board")};
// Command options that take a value; all others are flags.
const QStringList kValueOptions = {
    QStringLiteral("interval"),     QStringLiteral("duration"),   QStringLiteral("csv"),
    QStringLiteral("family"),       QStringLiteral("since"),      QStringLiteral("until"),
    QStringLiteral("device"),       QStringLiteral("port"),       QStringLiteral("verdict"),
    QStringLiteral("tool"),         QStringLiteral("work-order"), QStringLiteral("serial"),
    QStringLiteral("operator"),     QStringLiteral("journal"),    QStringLiteral("limit"),
    QStringLiteral("mqtt"),         QStringLiteral("mqtt-user"),  QStringLiteral("site"),
    QStringLiteral("cfx"),          QStringLiteral("cfx-user"),   QStringLiteral("cfx-address"),
    QStringLiteral("cfx-requests"), QStringLiteral("pdf")};

// `monitor --csv FILE` names a file; `joints --csv` and `board --csv` a format.
bool takesValue(const QString &command, const QString &option) {
    const bool csvFormat = command == QLatin1String("joints") || command == QLatin1String("board");
    return kValueOptions.contains(option) && !(csvFormat && option == QLatin1String("csv"));
}
const QMap<QString, QStringList> kCommandOptions = {
    {QStringLiteral("detect"), {QStringLiteral("json"), QStringLiteral("scan")}},
    {QStringLiteral("read"), {QStringLiteral("raw")}},
    {QStringLiteral("write"), {QStringLiteral("raw"), QStringLiteral("force")}},
    {QStringLiteral("send"), {}},
    {QStringLiteral("monitor"),
     {QStringLiteral("interval"), QStringLiteral("duration"), QStringLiteral("csv"),
      QStringLiteral("csv-one-file"), QStringLiteral("journal"), QStringLiteral("limit"),
      QStringLiteral("mqtt"), QStringLiteral("mqtt-user"), QStringLiteral("site"),
      QStringLiteral("cfx"), QStringLiteral("cfx-user"), QStringLiteral("cfx-address"),
      QStringLiteral("cfx-requests")}},
    {QStringLiteral("dump"), {QStringLiteral("json")}},
    {QStringLiteral("commands"), {QStringLiteral("family")}},
    {QStringLiteral("profile"), {QStringLiteral("force"), QStringLiteral("dry-run")}},
    {QStringLiteral("record"), {QStringLiteral("duration")}},
    {QStringLiteral("measure"), {QStringLiteral("json")}},
    {QStringLiteral("joints"),
     {QStringLiteral("since"), QStringLiteral("until"), QStringLiteral("device"),
      QStringLiteral("port"), QStringLiteral("verdict"), QStringLiteral("tool"),
      QStringLiteral("work-order"), QStringLiteral("json"), QStringLiteral("csv"),
      QStringLiteral("journal")}},
    {QStringLiteral("context"),
     {QStringLiteral("work-order"), QStringLiteral("serial"), QStringLiteral("operator"),
      QStringLiteral("stdin"), QStringLiteral("journal")}},
    {QStringLiteral("limits"), {}},
    {QStringLiteral("journal"), {QStringLiteral("json"), QStringLiteral("journal")}},
    {QStringLiteral("board"),
     {QStringLiteral("json"), QStringLiteral("csv"), QStringLiteral("pdf"),
      QStringLiteral("journal")}},
};

// What runs on every line of a workspace.
const QStringList kWorkspaceCommands = {QStringLiteral("detect"), QStringLiteral("monitor"),
                                        QStringLiteral("dump"), QStringLiteral("joints")};

bool parseInt(const QString &text, int lo, int hi, int *out) {
    bool ok = false;
    const int v = text.toInt(&ok);
    if (!ok || v < lo || v > hi)
        return false;
    *out = v;
    return true;
}

} // namespace

QString CliParser::usage() {
    return tr(
        "Usage: tipscope-cli [--port DEVICE | --tcp HOST:PORT | --demo | --demo-activity |\n"
        "                     --workspace FILE] [--baud N]\n"
        "                    [--parity none|even|odd] [--stop-bits 1|2] [--addr SRC:TGT | "
        "--no-addr]\n"
        "                    [--timeout MS] [--retries N] [--verbose] COMMAND ...\n"
        "\n"
        "Commands:\n"
        "  detect [--json] [--scan]  one line per device: \"<address or --> <model> <family> "
        "<version>\"\n"
        "  read CODE... [--raw]      one line per code: \"<CODE> <value> <unit>\"\n"
        "  write CODE VALUE [--raw [--force]]\n"
        "                            validate (MIT and MAT read first), send, and read back;\n"
        "                            --raw sends the data field, checked unless --force\n"
        "  send HEX                  send a raw frame; print the answer in hex and decoded\n"
        "  monitor [--interval MS] [--duration S] [--csv FILE [--csv-one-file]]\n"
        "          [--limit RULE] [--journal FILE]\n"
        "                            tip temperature, setpoint, power and status per port, and\n"
        "                            a line per joint, each joint kept in the journal\n"
        "  monitor --mqtt HOST:PORT [--mqtt-user U] [--site S] [--interval MS] [--duration S]\n"
        "                            publish the lines to an MQTT broker as tipscope-agent does\n"
        "                            (docs/mqtt.md); the password from TIPSCOPE_MQTT_PASSWORD\n"
        "  monitor --cfx amqp[s]://HOST:PORT [--cfx-user U] [--cfx-address ADDRESS]\n"
        "          [--cfx-requests /queue/NAME]\n"
        "                            every station as an IPC-CFX endpoint (docs/cfx.md), beside\n"
        "                            --mqtt or alone; the password from TIPSCOPE_CFX_PASSWORD\n"
        "  dump [--json]             every readable parameter, counter and error\n"
        "  commands [--family F]     the command catalog\n"
        "  profile save FILE         every writable setting of the device to a JSON profile\n"
        "  profile diff FILE         what applying the profile would change\n"
        "  profile apply FILE [--dry-run] [--force]\n"
        "                            write what differs, each value read back; --dry-run lists\n"
        "                            the frames; --force applies a profile of another family\n"
        "  record FILE [--duration S]\n"
        "                            every port's and the feeder's curves and events to a chart\n"
        "                            recording, as the Charts page records them\n"
        "  measure FILE [--json]     the heat-ups and recoveries of a recording, one line each\n"
        "  joints [--since T] [--until T] [--device D] [--port N] [--tool T]\n"
        "         [--verdict V] [--work-order W] [--json | --csv] [--journal FILE]\n"
        "                            the joints the journal keeps, newest first; T is 24h, 30m,\n"
        "                            7d or an ISO date and time; V is ok, slow-recovery,\n"
        "                            too-deep or incomplete\n"
        "  context [show | clear | set [--work-order W] [--serial S] [--operator O] [--stdin]]\n"
        "                            the work context stamped on every joint and event\n"
        "  limits [show | clear | set RULE]\n"
        "                            the joint limits; RULE is port=N,tool=T,recovery=S,dip=K,\n"
        "                            wear=SHARE (any of them; the most specific rule wins)\n"
        "  journal [show [--json] | retention DAYS] [--journal FILE]\n"
        "                            what the journal holds, and how many days it keeps\n"
        "                            records (0: all); every TipScope program shares it\n"
        "  board SERIAL [--json | --csv | --pdf FILE] [--journal FILE]\n"
        "                            one board's record: every joint stamped with the board\n"
        "                            serial, its tools' wear, the events while it was made;\n"
        "                            --csv its joints as joints --csv; --pdf a document to sign\n"
        "\n"
        "Without --addr or --no-addr the device is found automatically. --demo talks to the\n"
        "built-in simulated DME station (address 01) and SFR feeder (address 10);\n"
        "--demo-activity the same at work: joints on port 1 every 15 s, rests on port 2, feeds.\n"
        "--timeout is the device turnaround added to the wire time of each request.\n"
        "--workspace runs the command on every line of a workspace file at once, each output\n"
        "line prefixed with the line's name; monitor --csv writes a file per line.\n"
        "\n"
        "Exit codes: 0 ok; 1 usage, or a board serial the journal does not hold; 2 value\n"
        "refused before sending (nothing was written); 3 the device answered NAK, or a\n"
        "read-back or profile check failed; 4 no valid answer; 5 transport error; the journal\n"
        "(joints, board, journal show): 6 missing, 7 damaged, 8 newer, 9 locked, 10 not\n"
        "accessible, 11 disk full or failing.\n");
}

base::Outcome<CliOptions> CliParser::parse(const QStringList &arguments) {
    CliOptions o;
    o.line.serial.portName.clear();
    bool haveTransport = false;
    for (qsizetype i = 1; i < arguments.size(); ++i) {
        const QString a = arguments.at(i);
        const bool isOption = a.startsWith(QLatin1String("--")) && a.size() > 2;
        if (!isOption) {
            if (o.command.isEmpty()) {
                if (!kCommands.contains(a))
                    return base::failure(tr("unknown command '%1'").arg(base::elided(a)));
                o.command = a;
            } else {
                o.args.append(a);
            }
            continue;
        }
        QString name = a.mid(2);
        QString inlineValue;
        const bool hasInline = name.contains(QLatin1Char('='));
        if (hasInline) {
            inlineValue = name.section(QLatin1Char('='), 1);
            name = name.section(QLatin1Char('='), 0, 0);
        }
        auto takeValue = [&](QString *out) {
            if (hasInline) {
                *out = inlineValue;
                return true;
            }
            if (i + 1 >= arguments.size())
                return false;
            *out = arguments.at(++i);
            return true;
        };
        QString v;
        // A command's own options first: `joints --port 1` names a port, not the line.
        if (!o.command.isEmpty() && kCommandOptions.value(o.command).contains(name)) {
            if (takesValue(o.command, name)) {
                if (!takeValue(&v))
                    return base::failure(tr("--%1 needs a value").arg(name));
                o.values.insert(name, v);
            } else {
                if (hasInline)
                    return base::failure(tr("--%1 takes no value").arg(name));
                o.flags.append(name);
            }
        } else if (name == QLatin1String("help")) {
            o.showHelp = true;
        } else if (name == QLatin1String("version")) {
            o.showVersion = true;
        } else if (name == QLatin1String("verbose")) {
            o.verbose = true;
        } else if (name == QLatin1String("demo") || name == QLatin1String("demo-activity")) {
            if (haveTransport)
                return base::failure(tr("give only one of --port, --tcp and --demo"));
            haveTransport = o.demo = true;
            o.demoActivity = name == QLatin1String("demo-activity");
            o.line.kind = link::LineSettings::Kind::Demo;
        } else if (name == QLatin1String("workspace")) {
            if (haveTransport || !takeValue(&v) || v.isEmpty())
                return base::failure(tr("--workspace takes a file, and only one of --port, "
                                        "--tcp, --demo, --workspace"));
            haveTransport = true;
            o.workspace = v;
        } else if (name == QLatin1String("port")) {
            if (haveTransport || !takeValue(&v) || v.isEmpty())
                return base::failure(
                    tr("--port takes a device, and only one of --port, --tcp, --demo"));
            haveTransport = true;
            o.line.kind = link::LineSettings::Kind::Serial;
            o.line.serial.portName = link::typedPortName(v);
        } else if (name == QLatin1String("tcp")) {
            if (haveTransport || !takeValue(&v) ||
                !link::TcpTransport::parseHostPort(v, &o.line.tcpHost, &o.line.tcpPort))
                return base::failure(
                    tr("--tcp takes HOST:PORT, and only one of --port, --tcp, --demo"));
            haveTransport = true;
            o.line.kind = link::LineSettings::Kind::Tcp;
        } else if (name == QLatin1String("baud")) {
            if (!takeValue(&v) || !parseInt(v, 50, 4'000'000, &o.line.serial.baudRate))
                return base::failure(tr("--baud takes a rate such as 19200"));
        } else if (name == QLatin1String("parity")) {
            static const QMap<QString, QSerialPort::Parity> parities = {
                {QStringLiteral("none"), QSerialPort::NoParity},
                {QStringLiteral("even"), QSerialPort::EvenParity},
                {QStringLiteral("odd"), QSerialPort::OddParity}};
            if (!takeValue(&v) || !parities.contains(v))
                return base::failure(tr("--parity takes none, even or odd"));
            o.line.serial.parity = parities.value(v);
        } else if (name == QLatin1String("stop-bits")) {
            if (!takeValue(&v) || (v != QLatin1String("1") && v != QLatin1String("2")))
                return base::failure(tr("--stop-bits takes 1 or 2"));
            o.line.serial.stopBits =
                v == QLatin1String("2") ? QSerialPort::TwoStop : QSerialPort::OneStop;
        } else if (name == QLatin1String("addr")) {
            int src = 0, tgt = 0;
            if (!takeValue(&v) || !parseInt(v.section(QLatin1Char(':'), 0, 0), 0, 99, &src) ||
                !parseInt(v.section(QLatin1Char(':'), 1), 0, 99, &tgt) ||
                v.count(QLatin1Char(':')) != 1)
                return base::failure(
                    tr("--addr takes SRC:TGT, two addresses from 00 to 99 (e.g. 00:01)"));
            o.addressing = CliOptions::Addressing::With;
            o.line.queue.robotAddress = src;
            o.targetAddress = tgt;
        } else if (name == QLatin1String("no-addr")) {
            o.addressing = CliOptions::Addressing::Without;
        } else if (name == QLatin1String("timeout")) {
            if (!takeValue(&v) || !parseInt(v, 1, 60'000, &o.line.queue.turnaroundMs))
                return base::failure(tr("--timeout takes milliseconds from 1 to 60000"));
        } else if (name == QLatin1String("retries")) {
            if (!takeValue(&v) || !parseInt(v, 0, 10, &o.line.queue.retries))
                return base::failure(tr("--retries takes a number from 0 to 10"));
        } else {
            const QString shown = base::elided(name);
            return base::failure(o.command.isEmpty()
                                     ? tr("unknown option --%1").arg(shown)
                                     : tr("'%1' has no option --%2").arg(o.command, shown));
        }
    }
    if (o.showHelp || o.showVersion)
        return o;
    if (o.command.isEmpty())
        return base::failure(tr("no command given"));
    if (!o.workspace.isEmpty() && !kWorkspaceCommands.contains(o.command))
        return base::failure(
            tr("--workspace runs detect, monitor, dump or joints, not %1").arg(o.command));
    if (o.flags.contains(QStringLiteral("csv-one-file")) &&
        (o.workspace.isEmpty() || !o.values.contains(QStringLiteral("csv"))))
        return base::failure(tr("--csv-one-file goes with --workspace and --csv FILE"));
    if (!haveTransport && !kOffline.contains(o.command))
        return base::failure(
            tr("say where the device is: --port DEVICE, --tcp HOST:PORT or --demo"));
    return o;
}

} // namespace tipscope::cli
