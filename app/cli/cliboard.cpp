// tipscope-cli board SERIAL: the record of one board from the journal (lib/journal/boardrecord.h)
// as text lines, --json, --csv (its joints) or --pdf FILE (lib/report/boardpdf.h). It reads the
// journal another program writes, and never writes it.
#include "clicommands.h"

#include "base/elide.h"
#include "journal/boardexport.h"
#include "journal/journalreader.h"
#include "report/boardpdf.h"

#include <QDateTime>
#include <QJsonDocument>

namespace tipscope::cli {

namespace {

struct CliBoardTr {
    Q_DECLARE_TR_FUNCTIONS(CliBoard)
};

// The one output format asked for, or why the options are wrong.
base::Outcome<QString> boardFormatOf(const CliOptions &o) {
    QStringList formats;
    for (const QString &flag : {QStringLiteral("json"), QStringLiteral("csv")})
        if (o.flags.contains(flag))
            formats.append(flag);
    if (o.values.contains(QStringLiteral("pdf")))
        formats.append(QStringLiteral("pdf"));
    if (formats.size() > 1)
        return base::failure(CliBoardTr::tr("give one of --json, --csv and --pdf FILE"));
    if (o.args.size() != 1 || o.args.first().isEmpty())
        return base::failure(CliBoardTr::tr("board takes one board serial"));
    return formats.value(0, QStringLiteral("text"));
}

} // namespace

int runBoard(const CliOptions &o, QTextStream &out, QTextStream &err) {
    const auto format = boardFormatOf(o);
    if (!format) {
        err << "tipscope-cli: " << format.error() << Qt::endl;
        return kUsage;
    }
    journal::JournalReader reader;
    if (const int rc = openJournalToReport(o, reader, err); rc != kOk)
        return rc;
    const QString serial = o.args.first();
    const auto record = journal::buildBoardRecord(reader, serial);
    if (!record) {
        err << "tipscope-cli: " << record.error() << Qt::endl;
        return kTransport;
    }
    if (record->isEmpty()) {
        // As an unknown --device of `joints` is: the question names nothing the journal holds.
        err << "tipscope-cli: "
            << CliBoardTr::tr("the journal has no board '%1': no joint or event carries that "
                              "serial")
                   .arg(base::elided(serial))
            << Qt::endl;
        return kUsage;
    }
    const QString software = QCoreApplication::applicationVersion();
    if (*format == QLatin1String("pdf")) {
        const QString path = o.values.value(QStringLiteral("pdf"));
        const report::BoardReportInfo info{software, reader.path(),
                                           QDateTime::currentMSecsSinceEpoch()};
        if (const auto written = report::writeBoardPdf(record.value(), info, path); !written) {
            err << "tipscope-cli: " << written.error() << Qt::endl;
            return kUsage; // as a profile that cannot be saved: the file named is wrong
        }
    } else if (*format == QLatin1String("json")) {
        out << QJsonDocument(journal::boardJson(record.value(), software))
                   .toJson(QJsonDocument::Indented);
    } else if (*format == QLatin1String("csv")) {
        out << journal::boardCsv(record.value());
    } else {
        out << journal::boardText(record.value(), software);
    }
    out.flush();
    return kOk;
}

} // namespace tipscope::cli
