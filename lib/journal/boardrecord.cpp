#include "boardrecord.h"

#include "journalreader.h"

#include "model/joints/tipwear.h"

#include <QSet>
#include <algorithm>
#include <tuple>

namespace tipscope::journal {

using base::failure;
using base::Outcome;

BoardResult boardResultOf(const QMap<model::JointVerdict, int> &verdicts) {
    if (verdicts.isEmpty())
        return BoardResult::NoJoints;
    if (verdicts.contains(model::JointVerdict::TooDeep) ||
        verdicts.contains(model::JointVerdict::SlowRecovery))
        return BoardResult::Fail;
    if (verdicts.contains(model::JointVerdict::Incomplete))
        return BoardResult::NotJudged;
    return BoardResult::Pass;
}

namespace {

void addOnce(QStringList &list, const QString &text) {
    if (!text.isEmpty() && !list.contains(text))
        list.append(text);
}

bool isOfTip(const StoredJoint &stored, const BoardTip &tip) {
    const model::JointRecord &j = stored.record;
    return j.device == tip.device && j.port == tip.port && j.tool == tip.tool;
}

// The board's tips in the order their first joints were made, with their joints and setpoints.
QList<BoardTip> boardTipsOf(const QList<StoredJoint> &joints) {
    QList<BoardTip> tips;
    for (const StoredJoint &stored : joints) {
        auto tip = std::find_if(tips.begin(), tips.end(),
                                [&stored](const BoardTip &t) { return isOfTip(stored, t); });
        if (tip == tips.end()) {
            BoardTip added;
            added.device = stored.record.device;
            added.port = stored.record.port;
            added.tool = stored.record.tool;
            tip = tips.insert(tips.end(), added);
        }
        ++tip->joints;
        if (!tip->setpoints.contains(stored.record.setpoint))
            tip->setpoints.append(stored.record.setpoint);
    }
    for (BoardTip &tip : tips)
        std::sort(tip.setpoints.begin(), tip.setpoints.end());
    return tips;
}

// The tip's wear up to `untilMs`: its port's joints since the last tool change replayed through
// TipWear, which starts afresh at a joint of another tool as the session's does.
Outcome<void> replayWear(const JournalReader &reader, BoardTip &tip, qint64 fromMs,
                         qint64 untilMs) {
    EventFilter changes;
    changes.deviceKey = tip.device.key();
    changes.port = tip.port;
    changes.kinds = {JournalEvent::Kind::ToolChange};
    changes.untilMs = fromMs + 1;
    changes.limit = 1;
    const auto change = reader.events(changes);
    if (!change)
        return failure(change.error());
    JointFilter history;
    history.deviceKey = tip.device.key();
    history.port = tip.port;
    history.untilMs = untilMs;
    history.order = Order::OldestFirst;
    if (!change->isEmpty()) {
        tip.sinceMs = change->first().record.timeMs;
        history.sinceMs = tip.sinceMs;
    }
    const auto joints = reader.joints(history);
    if (!joints)
        return failure(joints.error());
    model::TipWear wear;
    constexpr double kNeverNotice = 1e9; // the figures are wanted here, not the notice
    for (const StoredJoint &stored : joints.value()) {
        (void)wear.add(stored.record, kNeverNotice);
        // Counted as TipWear keeps them: another tool's joint starts afresh.
        tip.historyJoints = stored.record.tool == tip.tool ? tip.historyJoints + 1 : 0;
    }
    tip.baselineMs = wear.baselineMs(tip.device, tip.port);
    tip.recentMs = wear.recentMs(tip.device, tip.port);
    return {};
}

// The board's own events, and those of its devices while its joints were made.
Outcome<QList<StoredEvent>> eventsOf(const JournalReader &reader, const BoardRecord &record) {
    EventFilter stamped;
    stamped.boardSerial = record.serial;
    stamped.order = Order::OldestFirst;
    auto events = reader.events(stamped);
    if (!events)
        return events;
    QList<StoredEvent> all = events.value();
    QSet<qint64> ids;
    for (const StoredEvent &e : all)
        ids.insert(e.id);
    QSet<QString> devices;
    for (const StoredJoint &j : record.joints)
        devices.insert(j.record.device.key());
    for (const QString &key : devices) {
        EventFilter during;
        during.deviceKey = key;
        during.sinceMs = record.joints.first().record.startMs;
        during.untilMs = record.lastMs + 1;
        during.order = Order::OldestFirst;
        const auto more = reader.events(during);
        if (!more)
            return more;
        for (const StoredEvent &e : more.value())
            if (!ids.contains(e.id))
                all.append(e);
    }
    std::sort(all.begin(), all.end(), [](const StoredEvent &a, const StoredEvent &b) {
        return std::pair(a.record.timeMs, a.id) < std::pair(b.record.timeMs, b.id);
    });
    return all;
}

// Per device, the last profile applied before the board.
Outcome<QList<StoredEvent>> profilesBeforeOf(const JournalReader &reader,
                                             const BoardRecord &record) {
    QList<StoredEvent> profiles;
    QStringList seen;
    for (const BoardTip &tip : record.tips) {
        if (seen.contains(tip.device.key()))
            continue;
        seen.append(tip.device.key());
        EventFilter last;
        last.deviceKey = tip.device.key();
        last.kinds = {JournalEvent::Kind::ProfileApply};
        last.untilMs = record.firstMs;
        last.limit = 1;
        const auto found = reader.events(last);
        if (!found)
            return found;
        profiles += found.value();
    }
    return profiles;
}

int verdictRank(model::JointVerdict verdict) {
    switch (verdict) {
    case model::JointVerdict::TooDeep:
        return 0;
    case model::JointVerdict::SlowRecovery:
        return 1;
    case model::JointVerdict::Incomplete:
        return 2;
    case model::JointVerdict::Ok:
        break;
    }
    return 3;
}

} // namespace

QString boardResultName(BoardResult result) {
    switch (result) {
    case BoardResult::Pass:
        return QStringLiteral("pass");
    case BoardResult::Fail:
        return QStringLiteral("fail");
    case BoardResult::NotJudged:
        return QStringLiteral("not judged");
    case BoardResult::NoJoints:
        break;
    }
    return QStringLiteral("no joints");
}

Outcome<BoardRecord> buildBoardRecord(const JournalReader &reader, const QString &serial) {
    BoardRecord record;
    record.serial = serial;
    JointFilter filter;
    filter.boardSerial = serial;
    filter.order = Order::OldestFirst;
    const auto joints = reader.joints(filter);
    if (!joints)
        return failure(joints.error());
    record.joints = joints.value();
    for (const StoredJoint &stored : record.joints) {
        ++record.verdicts[stored.record.verdict];
        addOnce(record.workOrders, stored.context.workOrder);
        addOnce(record.operators, stored.context.operatorName);
        record.lastMs = qMax(record.lastMs, stored.record.endMs);
    }
    record.result = boardResultOf(record.verdicts);
    if (!record.joints.isEmpty())
        record.firstMs = record.joints.first().record.startMs;
    const auto events = eventsOf(reader, record);
    if (!events)
        return failure(events.error());
    record.events = events.value();
    if (record.joints.isEmpty() && !record.events.isEmpty()) {
        record.firstMs = record.events.first().record.timeMs;
        record.lastMs = record.events.last().record.timeMs;
    }
    for (const StoredEvent &stored : record.events) {
        if (stored.context.boardSerial != serial)
            continue; // an event of the station under another line's context
        addOnce(record.workOrders, stored.context.workOrder);
        addOnce(record.operators, stored.context.operatorName);
    }
    record.tips = boardTipsOf(record.joints);
    for (BoardTip &tip : record.tips) {
        // Up to the tip's last joint on the board: the port may have had another tool after it.
        const auto ofTip = [&tip](const StoredJoint &j) { return isOfTip(j, tip); };
        const auto first = std::find_if(record.joints.cbegin(), record.joints.cend(), ofTip);
        const auto last = std::find_if(record.joints.crbegin(), record.joints.crend(), ofTip);
        if (const auto replayed =
                replayWear(reader, tip, first->record.startMs, last->record.startMs + 1);
            !replayed)
            return failure(replayed.error());
    }
    const auto profiles = profilesBeforeOf(reader, record);
    if (!profiles)
        return failure(profiles.error());
    record.profilesBefore = profiles.value();
    return record;
}

QList<StoredJoint> worstJoints(const BoardRecord &record, int count) {
    QList<StoredJoint> sorted = record.joints;
    const auto key = [](const StoredJoint &s) {
        const model::JointRecord &j = s.record;
        return std::tuple(verdictRank(j.verdict), -j.recoveryMs.value_or(kDayMs), -j.dipDepth,
                          j.startMs);
    };
    std::stable_sort(
        sorted.begin(), sorted.end(),
        [&key](const StoredJoint &a, const StoredJoint &b) { return key(a) < key(b); });
    return sorted.mid(0, count);
}

int jointsWithoutLimits(const BoardRecord &record) {
    return int(std::count_if(record.joints.cbegin(), record.joints.cend(),
                             [](const StoredJoint &joint) { return !joint.record.limits; }));
}

} // namespace tipscope::journal
