// The support report: one action writes what support staff need into two files, JSON for
// machines and text for people: TipScope's version, the line and its statistics, each device's
// identity and software version, every value it reported (settings, counters, errors), and the
// recent event log, and (when the caller adds them under "joints") the joint statistics of the
// last 24 hours; with a workspace open, each of its lines under its name, with its own statistics,
// devices and events. Nothing is read from the devices for it: it shows what TipScope knew.
#pragma once

#include "base/outcome.h"

#include <QJsonObject>
#include <QList>
#include <QString>
#include <QStringList>

namespace tipscope::model {

class Session;

// A workspace's line as the report names it.
struct ReportedLine {
    QString name;
    QString cell;
    QString location;
    Session *session = nullptr;
};

[[nodiscard]] QJsonObject supportReportJson(Session &session, int recentEvents = 500);
// `session`'s report with the workspace's lines under "lines", each as {"name", "cell",
// "location", "line", "devices", "events"}.
[[nodiscard]] QJsonObject supportReportJson(Session &session, const QList<ReportedLine> &workspace,
                                            int recentEvents = 500);
[[nodiscard]] QString supportReportText(const QJsonObject &report);
// Writes tipscope-report-<date>.json and .txt of `report` into `folder`; returns their paths,
// or why not.
[[nodiscard]] base::Outcome<QStringList> writeSupportReport(const QJsonObject &report,
                                                            const QString &folder);

} // namespace tipscope::model
