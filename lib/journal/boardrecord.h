// BoardRecord: everything the journal holds about one board (the board serial of the work
// context stamped on joints and events), gathered for a record a quality engineer signs
// (`tipscope-cli board`, the GUI's board report). A plain value; buildBoardRecord() only reads.
//
// What it holds, and where from:
//   joints     every joint stamped with the serial, oldest first, with its context, figures,
//              uncertainties and verdict;
//   events     every event stamped with the serial, and every event of the board's devices
//              between its first joint's start and its last joint's end (another line's context
//              may have been in force), oldest first: faults, alarms, warnings, writes;
//   tips       per device, port and tool: the joints made with it, the setpoints they were made
//              at, and its wear as TipWear judges it, replayed from the journal's joints of that
//              port since the last tool change before the board (the median recovery of the
//              tip's first joints and of its last ones up to its last joint on the board);
//   profiles   per device, the last profile applied before the board (settings the journal holds
//              only as changes made through TipScope: writes and profile applies).
// What the journal does not hold is not invented: the limits of the joints journaled before it
// kept them with each joint (schema 6; a joint warning among the events names the limit a failed
// joint broke), the station's settings as they stood (changes at the station's own keys are not
// seen), and the tip's readings during a joint (no curve can be drawn from the journal).
#pragma once

#include "journaltypes.h"

#include "base/outcome.h"

#include <QMap>

namespace tipscope::journal {

class JournalReader;

// From the joints' verdicts: Fail when any failed (too deep, slow recovery), else NotJudged when
// any could not be judged, else Pass; NoJoints for a board with events only.
enum class BoardResult { Pass, Fail, NotJudged, NoJoints };
[[nodiscard]] QString boardResultName(BoardResult result); // "pass", "fail", ... (files)
// The rule above, for joints counted by verdict.
[[nodiscard]] BoardResult boardResultOf(const QMap<model::JointVerdict, int> &verdicts);

struct BoardTip {
    model::DeviceIdentity device;
    int port = 0;
    QString tool;
    int joints = 0;                   // on this board
    QList<int> setpoints;             // °C, ascending, each once
    qint64 sinceMs = 0;               // the tool change that began this tip; 0: none in the journal
    int historyJoints = 0;            // the tip's joints in the journal up to then, any verdict
    std::optional<qint64> baselineMs; // median recovery of the tip's first TipWear::kWindow
    std::optional<qint64> recentMs;   // of its last ones, up to its last joint on the board
};

struct BoardRecord {
    QString serial;
    QList<StoredJoint> joints;
    QList<StoredEvent> events;
    QList<BoardTip> tips;
    QList<StoredEvent> profilesBefore;
    QMap<model::JointVerdict, int> verdicts;
    BoardResult result = BoardResult::NoJoints;
    qint64 firstMs = 0;     // the first joint's start, or the first event's time
    qint64 lastMs = 0;      // the last joint's end, or the last event's time
    QStringList workOrders; // of the records stamped with the board, in order of appearance
    QStringList operators;

    [[nodiscard]] bool isEmpty() const { return joints.isEmpty() && events.isEmpty(); }
};

// The record of `serial`; empty (isEmpty()) when the journal has no joint or event stamped with
// it. Fails only when the journal cannot be read.
[[nodiscard]] base::Outcome<BoardRecord> buildBoardRecord(const JournalReader &reader,
                                                          const QString &serial);

// How many of the board's joints carry no limits (journaled before the journal kept them).
[[nodiscard]] int jointsWithoutLimits(const BoardRecord &record);

// The `count` worst joints: failed ones first (too deep, then slow recovery), then by recovery
// time, slowest first (a joint that never recovered counts as slowest), then by dip.
[[nodiscard]] QList<StoredJoint> worstJoints(const BoardRecord &record, int count);

} // namespace tipscope::journal
