// runCfxBench: `tipscope-bench cfx`, the IPC-CFX endpoint of issue 42 under a plant's load. Starts
// a RabbitMQ node with its AMQP 1.0 plugin on free loopback ports, --stations (default 32)
// tipscope-sim stations over TCP (a DME each making --joints-per-minute joints on every port,
// every other one with an SFR feeder, the wire paced like a --pace baud line), and the
// independent Python consumer (CfxTap) on a durable queue that the agent publishes to, so what
// is sent while the consumer reconnects waits for it. A work context names a new board every
// --board-s seconds: at every board's end each station sends UnitsProcessed (with its joints)
// and WorkCompleted, and at its start WorkStarted, so the messages come in bursts of up to three
// a station, as at a real line's board change.
//
// Every agent publishes MQTT to a Mosquitto of the bench's, as a plant's agent does. First one
// without CFX runs the stations for --seconds, then one with CFX beside MQTT for as long, the
// same boards changing, and the two agents' CPU is compared. Then
// the broker is stopped for --outage-s while boards keep changing, started again and the
// backlog's drain timed; then the agent is killed (SIGKILL) in the middle of a board change's
// burst and started again on its journal. At the end every board named is checked at every
// station against the messages received and the agent's journal. Prints:
//   cfx.agent_cpu_off_pct, cfx.agent_cpu_on_pct  the agent's user + system CPU without and with
//                                CFX, % of one core over the window; cfx.agent_cpu_ratio their
//                                ratio
//   cfx.consumer_cpu_pct, cfx.stations_cpu_pct  for context: they share the machine with the
//                                agent
//   cfx.latency_p50_ms/_p99_ms   a message's arrival at the consumer minus its TimeStamp, the
//                                moment the journal recorded what it tells (target p99 < 500)
//   cfx.board_latency_p50_ms/_p99_ms  the same for UnitsProcessed alone: a board's end (the
//                                context naming the next) until its joints reach the consumer
//   cfx.messages_per_s           messages received a second in the window
//   cfx.backlog_messages         messages stamped during the outage, sent once the broker returned
//   cfx.backlog_first_s          the broker's return until the first of them arrived
//   cfx.backlog_drain_s, cfx.backlog_drain_per_s  the first until the last of them, and the rate
//                                (target >= 500 messages/s)
//   cfx.restart_s                the SIGKILL until every station said WorkStarted for the board
//                                named just before it
//   cfx.boards, cfx.joints_total the boards named and the journal's joints on them
//   cfx.messages_lost            WorkStarted or WorkCompleted of a board missing at a station
//   cfx.joints_lost              joints of the journal on a finished board in no UnitsProcessed
//   cfx.duplicates_same_id       messages received again with a UniqueID seen before (AMQP's at
//                                least once allows them; a consumer drops them by that id)
//   cfx.duplicates_two_ids       one message (or one joint) received under two UniqueIDs (must
//                                be 0)
//   cfx.consumer_complaints      what the consumer found not to be CFX (must be 0)
// A benchmark: it asserts nothing, but exits non-zero when it could not measure (RabbitMQ or the
// Python binding missing, a process that did not start, endpoints that never connected).
#pragma once

#include <QStringList>

namespace tipscope::bench {

int runCfxBench(const QStringList &args);

} // namespace tipscope::bench
