#include "journalsettings.h"

#include "sqlerror.h"

#include <QCoreApplication>
#include <QSqlQuery>
#include <QVariant>

namespace tipscope::journal {

using base::failure;
using base::Outcome;

namespace {

struct JournalSettingsTr {
    Q_DECLARE_TR_FUNCTIONS(Journal)
};

const QString kRetentionKey = QStringLiteral("retention_days");

} // namespace

Outcome<int> readRetentionDays(QSqlDatabase &db) {
    QSqlQuery query(db);
    if (!query.prepare(QStringLiteral("SELECT value FROM settings WHERE key = ?")))
        return failure(describeSqlError(query.lastError(), db.databaseName()));
    query.addBindValue(kRetentionKey);
    if (!query.exec())
        return failure(describeSqlError(query.lastError(), db.databaseName()));
    if (!query.next())
        return kDefaultRetentionDays;
    bool ok = false;
    const int days = query.value(0).toString().toInt(&ok);
    // A value another tool wrote badly must not prune a year of records: keep the default.
    return ok && checkRetentionDays(days) ? days : kDefaultRetentionDays;
}

Outcome<void> storeRetentionDays(QSqlDatabase &db, int days) {
    if (const auto valid = checkRetentionDays(days); !valid)
        return valid;
    QSqlQuery query(db);
    if (!query.prepare(QStringLiteral("INSERT INTO settings (key, value) VALUES (?, ?) "
                                      "ON CONFLICT (key) DO UPDATE SET value = excluded.value")))
        return failure(describeSqlError(query.lastError(), db.databaseName()));
    query.addBindValue(kRetentionKey);
    query.addBindValue(QString::number(days));
    if (!query.exec())
        return failure(describeSqlError(query.lastError(), db.databaseName()));
    return {};
}

Outcome<void> checkRetentionDays(int days) {
    if (days < 0 || days > kMaxRetentionDays)
        return failure(JournalSettingsTr::tr(
                           "A retention of %1 days is not possible: give 0 (keep everything) "
                           "up to %2 days.")
                           .arg(days)
                           .arg(kMaxRetentionDays));
    return {};
}

} // namespace tipscope::journal
