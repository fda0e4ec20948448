// Internal: the SELECT statements JournalReader runs, built from its filters, and how their rows
// become records. Conditions bind their values in order, never paste them into the text.
#pragma once

#include "journaltypes.h"

#include <QSqlQuery>
#include <QString>
#include <QVariantList>

namespace tipscope::journal {

struct Select {
    QString sql;
    QVariantList values;
};

// Every column readJoint() reads, for the joints the filter selects, in its order and limit.
[[nodiscard]] Select selectJoints(const JointFilter &filter);
[[nodiscard]] Select selectEvents(const EventFilter &filter);
// The joints the filter selects as "FROM joints j WHERE ...", without order or limit, for
// aggregates to put their own columns before.
[[nodiscard]] Select jointsWhere(const JointFilter &filter);
// The oldest unsent records after row `afterId`.
[[nodiscard]] Select selectUnsentJoints(qint64 afterId, int limit);
[[nodiscard]] Select selectUnsentEvents(qint64 afterId, int limit, SentChannel channel);

// The line, address, model and software columns from `first` on.
[[nodiscard]] model::DeviceIdentity readDevice(const QSqlQuery &query, int first);
[[nodiscard]] StoredJoint readJoint(const QSqlQuery &query);
[[nodiscard]] StoredEvent readEvent(const QSqlQuery &query);

} // namespace tipscope::journal
