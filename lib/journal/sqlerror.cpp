#include "sqlerror.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QStorageInfo>
#include <sys/resource.h>

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

// SQLite says "disk full" only when the file system said ENOSPC to a write it could tell apart;
// many a full disk, and every write past the process's file size limit (EFBIG), come back as a
// plain I/O error. Below this, a disk that errs is taken for a full one.
constexpr qint64 kNearlyFullBytes = 1024 * 1024;

bool noRoomFor(const QString &path) {
    if (path.isEmpty())
        return false;
    const QStorageInfo disk(QFileInfo(path).absolutePath());
    if (disk.isValid() && disk.bytesAvailable() < kNearlyFullBytes)
        return true;
    rlimit limit{};
    if (::getrlimit(RLIMIT_FSIZE, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY)
        return false;
    // A write that would pass the limit is refused whole or in part: the file (or SQLite's
    // write-ahead log beside it) stands within a page or so of it.
    constexpr qint64 kLargestPage = 65536;
    const qint64 largest =
        qMax(QFileInfo(path).size(), QFileInfo(path + QLatin1String("-wal")).size());
    return largest + kLargestPage >= qint64(limit.rlim_cur);
}

int codeFor(const QSqlError &error, const QString &path) {
    const int code = primaryCode(error);
    return code == kIoError && noRoomFor(path) ? int(kFull) : code;
}

} // namespace

QString describeSqlError(const QSqlError &error, const QString &path) {
    switch (codeFor(error, path)) {
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

JournalProblem problemOf(const QSqlError &error, const QString &path) {
    switch (codeFor(error, path)) {
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
