// journal_crash_writer PATH: appends joints to the journal at PATH as fast as it can, for ever,
// and prints the unique id of each one (a line each) once the journal says it is durable.
// tst_journalcrash kills it with SIGKILL in the middle of this and checks the file.
#include "journalfixture.h"

#include <QCoreApplication>
#include <QTimer>
#include <cstdio>

using namespace tipscope;

int main(int argc, char *argv[]) {
    QCoreApplication app(argc, argv);
    if (app.arguments().size() != 2) {
        std::fputs("usage: journal_crash_writer PATH\n", stderr);
        return 2;
    }
    journal::JournalOptions options;
    options.retentionDays = 0;
    journal::Journal journal(app.arguments().at(1), options);
    QObject::connect(&journal, &journal::Journal::committed, [](const journal::Committed &ids) {
        QByteArray lines;
        for (const journal::RecordId &id : ids.joints)
            lines += id.uid.toByteArray(QUuid::WithoutBraces) + '\n';
        std::fwrite(lines.constData(), 1, size_t(lines.size()), stdout);
        std::fflush(stdout);
    });
    QObject::connect(&journal, &journal::Journal::stateChanged, [&](journal::JournalState state) {
        if (state == journal::JournalState::Failed) {
            std::fprintf(stderr, "%s\n", qPrintable(journal.errorText()));
            QCoreApplication::exit(1);
        }
    });
    // As fast as the writer takes them, without piling up beyond what the journal holds.
    qint64 next = 0;
    QTimer load;
    QObject::connect(&load, &QTimer::timeout, [&] {
        while (journal.pendingCount() < 4000) {
            journal.append(testing::sampleJoint(int(next % 100'000), testing::kT0 + next));
            ++next;
        }
    });
    load.start(0);
    return app.exec();
}
