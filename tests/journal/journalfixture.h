// Shared pieces of the journal tests: records with every field set, and a plain SQLite
// connection of the test's own, to look at a file without the code under test.
#pragma once

#include "journal/boardrecord.h"
#include "journal/journal.h"

#include <QSqlDatabase>
#include <QString>
#include <QVariant>

namespace tipscope::testing {

inline constexpr qint64 kT0 = 1'700'000'000'000; // 2023-11-14, a fixed instant

// Device `n` (0, 1, ...) on its own line: "/dev/serial/by-id/usb-JBC_n-if00", address 01.
[[nodiscard]] model::DeviceIdentity sampleDevice(int n);
// Joint `i`: every field set and different from joint i-1's; started at `startMs`.
[[nodiscard]] model::JointRecord sampleJoint(int i, qint64 startMs, int port = 1, int deviceNo = 0);
// Event `i`: a write with details, on port `port` of device 0.
[[nodiscard]] journal::JournalEvent sampleEvent(int i, qint64 timeMs, int port = 1);
// An event of `kind` on port `port` of device 0: an error ("Short circuit") unless `severity` is
// Info ("error cleared").
[[nodiscard]] journal::JournalEvent portEvent(journal::JournalEvent::Kind kind,
                                              journal::JournalEvent::Severity severity, int port,
                                              qint64 timeMs);

// A journal with one board on it, "SN-42", as a plant's would hold it:
// - before it (board SN-41): a tool change on device 0 port 1, the tip's first joints
//   (TipWear::kWindow and two more, recovering in 1.0 s) and a profile applied to device 0;
// - the board: joints on device 0 port 1 with the same tip, slower (1.3 s), one slow recovery,
//   one only bounded (incomplete), one too deep on port 2 with another tool; a port error and a
//   joint warning stamped with the board; a status event of device 0 while the board was made,
//   stamped with another line's context; a status event of device 1 at the same time (not the
//   board's: its device made none of the board's joints);
// - after it: a joint of board SN-43.
// Every record goes through the journal's own writer; the file is flushed and closed.
struct SampleBoard {
    QList<model::JointRecord> joints;    // the board's, in time order
    QList<journal::JournalEvent> events; // the board's, in time order
    journal::JournalEvent profileBefore;
    int tipJointsBefore = 0; // port 1's C245 joints before the board
    bool written = false;    // flushed: every record is in the file
};
[[nodiscard]] SampleBoard writeSampleBoard(const QString &path);
// writeSampleBoard() at `path`, and the record of SN-42 read back from it; the reason when not.
[[nodiscard]] base::Outcome<journal::BoardRecord> writeAndReadSampleBoard(const QString &path);

// Options for tests: nothing pruned (retention 0), retries every 50 ms.
[[nodiscard]] journal::JournalOptions quickOptions();

// Waits (with the event loop) until the journal left Opening.
[[nodiscard]] bool waitOpened(journal::Journal &journal, int timeoutMs = 10000);

// A connection of the test's own to `path`; closed and removed when destroyed.
class RawDatabase {
public:
    explicit RawDatabase(const QString &path);
    ~RawDatabase();
    [[nodiscard]] bool isOpen() const { return m_db.isOpen(); }
    // The first column of the first row `sql` answers; an invalid QVariant on failure.
    [[nodiscard]] QVariant scalar(const QString &sql);
    // Runs every `;`-separated statement; false and `error` on the first failure.
    [[nodiscard]] bool execAll(const QString &script, QString *error);

private:
    QString m_name;
    QSqlDatabase m_db;
};

} // namespace tipscope::testing
