// tipscope-cli joints: the joints the journal keeps, newest first, narrowed by time, device,
// port, tool, verdict and work order; as text lines, --json or --csv. It reads the journal
// another program (the GUI, a monitor) writes, and never writes it.
#include "clicommands.h"

#include "base/elide.h"
#include "journal/jointexport.h"
#include "journal/journal.h"
#include "journal/journalreader.h"

#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QRegularExpression>

namespace tipscope::cli {

using namespace tipscope::journal;

namespace {

struct CliJointsTr {
    Q_DECLARE_TR_FUNCTIONS(CliJoints)
};

// "24h", "30m", "7d", "90s" before now, or an ISO 8601 date or date and time (local time unless
// it names its zone).
base::Outcome<qint64> timeOf(const QString &text, qint64 nowMs) {
    static const QRegularExpression relative(QStringLiteral("^(\\d{1,6})([smhd])$"));
    if (const auto m = relative.match(text); m.hasMatch()) {
        static const QMap<QString, qint64> unitMs = {{QStringLiteral("s"), 1000},
                                                     {QStringLiteral("m"), 60'000},
                                                     {QStringLiteral("h"), 3'600'000},
                                                     {QStringLiteral("d"), 86'400'000}};
        return nowMs - m.captured(1).toLongLong() * unitMs.value(m.captured(2));
    }
    QDateTime t = QDateTime::fromString(text, Qt::ISODateWithMs);
    if (!t.isValid())
        t = QDateTime(QDate::fromString(text, Qt::ISODate), QTime(0, 0));
    if (!t.isValid())
        return base::failure(
            CliJointsTr::tr(
                "'%1' is not a time: write 24h, 30m, 7d, 2026-12-01 or 2026-12-01T08:00")
                .arg(base::elided(text)));
    return t.toMSecsSinceEpoch();
}

// The one device the journal knows that `text` names: its key, its model, its address or its
// line.
base::Outcome<QString> deviceKeyOf(const JournalReader &reader, const QString &text) {
    const auto devices = reader.devices();
    if (!devices)
        return base::failure(devices.error());
    QStringList keys;
    for (const model::DeviceIdentity &d : devices.value()) {
        const QString address =
            d.address ? QStringLiteral("%1").arg(*d.address, 2, 10, QLatin1Char('0')) : QString();
        if (d.key() == text)
            return d.key();
        if (d.model.compare(text, Qt::CaseInsensitive) == 0 || address == text || d.line == text)
            keys.append(d.key());
    }
    if (keys.size() == 1)
        return keys.first();
    if (keys.isEmpty())
        return base::failure(
            CliJointsTr::tr("the journal has no device '%1'").arg(base::elided(text)));
    return base::failure(CliJointsTr::tr("'%1' names %2 devices; give one of:\n  %3")
                             .arg(base::elided(text))
                             .arg(keys.size())
                             .arg(keys.join(QStringLiteral("\n  "))));
}

base::Outcome<JointFilter> filterOf(const CliOptions &o, const JournalReader &reader) {
    JointFilter f;
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    for (const auto &[name, bound] : {std::pair{QStringLiteral("since"), &f.sinceMs},
                                      std::pair{QStringLiteral("until"), &f.untilMs}}) {
        if (!o.values.contains(name))
            continue;
        const auto t = timeOf(o.values.value(name), now);
        if (!t)
            return base::failure(QStringLiteral("--%1: %2").arg(name, t.error()));
        *bound = t.value();
    }
    if (o.values.contains(QStringLiteral("device"))) {
        const auto key = deviceKeyOf(reader, o.values.value(QStringLiteral("device")));
        if (!key)
            return base::failure(QStringLiteral("--device: %1").arg(key.error()));
        f.deviceKey = key.value();
    }
    if (o.values.contains(QStringLiteral("port"))) {
        bool ok = false;
        const int port = o.values.value(QStringLiteral("port")).toInt(&ok);
        if (!ok || port < 1 || port > 4)
            return base::failure(CliJointsTr::tr("--port takes a port number from 1 to 4"));
        f.port = port;
    }
    if (o.values.contains(QStringLiteral("verdict"))) {
        const QString v =
            o.values.value(QStringLiteral("verdict")).replace(QLatin1Char('-'), QLatin1Char(' '));
        f.verdict = model::jointVerdictFromName(v);
        if (!f.verdict)
            return base::failure(
                CliJointsTr::tr("--verdict takes ok, slow-recovery, too-deep or incomplete"));
    }
    if (o.values.contains(QStringLiteral("tool")))
        f.tool = o.values.value(QStringLiteral("tool"));
    if (o.values.contains(QStringLiteral("work-order")))
        f.workOrder = o.values.value(QStringLiteral("work-order"));
    return f;
}

} // namespace

QString journalPathOf(const CliOptions &o) {
    return o.values.value(QStringLiteral("journal"), Journal::defaultPath());
}

static int exitCodeFor(JournalProblem problem) {
    switch (problem) {
    case JournalProblem::Missing:
        return kJournalMissing;
    case JournalProblem::Damaged:
    case JournalProblem::Foreign:
        return kJournalDamaged;
    case JournalProblem::Newer:
        return kJournalNewer;
    case JournalProblem::Locked:
        return kJournalLocked;
    case JournalProblem::Full:
    case JournalProblem::DiskError:
        return kJournalDisk;
    case JournalProblem::ReadOnly:
    case JournalProblem::Other:
    case JournalProblem::None:
        break;
    }
    return kJournalInaccessible;
}

int openJournalToReport(const CliOptions &o, JournalReader &reader, QTextStream &err) {
    auto ready = reader.open(journalPathOf(o));
    if (ready)
        ready = reader.check();
    if (ready)
        return kOk;
    err << "tipscope-cli: " << ready.error() << Qt::endl;
    return exitCodeFor(reader.problem());
}

int runJoints(const CliOptions &o, QTextStream &out, QTextStream &err) {
    const bool json = o.flags.contains(QStringLiteral("json"));
    const bool csv = o.flags.contains(QStringLiteral("csv"));
    if (json && csv) {
        err << CliJointsTr::tr("tipscope-cli: give --json or --csv, not both") << Qt::endl;
        return kUsage;
    }
    JournalReader reader;
    if (const int rc = openJournalToReport(o, reader, err); rc != kOk)
        return rc;
    const auto filter = filterOf(o, reader);
    if (!filter) {
        err << "tipscope-cli: " << filter.error() << Qt::endl;
        return kUsage;
    }
    const auto joints = reader.joints(filter.value());
    if (!joints) {
        err << "tipscope-cli: " << joints.error() << Qt::endl;
        return kTransport;
    }
    QList<StoredJoint> shown = joints.value();
    if (!o.lineName.isEmpty()) { // a workspace's line: the joints of its devices
        const QString line = link::lineIdentityName(o.line);
        shown.removeIf([&line](const StoredJoint &j) { return j.record.device.line != line; });
    }
    if (json) {
        QJsonArray array;
        for (const StoredJoint &j : shown)
            array.append(jointJson(j));
        out << QJsonDocument(array).toJson(QJsonDocument::Indented);
    } else if (csv) {
        out << jointCsvHeader() << '\n';
        for (const StoredJoint &j : shown)
            out << jointCsvRow(j) << '\n';
    } else {
        for (const StoredJoint &j : shown)
            out << jointTextLine(j) << '\n';
    }
    out.flush();
    return kOk;
}

} // namespace tipscope::cli
