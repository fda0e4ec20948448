// The journal's record types as they come back from it, and the filters that select them.
//
// Stored<T> is a record plus what the journal added when it stored it: the row id (increasing in
// the order records were appended, never reused, so "after id N" is a resumable position), the
// globally unique id (a random UUID; MQTT subscribers deduplicate by it), the work context in
// force when it was appended, and whether store-and-forward has marked it sent.
#pragma once

#include "journalevent.h"
#include "model/context/workcontext.h"
#include "model/joints/jointrecord.h"

#include <QList>
#include <QMetaType>
#include <QUuid>
#include <optional>

namespace tipscope::journal {

inline constexpr qint64 kDayMs = 24 * 3600 * 1000;

template <typename T> struct Stored {
    qint64 id = 0;
    QUuid uid;
    model::WorkContext context;
    bool sent = false;
    T record;
};
using StoredJoint = Stored<model::JointRecord>;
using StoredEvent = Stored<JournalEvent>;

// A record the journal wrote: its row id and its unique id.
struct RecordId {
    qint64 id = 0;
    QUuid uid;
};

// What one transaction made durable.
struct Committed {
    QList<RecordId> joints;
    QList<RecordId> events;
};

enum class Order { OldestFirst, NewestFirst };

// Who forwards a record: each keeps its own sent mark (CFX marks events only).
enum class SentChannel { Mqtt, Cfx };

// Joints whose start lies in [sinceMs, untilMs), of every device, port, ... unless narrowed.
struct JointFilter {
    std::optional<qint64> sinceMs;
    std::optional<qint64> untilMs;
    std::optional<QString> deviceKey; // DeviceIdentity::key()
    std::optional<int> port;
    std::optional<QString> tool;
    std::optional<model::JointVerdict> verdict;
    std::optional<QString> workOrder;
    std::optional<QString> boardSerial; // the work context's
    int limit = 0;                      // 0: all
    Order order = Order::NewestFirst;
};

// Events whose time lies in [sinceMs, untilMs).
struct EventFilter {
    std::optional<qint64> sinceMs;
    std::optional<qint64> untilMs;
    std::optional<QString> deviceKey;
    std::optional<int> port;
    QList<JournalEvent::Kind> kinds; // empty: every kind
    std::optional<QString> workOrder;
    std::optional<QString> boardSerial;
    int limit = 0;
    Order order = Order::NewestFirst;
};

// Recovery times of one port over a range: nearest-rank median and 95th percentile of the
// joints that recovered; `joints` counts them all, recovered or not.
struct PortRecovery {
    model::DeviceIdentity device;
    int port = 0;
    qint64 joints = 0;
    qint64 recovered = 0;
    qint64 medianMs = 0;
    qint64 p95Ms = 0;
};

// What a journal holds, for `tipscope-cli journal` and the support report.
struct JournalSummary {
    qint64 joints = 0;
    qint64 events = 0;
    qint64 unsentJoints = 0;
    qint64 unsentEvents = 0;
    std::optional<qint64> oldestMs; // none when the journal is empty
    std::optional<qint64> newestMs;
    int retentionDays = 0;
    qint64 fileBytes = 0; // the database and its write-ahead log
};

} // namespace tipscope::journal

Q_DECLARE_METATYPE(tipscope::journal::Committed)
