#include "sqlerror.h"

#include <QCoreApplication>

namespace tipscope::journal {

namespace {

struct SqlErrorTr {
    Q_DECLARE_TR_FUNCTIONS(Journal)
};

// SQLite's primary result codes (sqlite3.h); Qt reports them as the native error code.
enum SqliteCode {
    kPerm = 3,
    kBusy = 5,
    kLocked = 6,
    kReadOnly = 8,
    kIoError = 10,
    kCorrupt = 11,
    kFull = 13,
    kCantOpen = 14,
    kTooBig = 18,
    kConstraint = 19,
    kMismatch = 20,
    kAuth = 23,
    kNotADatabase = 26
};

int primaryCode(const QSqlError &error) {
    bool ok = false;
    const int code = error.nativeErrorCode().toInt(&ok);
    return ok ? code & 0xff : -1;
}

} // namespace

QString describeSqlError(const QSqlError &error, const QString &path) {
    switch (primaryCode(error)) {
    case kFull:
        return SqlErrorTr::tr(
                   "The journal %1 cannot grow: the disk is full or the journal reached its "
                   "size limit.")
            .arg(path);
    case kPerm:
    case kReadOnly:
    case kCantOpen:
    case kAuth:
        return readOnlyJournalText(path);
    case kCorrupt:
    case kNotADatabase:
        return SqlErrorTr::tr(
                   "The journal %1 is damaged or is not a journal; it was left untouched.")
            .arg(path);
    case kBusy:
    case kLocked:
        return SqlErrorTr::tr("The journal %1 is locked by another program.").arg(path);
    case kIoError:
        return SqlErrorTr::tr("The disk holding the journal %1 reported an error.").arg(path);
    default:
        return SqlErrorTr::tr("The journal %1 reported an error: %2").arg(path, error.text());
    }
}

JournalProblem problemOf(const QSqlError &error) {
    switch (primaryCode(error)) {
    case kFull:
        return JournalProblem::Full;
    case kPerm:
    case kReadOnly:
    case kCantOpen:
    case kAuth:
        return JournalProblem::ReadOnly;
    case kCorrupt:
    case kNotADatabase:
        return JournalProblem::Damaged;
    case kBusy:
    case kLocked:
        return JournalProblem::Locked;
    case kIoError:
        return JournalProblem::DiskError;
    default:
        return JournalProblem::Other;
    }
}

QString readOnlyJournalText(const QString &path) {
    return SqlErrorTr::tr(
               "The journal %1 cannot be written: its folder or the file is read-only or not "
               "accessible.")
        .arg(path);
}

bool isRecordError(const QSqlError &error) {
    const int code = primaryCode(error);
    return code == kConstraint || code == kMismatch || code == kTooBig;
}

} // namespace tipscope::journal
