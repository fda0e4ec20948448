// The per-board CFX messages of one station: a board (the work context's board serial) is one
// CFX transaction at each station that works on it, opened by Production.WorkStarted and closed
// by Production.Processing.UnitsProcessed (the joints the station made on it) and
// Production.WorkCompleted, with the SDK's names (CFX/Production/WorkStarted.cs,
// WorkCompleted.cs, Processing/UnitsProcessed.cs, CFX/Structures/HandSoldering/*.cs,
// CFX/Structures/Generic/*.cs; docs/cfx.md).
//
// UnitsProcessed carries the board twice, for two kinds of reader: its CommonProcessData is the
// SDK's HandSolderingBoardProcessData (each joint a SolderPoint with its start, end and tip), and
// its one ProcessedUnit's UnitProcessData is a GenericProcessData of CFX 2.1 with what the
// hand-soldering structures have no field for: each joint a stage with its dip, recovery time,
// their uncertainties and limits, the verdict and the tool.
#pragma once

#include "cfxmessages.h"

#include "journal/boardrecord.h"
#include "journal/journaltypes.h"

namespace tipscope::cfx {

struct BoardWork {
    QString serial;
    QUuid transaction; // the same in the work's WorkStarted, UnitsProcessed and WorkCompleted
    QString workOrder;
    qint64 startedMs = 0;               // the work context named the board
    qint64 finishedMs = 0;              // it named another, or none
    QList<journal::StoredJoint> joints; // this station's on the board, oldest first
    // This station's port status changes: for each port the last one before the board (the
    // status it began in), then those while it was made, oldest first. Their details carry the
    // wire's status numbers ("from", "to"); a change journaled without them is passed over.
    QList<journal::StoredEvent> statusChanges;
};

// How long each port of the station spent in each status while the board was made (working,
// in the stand, sleep, hibernation: the status digit of the port's status), from
// BoardWork::statusChanges; a port whose status is never known then is left out.
struct PortStatusTimes {
    int port = 0;
    qint64 ms[4] = {0, 0, 0, 0};
};
[[nodiscard]] QList<PortStatusTimes> portStatusTimes(const BoardWork &work);

// From the joints' verdicts (journal::BoardResult): Succeeded, Failed, or Error when a joint
// could not be judged; what a board without joints at this station is: see workCompleted().
[[nodiscard]] QString processingResultOf(journal::BoardResult result);

// The board's id in HandSolderingBoardProcessData: the same for one serial at every station and
// in every message, so an MES joins them.
[[nodiscard]] QUuid boardId(const QString &serial);

[[nodiscard]] Message workStarted(const BoardWork &work);
// Result Completed when the station made joints on the board, Skipped when it made none.
[[nodiscard]] Message workCompleted(const BoardWork &work);
[[nodiscard]] Message unitsProcessed(const BoardWork &work);

} // namespace tipscope::cfx
