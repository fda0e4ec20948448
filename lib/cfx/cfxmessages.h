// The CFX messages a soldering station's endpoint publishes, and the answers to requests, built
// with the field names of the IPC's SDK (each class is cited in docs/cfx.md). A builder returns
// the message's name and body; the envelope (cfxenvelope.h) adds who sends it, when and its id.
//
// A station's condition (what its ports and its link report) is mapped to a SEMI E10 state, the
// codes the SDK writes for ResourceState (as text: "2200"); the table is kE10Mapping, documented
// in docs/cfx.md.
// Faults come from the journal's station, port and feeder error events: the event that raises a
// fault gives its FaultOccurrenceId (the event's own id), so a FaultCleared made from a later
// "error cleared" event names the same occurrence.
#pragma once

#include "cfxenvelope.h"

#include "journal/journalevent.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QList>
#include <QUuid>
#include <optional>

namespace tipscope::cfx {

// A message without its envelope.
struct Message {
    QString name;
    QJsonObject body;
};

// `message` in its envelope, sent by `source`: a new id and the present time unless given.
[[nodiscard]] Envelope envelopeOf(const Message &message, const QString &source,
                                  const QUuid &uniqueId = QUuid::createUuid(),
                                  const QDateTime &time = QDateTime::currentDateTimeUtc());

// What TipScope knows of a station at a time, from the most to the least telling.
enum class StationCondition { Error, LinkLost, Working, InStand, Sleep, Hibernation };

// SEMI E10 states as the SDK's ResourceState enumerates them (CFX/Structures/ResourceState.cs).
enum class E10State {
    ProductiveRegularWork = 1100,
    StandbyNoOperator = 2100,
    StandbyNoProduct = 2200,
    StandbyNoHost = 2500,
    UnscheduledDowntime = 5000,
};

struct E10Mapping {
    StationCondition condition;
    E10State state;
    const char *why; // for docs/cfx.md and the tests
};
extern const E10Mapping kE10Mapping[6];

[[nodiscard]] E10State e10StateOf(StationCondition condition);
[[nodiscard]] QString conditionName(StationCondition condition);

// A CFX handle: dot-separated vendor, model and unit (serial number or the station's UID), each
// part reduced to letters, digits, '-' and '_' so the handle stays one AMQP subject word each.
[[nodiscard]] QString endpointHandle(const QString &vendor, const QString &model,
                                     const QString &unit);

[[nodiscard]] Message endpointConnected(const QString &handle, const QString &requestUri,
                                        const QString &requestAddress);
// `activeFaults`: an empty list says no fault is active, null that they are not known (the SDK's
// Heartbeat.ActiveFaults).
[[nodiscard]] Message heartbeat(const QString &handle, qint64 periodMs,
                                const QJsonValue &activeFaults);
[[nodiscard]] Message endpointShuttingDown(const QString &handle);
// `oldDurationMs` empty: unknown (the endpoint did not see the old state begin).
[[nodiscard]] Message stationStateChanged(StationCondition before,
                                          std::optional<qint64> oldDurationMs,
                                          StationCondition after, const QJsonObject &relatedFault);

// A fault raised or cleared by a journal event, or nothing when the event is neither.
struct FaultChange {
    bool raised = false;
    QJsonObject fault; // the CFX Fault, when raised
};
// True for the events that raise or clear faults (station, port and feeder errors).
[[nodiscard]] bool isFaultEvent(const journal::JournalEvent &event);
// Where a fault lives: one station, port or feeder error at a time per place.
[[nodiscard]] QString faultPlace(const journal::JournalEvent &event);
[[nodiscard]] QJsonObject fault(const journal::JournalEvent &event, const QUuid &occurrenceId);
[[nodiscard]] Message faultOccurred(const QJsonObject &fault);
[[nodiscard]] Message faultCleared(const QUuid &occurrenceId);

// Answers on the request queue.
[[nodiscard]] Message areYouThereResponse(const QString &handle, const QString &requestUri,
                                          const QString &requestAddress);
[[nodiscard]] Message notSupportedResponse(const QString &request);

} // namespace tipscope::cfx
