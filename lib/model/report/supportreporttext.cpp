// The support report as people read it: the JSON of supportReportJson in plain text, in the
// language of the user, leaving out what is not known instead of printing it blank.
#include "supportreport.h"

#include "model/events/eventtext.h"

#include "protocol/catalogtext.h"

#include <QCoreApplication>
#include <QJsonArray>

namespace tipscope::model {

namespace {
struct SupportReportTr {
    Q_DECLARE_TR_FUNCTIONS(SupportReport)
};

// A report written before values had labels names them by the catalog's name alone.
QString label(const QJsonObject &value) {
    const QString label = value.value(QStringLiteral("label")).toString();
    return label.isEmpty() ? protocol::catalogText(value.value(QStringLiteral("name")).toString())
                           : label;
}

// "Device 01: DME-2C (DME), software 1.02"; what is not known is left out, not left blank.
QString deviceHeading(const QJsonObject &d) {
    const QString model = d.value(QStringLiteral("model")).toString();
    const QString family = d.value(QStringLiteral("family")).toString();
    const QString software = d.value(QStringLiteral("softwareVersion")).toString();
    QString heading =
        SupportReportTr::tr("Device %1").arg(d.value(QStringLiteral("address")).toString());
    if (!model.isEmpty() || !family.isEmpty())
        heading += QStringLiteral(": ") + (model.isEmpty() ? family
                                           : family.isEmpty() || family == model
                                               ? model
                                               : SupportReportTr::tr("%1 (%2)").arg(model, family));
    if (!software.isEmpty())
        heading += SupportReportTr::tr(", software %1").arg(software);
    return heading;
}

// "Joints from … to …:", then one line per port with its counts by verdict and its recovery times.
QString jointStatisticsText(const QJsonObject &joints) {
    if (joints.contains(QStringLiteral("error")))
        return SupportReportTr::tr("Joints of the last 24 hours: not read: %1")
            .arg(joints.value(QStringLiteral("error")).toString());
    QStringList out{SupportReportTr::tr("Joints from %1 to %2:")
                        .arg(joints.value(QStringLiteral("since")).toString(),
                             joints.value(QStringLiteral("until")).toString())};
    const QJsonArray ports = joints.value(QStringLiteral("ports")).toArray();
    if (ports.isEmpty())
        out << SupportReportTr::tr("  none");
    for (const QJsonValue &pv : ports) {
        const QJsonObject p = pv.toObject();
        const auto count = [&p](const QString &name) {
            return QString::number(p.value(name).toInteger());
        };
        QString line =
            SupportReportTr::tr("  %1, port %2: %3 joints: %4 ok, %5 slow recovery, %6 too deep, "
                                "%7 incomplete")
                .arg(p.value(QStringLiteral("device")).toString())
                .arg(p.value(QStringLiteral("port")).toInt())
                .arg(count(QStringLiteral("joints")), count(QStringLiteral("ok")),
                     count(QStringLiteral("slow recovery")), count(QStringLiteral("too deep")),
                     count(QStringLiteral("incomplete")));
        if (p.contains(QStringLiteral("recoveryMedianMs")))
            line += SupportReportTr::tr("; recovery median %1 ms, 95th percentile %2 ms")
                        .arg(count(QStringLiteral("recoveryMedianMs")),
                             count(QStringLiteral("recoveryP95Ms")));
        out << line;
    }
    return out.join(QLatin1Char('\n'));
}
// "Journal: PATH", whether it writes, what it holds, what it lost (journal/journalhealth.h).
QString journalHealthText(const QJsonObject &j) {
    const auto number = [&j](const QString &name) {
        return QString::number(j.value(name).toInteger());
    };
    const auto text = [&j](const QString &name) { return j.value(name).toString(); };
    QStringList out{SupportReportTr::tr("Journal: %1").arg(text(QStringLiteral("path")))};
    const QString state = text(QStringLiteral("state"));
    const QString writing = state == QLatin1String("ready")    ? SupportReportTr::tr("yes")
                            : state == QLatin1String("failed") ? SupportReportTr::tr("no")
                            : state == QLatin1String("opening")
                                ? SupportReportTr::tr("not yet, opening")
                                : SupportReportTr::tr("no, closed");
    const QString error = text(QStringLiteral("error"));
    out << (error.isEmpty() ? SupportReportTr::tr("  writing: %1").arg(writing)
                            : SupportReportTr::tr("  writing: %1: %2").arg(writing, error));
    if (j.value(QStringLiteral("lost")).toInteger() > 0)
        out << SupportReportTr::tr("  lost: %1 records (%2)")
                   .arg(number(QStringLiteral("lost")), text(QStringLiteral("lossReason")));
    if (j.contains(QStringLiteral("readError"))) {
        out << SupportReportTr::tr("  not read: %1").arg(text(QStringLiteral("readError")));
        return out.join(QLatin1Char('\n'));
    }
    out << SupportReportTr::tr("  %1 joints and %2 events, %3 and %4 of them not yet published; "
                               "%5 waiting in memory")
               .arg(number(QStringLiteral("joints")), number(QStringLiteral("events")),
                    number(QStringLiteral("unsentJoints")), number(QStringLiteral("unsentEvents")),
                    number(QStringLiteral("pending")));
    if (j.contains(QStringLiteral("oldest")))
        out << SupportReportTr::tr("  from %1 to %2")
                   .arg(text(QStringLiteral("oldest")), text(QStringLiteral("newest")));
    const qint64 days = j.value(QStringLiteral("retentionDays")).toInteger();
    out << (days == 0 ? SupportReportTr::tr("  kept without a time limit; %1 bytes on disk")
                            .arg(number(QStringLiteral("bytes")))
                      : SupportReportTr::tr("  kept for %1 days; %2 bytes on disk")
                            .arg(QString::number(days), number(QStringLiteral("bytes"))));
    return out.join(QLatin1Char('\n'));
}

// A line's link, statistics and devices, each value with its label and what to check.
void appendLine(QStringList &out, const QJsonObject &part) {
    const QJsonObject line = part.value(QStringLiteral("line")).toObject();
    out << SupportReportTr::tr("Line: %1").arg(line.value(QStringLiteral("transport")).toString())
        << SupportReportTr::tr("State: %1").arg(line.value(QStringLiteral("state")).toString())
        << SupportReportTr::tr("Statistics: %1")
               .arg(line.value(QStringLiteral("summary")).toString())
        << QString();
    for (const QJsonValue &dv : part.value(QStringLiteral("devices")).toArray()) {
        const QJsonObject d = dv.toObject();
        out << deviceHeading(d);
        for (const QJsonValue &vv : d.value(QStringLiteral("values")).toArray()) {
            const QJsonObject v = vv.toObject();
            // The JSON keeps the catalog's English name for machines; people read the label,
            // which names the tool and port of a per-tool or per-port setting.
            out << QStringLiteral("  %1 %2: %3")
                       .arg(v.value(QStringLiteral("code")).toString(), -4)
                       .arg(label(v), v.value(QStringLiteral("text")).toString());
        }
        const QJsonArray advice = d.value(QStringLiteral("whatToCheck")).toArray();
        if (!advice.isEmpty())
            out << SupportReportTr::tr("  What to check:");
        for (const QJsonValue &av : advice) {
            const QJsonObject a = av.toObject();
            out << QStringLiteral("    %1 (%2): %3")
                       .arg(a.value(QStringLiteral("label")).toString(),
                            a.value(QStringLiteral("error")).toString(),
                            a.value(QStringLiteral("check")).toString());
        }
        out << QString();
    }
}

void appendEvents(QStringList &out, const QJsonArray &events) {
    for (const QJsonValue &ev : events) {
        const QJsonObject e = ev.toObject();
        const QString text = repeatedEventText(e.value(QStringLiteral("text")).toString(),
                                               e.value(QStringLiteral("count")).toInt(1),
                                               e.value(QStringLiteral("lastTime")).toString());
        out << QStringLiteral("  %1 [%2] %3 %4: %5")
                   .arg(e.value(QStringLiteral("time")).toString(),
                        e.value(QStringLiteral("severity")).toString(),
                        e.value(QStringLiteral("kind")).toString(),
                        e.value(QStringLiteral("source")).toString(), text);
    }
}

// "Workspace line cell-3 (Cell 3, Hall B)": its names, those it has.
QString workspaceLineHeading(const QJsonObject &part) {
    QStringList where;
    for (const QString &key : {QStringLiteral("cell"), QStringLiteral("location")})
        if (const QString name = part.value(key).toString(); !name.isEmpty())
            where << name;
    const QString name = part.value(QStringLiteral("name")).toString();
    return where.isEmpty() ? SupportReportTr::tr("Workspace line %1").arg(name)
                           : SupportReportTr::tr("Workspace line %1 (%2)")
                                 .arg(name, where.join(QStringLiteral(", ")));
}
} // namespace

QString supportReportText(const QJsonObject &r) {
    QStringList out;
    out << SupportReportTr::tr("TipScope support report, %1")
               .arg(r.value(QStringLiteral("created")).toString())
        << SupportReportTr::tr("TipScope %1, Qt %2, %3")
               .arg(r.value(QStringLiteral("tipscopeVersion")).toString(),
                    r.value(QStringLiteral("qtVersion")).toString(),
                    r.value(QStringLiteral("system")).toString())
        << QString();
    const QJsonArray workspace = r.value(QStringLiteral("lines")).toArray();
    // Beside a workspace, the connection bar's line only when it was in use.
    if (workspace.isEmpty() || !r.value(QStringLiteral("line")).toObject().isEmpty() ||
        !r.value(QStringLiteral("devices")).toArray().isEmpty())
        appendLine(out, r);
    for (const QJsonValue &lv : workspace) {
        const QJsonObject part = lv.toObject();
        out << workspaceLineHeading(part);
        appendLine(out, part);
        out << SupportReportTr::tr("Recent events of %1:")
                   .arg(part.value(QStringLiteral("name")).toString());
        appendEvents(out, part.value(QStringLiteral("events")).toArray());
        out << QString();
    }
    if (r.contains(QStringLiteral("journal")))
        out << journalHealthText(r.value(QStringLiteral("journal")).toObject()) << QString();
    if (r.contains(QStringLiteral("joints")))
        out << jointStatisticsText(r.value(QStringLiteral("joints")).toObject()) << QString();
    out << SupportReportTr::tr("Recent events:");
    appendEvents(out, r.value(QStringLiteral("events")).toArray());
    return out.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

} // namespace tipscope::model
