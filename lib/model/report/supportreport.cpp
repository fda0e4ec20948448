// The support report as JSON, and written to files with its text beside it.
#include "supportreport.h"

#include "base/atomicsave.h"
#include "base/timetext.h"
#include "model/device/settingname.h"
#include "model/session.h"

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QMetaEnum>
#include <QSysInfo>

namespace tipscope::model {

namespace {
// Ports in the order a person reads them: the device's own (0) first.
QList<int> errorPorts(const DeviceModel &d) {
    QList<int> ports{0};
    if (const auto *station = qobject_cast<const StationModel *>(&d))
        for (const PortModel *port : station->ports())
            ports.append(port->number());
    return ports;
}

QJsonObject deviceJson(const DeviceModel &d) {
    QJsonArray advice;
    for (int port : errorPorts(d)) {
        const QString text = d.errorAdvice(port);
        const Parameter *error = d.parameter(protocol::Role::Error, port);
        if (!text.isEmpty() && error)
            advice.append(QJsonObject{{QStringLiteral("code"), QString::fromLatin1(error->code())},
                                      {QStringLiteral("label"), settingName(*error)},
                                      {QStringLiteral("error"), error->displayText()},
                                      {QStringLiteral("check"), text}});
    }
    QJsonArray values;
    for (const Parameter *p : d.parameters()) {
        if (!p->value())
            continue;
        values.append(
            QJsonObject{{QStringLiteral("code"), QString::fromLatin1(p->code())},
                        {QStringLiteral("name"), p->meta().name},
                        {QStringLiteral("label"), settingName(*p)},
                        {QStringLiteral("group"), protocol::groupName(p->meta().group)},
                        {QStringLiteral("data"), QString::fromLatin1(p->rawValue())},
                        {QStringLiteral("text"), p->displayText()},
                        {QStringLiteral("state"),
                         QString::fromLatin1(
                             QMetaEnum::fromType<Parameter::State>().valueToKey(int(p->state())))},
                        {QStringLiteral("updated"), base::isoTimeWithOffset(p->lastUpdate())}});
    }
    return {{QStringLiteral("address"), d.info().addressText()},
            {QStringLiteral("model"), d.info().model},
            {QStringLiteral("family"), d.family()},
            {QStringLiteral("softwareVersion"), d.info().softwareVersion},
            {QStringLiteral("values"), values},
            {QStringLiteral("whatToCheck"), advice}};
}

// The parts of a report that belong to one line: its link and statistics, its devices, its events.
QJsonObject linePart(Session &session, int recentEvents) {
    QJsonObject line;
    if (link::Line *l = session.line()) {
        const link::LinkStats &s = l->queue().stats();
        const qint64 now = l->queue().nowMs();
        QJsonObject naks;
        for (auto it = s.naks.begin(); it != s.naks.end(); ++it)
            naks.insert(QString::number(it.key()), it.value());
        line = {{QStringLiteral("transport"), l->transport().description()},
                {QStringLiteral("state"), l->stateText()},
                {QStringLiteral("reconnects"), l->reconnects()},
                {QStringLiteral("sent"), s.sent},
                {QStringLiteral("answered"), s.answered},
                {QStringLiteral("timeouts"), s.timeouts},
                {QStringLiteral("corrupted"), s.corrupted},
                {QStringLiteral("stray"), s.stray},
                {QStringLiteral("retries"), s.retries},
                {QStringLiteral("naks"), naks},
                {QStringLiteral("latencyMedianMs"), s.medianLatencyUs() / 1000.0},
                {QStringLiteral("transactionsPerSecond"), s.transactionsPerSecond(now)},
                {QStringLiteral("summary"), s.summary(now)}};
    }
    QJsonArray devices;
    for (const DeviceModel *d : session.devices())
        devices.append(deviceJson(*d));
    QJsonArray events;
    const QList<Event> all = session.eventLog().events();
    for (qsizetype i = qMax<qsizetype>(0, all.size() - recentEvents); i < all.size(); ++i) {
        const Event &e = all.at(i);
        QJsonObject event{{QStringLiteral("time"), base::isoTimeWithOffset(e.time)},
                          {QStringLiteral("kind"), Event::kindName(e.kind)},
                          {QStringLiteral("severity"), Event::severityName(e.severity)},
                          {QStringLiteral("source"), e.source},
                          {QStringLiteral("text"), e.text},
                          {QStringLiteral("count"), e.count}};
        if (e.count > 1)
            event.insert(QStringLiteral("lastTime"), base::isoTimeWithOffset(e.lastTime));
        events.append(event);
    }
    return {{QStringLiteral("line"), line},
            {QStringLiteral("devices"), devices},
            {QStringLiteral("events"), events}};
}
} // namespace

QJsonObject supportReportJson(Session &session, int recentEvents) {
    QJsonObject report{
        {QStringLiteral("format"), QStringLiteral("tipscope-support-report")},
        {QStringLiteral("created"), base::isoTimeWithOffset(QDateTime::currentDateTime())},
        {QStringLiteral("tipscopeVersion"), QStringLiteral(TIPSCOPE_VERSION)},
        {QStringLiteral("qtVersion"), QString::fromLatin1(qVersion())},
        {QStringLiteral("system"), QSysInfo::prettyProductName()}};
    const QJsonObject part = linePart(session, recentEvents);
    for (auto it = part.begin(); it != part.end(); ++it)
        report.insert(it.key(), it.value());
    return report;
}

QJsonObject supportReportJson(Session &session, const QList<ReportedLine> &workspace,
                              int recentEvents) {
    QJsonObject report = supportReportJson(session, recentEvents);
    if (workspace.isEmpty())
        return report;
    QJsonArray lines;
    for (const ReportedLine &l : workspace) {
        QJsonObject part = linePart(*l.session, recentEvents);
        part.insert(QStringLiteral("name"), l.name);
        if (!l.cell.isEmpty())
            part.insert(QStringLiteral("cell"), l.cell);
        if (!l.location.isEmpty())
            part.insert(QStringLiteral("location"), l.location);
        lines.append(part);
    }
    report.insert(QStringLiteral("lines"), lines);
    return report;
}

base::Outcome<QStringList> writeSupportReport(const QJsonObject &report, const QString &folder) {
    const QString stem = QDir(folder).filePath(
        QStringLiteral("tipscope-report-%1")
            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss"))));
    const QList<QPair<QString, QByteArray>> files = {
        {stem + QStringLiteral(".json"), QJsonDocument(report).toJson(QJsonDocument::Indented)},
        {stem + QStringLiteral(".txt"), supportReportText(report).toUtf8()}};
    QStringList written;
    for (const auto &[path, bytes] : files) {
        if (const auto saved = base::io::saveAtomically(path, bytes); !saved.ok())
            return base::failure(saved.error());
        written.append(path);
    }
    return written;
}

} // namespace tipscope::model
