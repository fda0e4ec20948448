// `tipscope-bench journal`, large file: a year of joints (and of events) built through the
// journal itself, its size on disk per record, and the queries the CLI, the Joints page and the
// support report make of it.
#include "benchsupport.h"
#include "journalbenchphases.h"

#include "journal/journalreader.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QSqlDatabase>
#include <QSqlQuery>
#include <QThread>
#include <functional>

namespace tipscope::bench {

namespace {

constexpr qint64 kYearStart = 1'672'531'200'000; // 2023-01-01 UTC
constexpr qint64 kDayMs = 24 * 3600 * 1000;
constexpr qint64 kYearMs = 365 * kDayMs;
constexpr int kStations = 10;

// Builds `rows` records over a year through a Journal; false when the journal failed.
bool build(const QString &path, const QString &name, int rows,
           const std::function<void(journal::Journal &, qint64, qint64)> &append) {
    journal::JournalOptions options;
    options.retentionDays = 0;
    journal::Journal journal(path, options);
    if (!waitJournalOpened(journal))
        return false;
    QElapsedTimer clock;
    clock.start();
    for (qint64 i = 0; i < rows; ++i) {
        while (journal.pendingCount() > 8000)
            QThread::msleep(1);
        if (i % 10'000 == 0)
            journal.setContext({QStringLiteral("WO-%1").arg(i / 10'000), QString(),
                                QStringLiteral("operator %1").arg(i / 10'000 % 7)});
        append(journal, i, kYearStart + i * (kYearMs / rows));
    }
    if (!journal.flush(600'000) || journal.lostCount() > 0) {
        printError(QStringLiteral("building the %1 file failed: %2 %3")
                       .arg(name, journal.errorText(), journal.lossReason()));
        return false;
    }
    printFigure(QStringLiteral("journal.build_%1_inserts_per_s").arg(name),
                double(rows) / (double(clock.nsecsElapsed()) / 1e9), QStringLiteral("records/s"),
                0);
    return true;
}

// The file's size once its write-ahead log is folded in, per record.
void printSize(const QString &path, const QString &name, int rows) {
    const QString connection = QStringLiteral("bench.size");
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), connection);
        db.setDatabaseName(path);
        if (db.open())
            QSqlQuery(db).exec(QStringLiteral("PRAGMA wal_checkpoint(TRUNCATE)"));
        db.close();
    }
    QSqlDatabase::removeDatabase(connection);
    const qint64 bytes = QFileInfo(path).size() + QFileInfo(path + QStringLiteral("-wal")).size();
    printFigure(QStringLiteral("journal.file_%1_mb").arg(name), double(bytes) / 1e6,
                QStringLiteral("MB"));
    printFigure(QStringLiteral("journal.bytes_per_%1").arg(name), double(bytes) / rows,
                QStringLiteral("bytes"));
}

// Runs `query` `count` times (its argument the run number) and prints the p50 and p99 time and
// the median number of rows it answered.
void timeQueries(const QString &name, int count, const std::function<qsizetype(int)> &query) {
    QList<double> ms;
    QList<double> rows;
    for (int q = 0; q < count; ++q) {
        QElapsedTimer clock;
        clock.start();
        rows.append(double(query(q)));
        ms.append(double(clock.nsecsElapsed()) / 1e6);
    }
    const QString prefix = QStringLiteral("journal.query_") + name;
    printFigure(prefix + QStringLiteral("_p50_ms"), quantile(ms, 0.5), QStringLiteral("ms"), 2);
    printFigure(prefix + QStringLiteral("_p99_ms"), quantile(ms, 0.99), QStringLiteral("ms"), 2);
    printFigure(prefix + QStringLiteral("_rows"), quantile(rows, 0.5), QStringLiteral("rows"), 0);
}

// Day q (spread over the year, the same for every run).
qint64 dayStart(int q) {
    return kYearStart + (qint64(q) * 7919 % 365) * kDayMs;
}

QString stationKey(int q) {
    return benchJoint(q % kStations, 0).device.key();
}

// The size of a query's answer; -1, with the reason in `error`, when it failed.
template <typename T> qsizetype sizeOf(const base::Outcome<QList<T>> &list, QString &error) {
    if (!list)
        error = list.error();
    return list ? list->size() : -1;
}

bool jointQueries(const JournalBenchOptions &o, const QString &path) {
    journal::JournalReader reader;
    if (const auto opened = reader.open(path); !opened) {
        printError(opened.error());
        return false;
    }
    QString error;
    timeQueries(QStringLiteral("day_port"), o.queries, [&](int q) {
        journal::JointFilter f;
        f.sinceMs = dayStart(q);
        f.untilMs = *f.sinceMs + kDayMs;
        f.port = q % 4 + 1;
        return sizeOf(reader.joints(f), error);
    });
    timeQueries(QStringLiteral("week_device_port_newest_1000"), o.queries, [&](int q) {
        journal::JointFilter f;
        f.sinceMs = dayStart(q);
        f.untilMs = *f.sinceMs + 7 * kDayMs;
        f.deviceKey = stationKey(q);
        f.port = q % 4 + 1;
        f.limit = 1000;
        return sizeOf(reader.joints(f), error);
    });
    timeQueries(QStringLiteral("month_verdict_counts"), qMax(1, o.queries / 5), [&](int q) {
        journal::JointFilter f;
        f.sinceMs = dayStart(q);
        f.untilMs = *f.sinceMs + 30 * kDayMs;
        const auto counts = reader.verdictCounts(f);
        if (!counts)
            error = counts.error();
        return counts ? qsizetype(counts->value(model::JointVerdict::Ok)) : -1;
    });
    timeQueries(QStringLiteral("month_recovery_by_port"), qMax(1, o.queries / 5), [&](int q) {
        journal::JointFilter f;
        f.sinceMs = dayStart(q);
        f.untilMs = *f.sinceMs + 30 * kDayMs;
        return sizeOf(reader.recoveryByPort(f), error);
    });
    timeQueries(QStringLiteral("unsent_first_1000"), o.queries,
                [&](int) { return sizeOf(reader.unsentJoints(0, 1000), error); });
    if (!error.isEmpty()) {
        printError(error);
        return false;
    }
    return true;
}

bool eventQueries(const JournalBenchOptions &o, const QString &path) {
    journal::JournalReader reader;
    if (const auto opened = reader.open(path); !opened) {
        printError(opened.error());
        return false;
    }
    QString error;
    timeQueries(QStringLiteral("events_day_device"), o.queries, [&](int q) {
        journal::EventFilter f;
        f.sinceMs = dayStart(q);
        f.untilMs = *f.sinceMs + kDayMs;
        f.deviceKey = stationKey(q);
        return sizeOf(reader.events(f), error);
    });
    if (!error.isEmpty()) {
        printError(error);
        return false;
    }
    return true;
}

// How SQLite runs the day-and-port query, for the record.
void printPlan(const QString &path) {
    const QString connection = QStringLiteral("bench.plan");
    {
        QSqlDatabase db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), connection);
        db.setDatabaseName(path);
        QStringList steps;
        QSqlQuery q(db);
        if (db.open() && q.exec(QStringLiteral(
                             "EXPLAIN QUERY PLAN SELECT * FROM joints j WHERE j.start_ms >= 0 "
                             "AND j.start_ms < 1 AND j.port = 1 ORDER BY j.start_ms DESC, j.id "
                             "DESC"))) {
            while (q.next())
                steps.append(q.value(3).toString());
        }
        printText(QStringLiteral("journal.query_day_port_plan"), steps.join(QStringLiteral("; ")));
        db.close();
    }
    QSqlDatabase::removeDatabase(connection);
}

} // namespace

bool journalLargeFilePhase(const JournalBenchOptions &o, const QString &folder) {
    const QString joints = QDir(folder).filePath(QStringLiteral("year-joints.sqlite"));
    if (!build(joints, QStringLiteral("joint"), o.rows,
               [](journal::Journal &j, qint64 i, qint64 t) { j.append(benchJoint(i, t)); }))
        return false;
    printSize(joints, QStringLiteral("joint"), o.rows);
    printPlan(joints);
    if (!jointQueries(o, joints))
        return false;
    const QString events = QDir(folder).filePath(QStringLiteral("year-events.sqlite"));
    if (!build(events, QStringLiteral("event"), o.rows,
               [](journal::Journal &j, qint64 i, qint64 t) { j.append(benchEvent(i, t)); }))
        return false;
    printSize(events, QStringLiteral("event"), o.rows);
    return eventQueries(o, events);
}

} // namespace tipscope::bench
