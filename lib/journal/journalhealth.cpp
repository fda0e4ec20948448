#include "journalhealth.h"

#include "jointexport.h"
#include "journalreader.h"

namespace tipscope::journal {

namespace {

QString stateName(JournalState state) {
    switch (state) {
    case JournalState::Opening:
        return QStringLiteral("opening");
    case JournalState::Ready:
        return QStringLiteral("ready");
    case JournalState::Failed:
        return QStringLiteral("failed");
    case JournalState::Closed:
        return QStringLiteral("closed");
    }
    return {};
}

} // namespace

QJsonObject journalHealth(const Journal &journal) {
    QJsonObject out{{QStringLiteral("path"), journal.path()},
                    {QStringLiteral("state"), stateName(journal.state())},
                    {QStringLiteral("error"), journal.errorText()},
                    {QStringLiteral("lost"), journal.lostCount()},
                    {QStringLiteral("lossReason"), journal.lossReason()},
                    {QStringLiteral("pending"), journal.pendingCount()}};
    JournalReader reader;
    const auto opened = reader.open(journal.path());
    const auto summary = opened ? reader.summary() : base::failure(opened.error());
    if (!summary) {
        out.insert(QStringLiteral("readError"), summary.error());
        return out;
    }
    const JournalSummary &s = summary.value();
    out.insert(QStringLiteral("joints"), s.joints);
    out.insert(QStringLiteral("events"), s.events);
    out.insert(QStringLiteral("unsentJoints"), s.unsentJoints);
    out.insert(QStringLiteral("unsentEvents"), s.unsentEvents);
    if (s.oldestMs)
        out.insert(QStringLiteral("oldest"), utcText(*s.oldestMs));
    if (s.newestMs)
        out.insert(QStringLiteral("newest"), utcText(*s.newestMs));
    out.insert(QStringLiteral("retentionDays"), journal.retentionDays()); // the one in force
    out.insert(QStringLiteral("bytes"), s.fileBytes);
    return out;
}

} // namespace tipscope::journal
