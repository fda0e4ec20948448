// runPlantBench: `tipscope-bench plant`, the plant of issue 19 on one machine. Starts a Mosquitto
// broker (persistence on) on a free loopback port, --stations (default 32) tipscope-sim stations
// over TCP (a DME each making --joints-per-minute random joints on every port, every other one
// with an SFR feeder, the wire paced like a --pace baud line and each answer handed over a byte at
// a time, or every --chunk-ms as a USB adapter does), one tipscope-agent process with all
// of them as lines of its workspace (site "bench", live values every --interval-ms, keep-alive
// 5 s, retries at most 1 s apart, its own journal), and a subscriber in this process
// (PlantSubscriber). Once every device's status is online and a warm-up has passed, it measures
// for --seconds, then stops the broker for --outage-s while the stations keep making joints,
// starts it again and waits for the backlog. Before the broker and the agent start, the wire floor
// (wirefloor.h) is measured on the same stations for 30 s. Prints:
//   plant.floor_tx_per_s, plant.floor_cpu_us_per_tx, plant.floor_cpu_pct  the floor client
//                                filling every wire, as the agent's lines do: its rate, its CPU
//                                per transaction and its share of one core, the least
//                                plant.agent_cpu_pct could be on this machine
//   plant.agent_cpu_pct          the agent's user + system CPU (/proc/<pid>/stat) over the
//                                window, % of one core (target < 5)
//   plant.stations_cpu_pct, plant.subscriber_cpu_pct  the simulators' together and this
//                                process's, for context: they share the machine with the agent
//   plant.live_latency_p50_ms/_p99_ms  a live message's arrival at the subscriber minus its "ts",
//                                the time the agent read the value (target p99 < 500 at 1 Hz)
//   plant.messages_per_s         every message the subscriber received in the window, a second
//   plant.live_per_port_hz       live messages a port a second (the ports of the devices' info)
//   plant.backlog_joints         joints of the agent's journal that started during the outage
//   plant.backlog_first_s        from the broker's return until the first of those arrived (the
//                                agent's reconnecting)
//   plant.backlog_drain_s        from the broker's return until the last of those arrived
//   plant.backlog_drain_per_s    the two's ratio
//   plant.joints_total           the journal's joints of the whole run, once all are forwarded
//   plant.joints_lost            of those, ids the subscriber never received (must be 0)
//   plant.joints_duplicated      copies received beyond the first (QoS 1 allows them); each
//                                duplicated joint is noted on stderr with its copies' arrivals
// A benchmark: it asserts nothing, but exits non-zero when it could not measure (Mosquitto not
// installed, a process that did not start, devices that never came online).
#pragma once

#include <QStringList>

namespace tipscope::bench {

int runPlantBench(const QStringList &args);

} // namespace tipscope::bench
