#include "boardpdf.h"

#include "base/atomicsave.h"
#include "base/timetext.h"
#include "journal/boardexport.h"
#include "journal/jointexport.h"
#include "model/joints/jointtable.h"
#include "model/joints/tipwear.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QGuiApplication>
#include <QLocale>
#include <QPageSize>
#include <QPdfWriter>
#include <QTextDocument>
#include <algorithm>

namespace tipscope::report {

using journal::BoardRecord;
using journal::BoardResult;
using journal::BoardTip;
using journal::StoredEvent;
using journal::StoredJoint;
using model::JointTableModel;

namespace {

struct BoardPdfTr {
    Q_DECLARE_TR_FUNCTIONS(BoardReport)
};

constexpr int kWorstShown = 3;

QString esc(const QString &text) {
    return text.toHtmlEscaped();
}

QString localTime(qint64 ms) {
    return QDateTime::fromMSecsSinceEpoch(ms).toString(QStringLiteral("yyyy-MM-dd HH:mm:ss"));
}

// Every cell keeps its words on one line but the last, the row's text (what happened, the wear,
// the verdict), which takes the width left.
QString row(const QStringList &cells, bool header = false) {
    const QString tag = header ? QStringLiteral("th") : QStringLiteral("td");
    QString html = QStringLiteral("<tr>");
    for (qsizetype i = 0; i < cells.size(); ++i) {
        const QString style =
            i + 1 < cells.size() ? QStringLiteral(" style=\"white-space: nowrap\"") : QString();
        html += QStringLiteral("<%1%2>%3</%1>").arg(tag, style, cells.at(i));
    }
    return html + QStringLiteral("</tr>");
}

QString table(const QStringList &header, const QStringList &rows) {
    return QStringLiteral("<table width=\"100%\" cellspacing=\"0\" cellpadding=\"2\" "
                          "border=\"1\" style=\"border-collapse: collapse\">") +
           row(header, true) + rows.join(QString()) + QStringLiteral("</table>");
}

QString resultText(BoardResult result) {
    switch (result) {
    case BoardResult::Pass:
        return BoardPdfTr::tr("PASS: every joint within its limits");
    case BoardResult::Fail:
        return BoardPdfTr::tr("FAIL: joints outside their limits");
    case BoardResult::NotJudged:
        return BoardPdfTr::tr("NOT JUDGED: no joint failed, but some could not be judged");
    case BoardResult::NoJoints:
        break;
    }
    return BoardPdfTr::tr("NO JOINTS: the journal holds events of this board only");
}

QString resultColour(BoardResult result) {
    switch (result) {
    case BoardResult::Pass:
        return QStringLiteral("#1b7a1b");
    case BoardResult::Fail:
        return QStringLiteral("#b00020");
    case BoardResult::NotJudged:
    case BoardResult::NoJoints:
        break;
    }
    return QStringLiteral("#8a6d00");
}

// The time of day, with the date only when it is not the board's first day.
QString timeOnBoard(qint64 ms, const BoardRecord &record) {
    const QDateTime time = QDateTime::fromMSecsSinceEpoch(ms);
    return time.date() == QDateTime::fromMSecsSinceEpoch(record.firstMs).date()
               ? time.toString(QStringLiteral("HH:mm:ss"))
               : localTime(ms);
}

QString cell(const StoredJoint &stored, int column) {
    return esc(JointTableModel::text({stored.record, stored.context.workOrder}, column,
                                     model::TemperatureUnit::Celsius));
}

// The dip and recovery with how sure each is: "40.0 K ± 0.5", "1.30 s ± 60 ms", an interval
// for a recovery only bounded.
QString sureDip(const StoredJoint &stored) {
    return BoardPdfTr::tr("%1 ± %2").arg(cell(stored, JointTableModel::Dip),
                                         QLocale().toString(stored.record.dipUncertaintyK, 'f', 1));
}

QString sureRecovery(const StoredJoint &stored) {
    const model::JointRecord &j = stored.record;
    if (!j.recoveryMs)
        return cell(stored, JointTableModel::Recovery);
    if (j.recoveryBounded)
        return BoardPdfTr::tr("%1 (bounded)").arg(cell(stored, JointTableModel::Recovery));
    return BoardPdfTr::tr("%1 ± %2 ms")
        .arg(cell(stored, JointTableModel::Recovery))
        .arg(j.recoveryUncertaintyMs);
}

// The limits the verdict was judged by, "≤ 80 K, ≤ 5.0 s"; a dash for a joint journaled before
// the journal kept them.
QString judgedBy(const StoredJoint &stored) {
    const auto &limits = stored.record.limits;
    if (!limits)
        return QStringLiteral("—");
    return BoardPdfTr::tr("≤ %1 K, ≤ %2 s")
        .arg(limits->maxDipK)
        .arg(QLocale().toString(double(limits->maxRecoveryMs) / 1000, 'f', 1));
}

// The limits the board's joints were judged by, each once (a joint journaled before the journal
// kept them has none).
QList<model::JudgedLimits> limitsOf(const BoardRecord &record) {
    QList<model::JudgedLimits> all;
    for (const StoredJoint &joint : record.joints)
        if (joint.record.limits && !all.contains(*joint.record.limits))
            all.append(*joint.record.limits);
    return all;
}

// A column of its own only where the joints were judged by different limits: a board made with
// one set of limits says them once, under the table, and keeps its page.
QString jointRow(const StoredJoint &stored, int number, const BoardRecord &record,
                 bool limitsColumn) {
    const QString verdict = cell(stored, JointTableModel::Verdict);
    const bool ok = stored.record.verdict == model::JointVerdict::Ok;
    QStringList cells{QString::number(number),
                      timeOnBoard(stored.record.startMs, record),
                      cell(stored, JointTableModel::Device),
                      cell(stored, JointTableModel::Port),
                      cell(stored, JointTableModel::Tool),
                      esc(stored.context.operatorName),
                      esc(stored.context.workOrder),
                      cell(stored, JointTableModel::Setpoint),
                      sureDip(stored),
                      sureRecovery(stored)};
    if (limitsColumn)
        cells.append(judgedBy(stored));
    cells.append(ok ? verdict : QStringLiteral("<b>%1</b>").arg(verdict));
    return row(cells);
}

QString header(const BoardRecord &record) {
    QString html = QStringLiteral("<h2>%1</h2>")
                       .arg(BoardPdfTr::tr("Board record: %1").arg(esc(record.serial)));
    html += QStringLiteral("<p style=\"font-size: 14pt; color: %1\"><b>%2</b></p>")
                .arg(resultColour(record.result), resultText(record.result));
    QStringList counts;
    for (const model::JointVerdict verdict : model::kJointVerdicts)
        counts.append(QStringLiteral("%1 %2")
                          .arg(record.verdicts.value(verdict))
                          .arg(esc(JointTableModel::verdictText(verdict))));
    const QString none = QStringLiteral("—");
    const QStringList lines{
        BoardPdfTr::tr("Made: %1 to %2")
            .arg(base::isoTimeWithOffset(QDateTime::fromMSecsSinceEpoch(record.firstMs)),
                 base::isoTimeWithOffset(QDateTime::fromMSecsSinceEpoch(record.lastMs))),
        BoardPdfTr::tr("Work order: %1")
            .arg(record.workOrders.isEmpty() ? none
                                             : esc(record.workOrders.join(QStringLiteral(", ")))),
        BoardPdfTr::tr("Operator: %1")
            .arg(record.operators.isEmpty() ? none
                                            : esc(record.operators.join(QStringLiteral(", ")))),
        BoardPdfTr::tr("Joints: %1 (%2)")
            .arg(record.joints.size())
            .arg(counts.join(QStringLiteral(", ")))};
    return html + QStringLiteral("<p>") + lines.join(QStringLiteral("<br>")) +
           QStringLiteral("</p>");
}

QString jointsSection(const BoardRecord &record) {
    const QList<model::JudgedLimits> limits = limitsOf(record);
    const bool limitsColumn = limits.size() > 1;
    QStringList rows;
    for (int i = 0; i < record.joints.size(); ++i)
        rows.append(jointRow(record.joints.at(i), i + 1, record, limitsColumn));
    QStringList head{QStringLiteral("#"),
                     JointTableModel::columnName(JointTableModel::Time),
                     BoardPdfTr::tr("Station"),
                     JointTableModel::columnName(JointTableModel::Port),
                     JointTableModel::columnName(JointTableModel::Tool),
                     BoardPdfTr::tr("Operator"),
                     JointTableModel::columnName(JointTableModel::WorkOrder),
                     JointTableModel::columnName(JointTableModel::Setpoint),
                     JointTableModel::columnName(JointTableModel::Dip),
                     JointTableModel::columnName(JointTableModel::Recovery)};
    if (limitsColumn)
        head.append(BoardPdfTr::tr("Limits (dip, recovery)"));
    head.append(JointTableModel::columnName(JointTableModel::Verdict));
    QString html = QStringLiteral("<h3>%1</h3>").arg(BoardPdfTr::tr("Joints")) + table(head, rows);
    if (limits.size() == 1)
        html += QStringLiteral("<p>%1</p>")
                    .arg(BoardPdfTr::tr("Judged by: a dip of at most %1 K, back within %2 K of "
                                        "the setpoint in at most %3 s.")
                             .arg(limits.first().maxDipK)
                             .arg(limits.first().bandK)
                             .arg(QLocale().toString(double(limits.first().maxRecoveryMs) / 1000,
                                                     'f', 1)));
    return html;
}

QString worstSection(const BoardRecord &record) {
    QStringList items;
    for (const StoredJoint &j : journal::worstJoints(record, kWorstShown)) {
        const auto at = std::find_if(record.joints.cbegin(), record.joints.cend(),
                                     [&j](const StoredJoint &other) { return other.id == j.id; });
        const int number = int(at - record.joints.cbegin()) + 1;
        items.append(
            QStringLiteral("<li>%1</li>")
                .arg(BoardPdfTr::tr("#%1 %2, port %3: dip %4, recovery %5, %6")
                         .arg(number)
                         .arg(cell(j, JointTableModel::Device))
                         .arg(j.record.port)
                         .arg(sureDip(j), sureRecovery(j), cell(j, JointTableModel::Verdict))));
    }
    return QStringLiteral("<h3>%1</h3><ul>%2</ul><p><i>%3</i></p>")
        .arg(BoardPdfTr::tr("Worst joints"), items.join(QString()),
             BoardPdfTr::tr("No curves: the journal keeps each joint's figures, not the tip's "
                            "readings during it."));
}

QString wearText(const BoardTip &tip) {
    const auto seconds = [](qint64 ms) { return base::secondsText(ms); };
    if (!tip.baselineMs)
        return BoardPdfTr::tr("not yet known: %1 joints of this tip; its first %2 recovered "
                              "ones are the baseline")
            .arg(tip.historyJoints)
            .arg(model::TipWear::kWindow);
    if (!tip.recentMs)
        return BoardPdfTr::tr("%1 s when plugged in; no joint since").arg(seconds(*tip.baselineMs));
    return BoardPdfTr::tr("recovers in %1 s now, %2 s when plugged in (%3)")
        .arg(seconds(*tip.recentMs), seconds(*tip.baselineMs), journal::wearShareText(tip));
}

QString tipsSection(const BoardRecord &record) {
    QStringList rows;
    for (const BoardTip &tip : record.tips) {
        QStringList setpoints;
        for (const int setpoint : tip.setpoints)
            setpoints.append(QStringLiteral("%1 °C").arg(setpoint));
        rows.append(
            row({esc(tip.device.model + QLatin1Char(' ') + journal::addressText(tip.device)),
                 QString::number(tip.port), esc(tip.tool), QString::number(tip.joints),
                 setpoints.join(QStringLiteral(", ")),
                 tip.sinceMs ? localTime(tip.sinceMs) : QStringLiteral("—"), wearText(tip)}));
    }
    const QStringList head{BoardPdfTr::tr("Station"),   BoardPdfTr::tr("Port"),
                           BoardPdfTr::tr("Tool"),      BoardPdfTr::tr("Joints"),
                           BoardPdfTr::tr("Setpoints"), BoardPdfTr::tr("Plugged in"),
                           BoardPdfTr::tr("Tip wear")};
    return QStringLiteral("<h3>%1</h3>").arg(BoardPdfTr::tr("Tools and settings")) +
           table(head, rows);
}

QString eventRow(const StoredEvent &stored) {
    const journal::JournalEvent &e = stored.record;
    QString where = e.device.isEmpty()
                        ? QStringLiteral("—")
                        : e.device.model + QLatin1Char(' ') + journal::addressText(e.device);
    if (e.port)
        where += BoardPdfTr::tr(", port %1").arg(*e.port);
    const bool fault = e.severity != journal::JournalEvent::Severity::Info;
    const QString text = fault ? QStringLiteral("<b>%1</b>").arg(esc(e.text)) : esc(e.text);
    return row(
        {esc(localTime(e.timeMs)), esc(where), esc(journal::JournalEvent::kindName(e.kind)), text});
}

// A heading, and its events as a table or "none".
QString eventsTable(const QString &title, const QList<StoredEvent> &events) {
    QStringList rows;
    for (const StoredEvent &e : events)
        rows.append(eventRow(e));
    const QStringList head{JointTableModel::columnName(JointTableModel::Time),
                           BoardPdfTr::tr("Station"), BoardPdfTr::tr("Kind"),
                           BoardPdfTr::tr("What happened")};
    return QStringLiteral("<h3>%1</h3>").arg(title) +
           (rows.isEmpty() ? QStringLiteral("<p>%1</p>").arg(BoardPdfTr::tr("None in the journal."))
                           : table(head, rows));
}

QString eventsSection(const BoardRecord &record) {
    return eventsTable(BoardPdfTr::tr("Profile applied before"), record.profilesBefore) +
           eventsTable(BoardPdfTr::tr("Faults and events while it was made"), record.events);
}

QString notHeldSection(const BoardRecord &record) {
    QStringList items;
    if (const int without = journal::jointsWithoutLimits(record); without > 0)
        items.append(BoardPdfTr::tr("The limits %1 of the %2 joints were judged by: they were "
                                    "journaled before the journal kept them; a failed joint's "
                                    "warning among the events names the limit it broke.")
                         .arg(without)
                         .arg(record.joints.size()));
    items += QStringList{
        BoardPdfTr::tr("The station's settings as they stood: the journal keeps only changes "
                       "made through TipScope (writes and profiles), not those made at the "
                       "station."),
        BoardPdfTr::tr("Curves of the joints: the journal keeps each joint's figures, not the "
                       "tip's readings.")};
    return QStringLiteral("<h3>%1</h3><ul><li>%2</li></ul>")
        .arg(BoardPdfTr::tr("Not in the journal"), items.join(QStringLiteral("</li><li>")));
}

QString footer(const BoardReportInfo &info) {
    return QStringLiteral("<p>%1<br>%2</p><p><br>%3</p>")
        .arg(BoardPdfTr::tr("Written by TipScope %1 on %2 from the journal %3")
                 .arg(esc(info.software), esc(localTime(info.writtenMs)), esc(info.journal)),
             BoardPdfTr::tr("Times are local; figures as measured from the station's readings, "
                            "each with how sure it is."),
             BoardPdfTr::tr("Checked by: ______________________   Date: ____________   "
                            "Signature: ______________________"));
}

} // namespace

QString boardHtml(const BoardRecord &record, const BoardReportInfo &info) {
    return QStringLiteral("<html><body style=\"font-size: 8pt\">") + header(record) +
           jointsSection(record) + worstSection(record) + tipsSection(record) +
           eventsSection(record) + notHeldSection(record) + footer(info) +
           QStringLiteral("</body></html>");
}

base::Outcome<void> writeBoardPdf(const BoardRecord &record, const BoardReportInfo &info,
                                  const QString &path) {
    if (!qobject_cast<QGuiApplication *>(QCoreApplication::instance()))
        return base::failure(
            BoardPdfTr::tr("cannot write %1: a PDF needs fonts, which need a graphical "
                           "application (QGuiApplication)")
                .arg(path));
    QBuffer pdf;
    pdf.open(QIODevice::WriteOnly);
    {
        QPdfWriter writer(&pdf);
        writer.setPageSize(QPageSize(QPageSize::A4));
        writer.setPageMargins(QMarginsF(12, 12, 12, 12), QPageLayout::Millimeter);
        writer.setTitle(BoardPdfTr::tr("Board record: %1").arg(record.serial));
        writer.setCreator(QStringLiteral("TipScope ") + info.software);
        QTextDocument document;
        document.setDocumentMargin(0); // the page's margins are the writer's
        document.setHtml(boardHtml(record, info));
        // Paginated here, on the writer's printable area at the document's 96 dpi: print() would
        // lay a document without a page size out with 2 cm margins of its own besides.
        document.setPageSize(writer.pageLayout().paintRect(QPageLayout::Point).size() *
                             (96.0 / 72.0));
        document.print(&writer);
    }
    return base::io::saveAtomically(path, pdf.data());
}

} // namespace tipscope::report
