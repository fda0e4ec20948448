// tipscope-cli journal: what the journal holds (records, unsent ones, time span, size) and its
// retention. The retention lives in the journal file, so setting it here sets it for the GUI and
// every other program that keeps the same journal; a running one takes it at its next pruning
// (hourly) or when it starts.
#include "clicommands.h"

#include "journal/jointexport.h"
#include "journal/journal.h"
#include "journal/journalreader.h"
#include "journal/journalsettings.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>

namespace tipscope::cli {

using namespace tipscope::journal;

namespace {

struct CliJournalTr {
    Q_DECLARE_TR_FUNCTIONS(CliJournal)
};

QString retentionText(int days) {
    return days == 0 ? QStringLiteral("0 (keep everything)") : QStringLiteral("%1 days").arg(days);
}

QJsonValue timeJson(const std::optional<qint64> &ms) {
    return ms ? QJsonValue(utcText(*ms)) : QJsonValue();
}

int show(const CliOptions &o, QTextStream &out, QTextStream &err) {
    JournalReader reader;
    if (const int rc = openJournalToReport(o, reader, err); rc != kOk)
        return rc;
    const auto summary = reader.summary();
    if (!summary) {
        err << "tipscope-cli: " << summary.error() << Qt::endl;
        return kTransport;
    }
    const JournalSummary &s = summary.value();
    if (o.flags.contains(QStringLiteral("json"))) {
        const QJsonObject json{{QStringLiteral("path"), reader.path()},
                               {QStringLiteral("joints"), s.joints},
                               {QStringLiteral("events"), s.events},
                               {QStringLiteral("unsent_joints"), s.unsentJoints},
                               {QStringLiteral("unsent_events"), s.unsentEvents},
                               {QStringLiteral("oldest"), timeJson(s.oldestMs)},
                               {QStringLiteral("newest"), timeJson(s.newestMs)},
                               {QStringLiteral("retention_days"), s.retentionDays},
                               {QStringLiteral("bytes"), s.fileBytes}};
        out << QJsonDocument(json).toJson(QJsonDocument::Indented);
        return kOk;
    }
    const auto time = [](const std::optional<qint64> &ms) {
        return ms ? utcText(*ms) : QStringLiteral("-");
    };
    out << "journal: " << reader.path() << '\n'
        << "joints: " << s.joints << " (" << s.unsentJoints << " unsent)\n"
        << "events: " << s.events << " (" << s.unsentEvents << " unsent)\n"
        << "oldest: " << time(s.oldestMs) << '\n'
        << "newest: " << time(s.newestMs) << '\n'
        << "retention: " << retentionText(s.retentionDays) << '\n'
        << "size: " << QLocale::c().formattedDataSize(s.fileBytes) << Qt::endl;
    return kOk;
}

int setRetention(const CliOptions &o, QTextStream &out, QTextStream &err) {
    bool ok = false;
    const QString text = o.args.value(1);
    const int days = text.toInt(&ok);
    if (!ok || o.args.size() != 2) {
        err << CliJournalTr::tr("tipscope-cli: journal retention takes a number of days (0 keeps "
                                "everything), for example: journal retention 90")
            << Qt::endl;
        return kUsage;
    }
    if (const auto valid = checkRetentionDays(days); !valid) {
        err << "tipscope-cli: " << valid.error() << Qt::endl;
        return kRefused;
    }
    // The writer stores it: the same path the GUI's Preferences take, migrations included.
    Journal journal(journalPathOf(o));
    (void)journal.setRetentionDays(days);
    journal.close();
    // Read back from the file: the proof that it was stored, without counting the records.
    JournalReader reader;
    const auto opened = reader.open(journal.path());
    const auto stored = opened ? reader.retentionDays() : base::failure(opened.error());
    if (!stored || *stored != days) {
        const QString why = !stored ? stored.error() : journal.errorText();
        err << CliJournalTr::tr("tipscope-cli: the retention could not be stored: %1").arg(why)
            << Qt::endl;
        return kTransport;
    }
    out << "retention: " << retentionText(days) << Qt::endl;
    return kOk;
}

} // namespace

int runJournal(const CliOptions &o, QTextStream &out, QTextStream &err) {
    const QString action = o.args.value(0, QStringLiteral("show"));
    if (action == QLatin1String("show") && o.args.size() <= 1)
        return show(o, out, err);
    if (action == QLatin1String("retention"))
        return setRetention(o, out, err);
    err << CliJournalTr::tr("tipscope-cli: journal takes show or retention DAYS") << Qt::endl;
    return kUsage;
}

} // namespace tipscope::cli
