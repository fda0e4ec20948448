// tipscope-cli context and limits: the work context stamped on every joint and event, and the
// joint limits, both kept in files every TipScope program shares. A running GUI or monitor
// follows the context file and journals the change; with none running, the next one to start
// does. Both print and read the same `name=value` lines, so a script can round-trip them.
#include "clicommands.h"

#include "base/elide.h"
#include "journal/workcontextfile.h"
#include "model/context/workcontextjson.h"
#include "model/joints/jointlimitsfile.h"

#include <QFile>

namespace tipscope::cli {

namespace {

struct CliContextTr {
    Q_DECLARE_TR_FUNCTIONS(CliContext)
};

const QString kWorkOrder = QStringLiteral("work_order");
const QString kSerial = QStringLiteral("board_serial");
const QString kOperator = QStringLiteral("operator");

void print(const model::WorkContext &c, QTextStream &out) {
    out << kWorkOrder << '=' << c.workOrder << '\n'
        << kSerial << '=' << c.boardSerial << '\n'
        << kOperator << '=' << c.operatorName << Qt::endl;
}

// Applies one `name=value` line read from standard input.
base::Outcome<void> applyLine(const QString &line, model::WorkContext &c) {
    const QString name = line.section(QLatin1Char('='), 0, 0).trimmed();
    const QString value = line.section(QLatin1Char('='), 1).trimmed();
    if (name == kWorkOrder)
        c.workOrder = value;
    else if (name == kSerial)
        c.boardSerial = value;
    else if (name == kOperator)
        c.operatorName = value;
    else
        return base::failure(
            CliContextTr::tr(
                "'%1' is not a context line: write work_order=W, board_serial=S or operator=O")
                .arg(base::elided(line)));
    return {};
}

base::Outcome<model::WorkContext> changed(const CliOptions &o, model::WorkContext c) {
    if (o.values.contains(QStringLiteral("work-order")))
        c.workOrder = o.values.value(QStringLiteral("work-order")).trimmed();
    if (o.values.contains(QStringLiteral("serial")))
        c.boardSerial = o.values.value(QStringLiteral("serial")).trimmed();
    if (o.values.contains(QStringLiteral("operator")))
        c.operatorName = o.values.value(QStringLiteral("operator")).trimmed();
    if (o.flags.contains(QStringLiteral("stdin"))) {
        QFile in;
        if (!in.open(stdin, QIODevice::ReadOnly | QIODevice::Text))
            return base::failure(CliContextTr::tr("cannot read standard input"));
        while (!in.atEnd()) {
            const QString line = QString::fromUtf8(in.readLine()).trimmed();
            if (line.isEmpty() || line.startsWith(QLatin1Char('#')))
                continue;
            if (const auto applied = applyLine(line, c); !applied)
                return base::failure(applied.error());
        }
    }
    return c;
}

} // namespace

int runContext(const CliOptions &o, QTextStream &out, QTextStream &err) {
    const QString action = o.args.value(0, QStringLiteral("show"));
    const QString path = journal::workContextPathFor(journalPathOf(o));
    const auto current = journal::readWorkContext(path);
    if (!current) {
        err << "tipscope-cli: " << current.error() << Qt::endl;
        return kUsage;
    }
    if (action == QLatin1String("show") && o.args.size() <= 1) {
        print(current.value(), out);
        return kOk;
    }
    model::WorkContext next;
    if (action == QLatin1String("set") && o.args.size() == 1) {
        const auto c = changed(o, current.value());
        if (!c) {
            err << "tipscope-cli: " << c.error() << Qt::endl;
            return kUsage;
        }
        next = c.value();
        if (const QString why = model::workContextProblem(next); !why.isEmpty()) {
            err << CliContextTr::tr("tipscope-cli: refused, nothing was changed: %1").arg(why)
                << Qt::endl;
            return kRefused;
        }
    } else if (action != QLatin1String("clear") || o.args.size() > 1) {
        err << CliContextTr::tr(
                   "tipscope-cli: context takes show, set [--work-order W] [--serial S] "
                   "[--operator O] [--stdin], or clear")
            << Qt::endl;
        return kUsage;
    }
    if (const auto saved = journal::writeWorkContext(path, next); !saved) {
        err << "tipscope-cli: " << saved.error() << Qt::endl;
        return kTransport;
    }
    print(next, out);
    return kOk;
}

int runLimits(const CliOptions &o, QTextStream &out, QTextStream &err) {
    const QString path = model::defaultJointLimitsPath();
    const auto loaded = model::loadJointLimits(path);
    if (!loaded) {
        err << "tipscope-cli: " << loaded.error() << Qt::endl;
        return kUsage;
    }
    model::JointLimitRules rules = loaded.value();
    const QString action = o.args.value(0, QStringLiteral("show"));
    if (action == QLatin1String("set") && o.args.size() == 2) {
        const auto rule = model::JointLimitRules::parseRule(o.args.at(1));
        if (!rule) {
            err << "tipscope-cli: " << rule.error() << Qt::endl;
            return kRefused;
        }
        rules.add(rule.value());
    } else if (action == QLatin1String("clear") && o.args.size() == 1) {
        rules = model::JointLimitRules(rules.defaults());
    } else if (action != QLatin1String("show") || o.args.size() > 1) {
        err << CliContextTr::tr("tipscope-cli: limits takes show, set RULE (such as "
                                "port=1,tool=C245,recovery=3.5,dip=60) or clear")
            << Qt::endl;
        return kUsage;
    }
    if (action != QLatin1String("show")) {
        if (const auto saved = model::saveJointLimits(path, rules); !saved) {
            err << "tipscope-cli: " << saved.error() << Qt::endl;
            return kTransport;
        }
    }
    const model::JointLimits &d = rules.defaults();
    const model::JointLimitRule defaults{std::nullopt, {}, d.maxRecoveryMs, d.maxDipK, d.wearShare};
    out << "default " << model::JointLimitRules::ruleText(defaults) << '\n';
    for (const model::JointLimitRule &rule : rules.rules())
        out << "rule " << model::JointLimitRules::ruleText(rule) << '\n';
    out.flush();
    return kOk;
}

} // namespace tipscope::cli
