// The journal's file: a new one gets the current schema in WAL mode; a version-1 file (written
// here by hand, as TipScope's first journal wrote it) is migrated with its records kept and
// unsent; files that are not ours to change (a newer schema, another program's database) are
// refused and left byte for byte as they were; the default file lives in TipScope's data folder.
#include "journalfixture.h"
#include "testmain.h"

#include "journal/journalreader.h"
#include "journal/journalschema.h"

#include <QCryptographicHash>
#include <QFile>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

namespace tst_journalschema {

using namespace tipscope;
using namespace tipscope::testing;
using journal::Journal;
using journal::JournalReader;
using journal::JournalState;

namespace {

// The schema of version 1 exactly as its migration created it, with a device, a context, two
// joints (one never recovered) and an event. Kept here as a literal: a later edit to the
// migration in code must not change what this test calls an old file.
const char kVersionOneFile[] = R"(
CREATE TABLE devices (id INTEGER PRIMARY KEY, key TEXT NOT NULL UNIQUE, line TEXT NOT NULL,
  address INTEGER, model TEXT NOT NULL, software TEXT NOT NULL);
CREATE TABLE contexts (id INTEGER PRIMARY KEY, work_order TEXT NOT NULL,
  board_serial TEXT NOT NULL, operator TEXT NOT NULL, UNIQUE (work_order, board_serial, operator));
CREATE TABLE joints (id INTEGER PRIMARY KEY AUTOINCREMENT, uid BLOB NOT NULL,
  context_id INTEGER NOT NULL, device_id INTEGER NOT NULL, port INTEGER NOT NULL,
  tool TEXT NOT NULL, start_ms INTEGER NOT NULL, end_ms INTEGER NOT NULL,
  setpoint INTEGER NOT NULL, lowest_tip INTEGER NOT NULL, dip_depth INTEGER NOT NULL,
  recovery_ms INTEGER, duration_ms INTEGER NOT NULL, power_peak INTEGER NOT NULL,
  power_integral REAL NOT NULL, verdict TEXT NOT NULL);
CREATE INDEX joints_by_time ON joints (start_ms);
CREATE INDEX joints_by_port ON joints (port, start_ms);
CREATE INDEX joints_by_device ON joints (device_id, start_ms);
CREATE TABLE events (id INTEGER PRIMARY KEY AUTOINCREMENT, uid BLOB NOT NULL,
  context_id INTEGER NOT NULL, device_id INTEGER, port INTEGER, time_ms INTEGER NOT NULL,
  kind TEXT NOT NULL, severity TEXT NOT NULL, text TEXT NOT NULL, details TEXT);
CREATE INDEX events_by_time ON events (time_ms);
CREATE INDEX events_by_device ON events (device_id, time_ms);
INSERT INTO devices VALUES (1, '/dev/ttyUSB0|01|DME-2C|9996780', '/dev/ttyUSB0', 1, 'DME-2C',
  '9996780');
INSERT INTO contexts VALUES (1, 'WO-17', 'SN-0042', 'Ana');
INSERT INTO joints VALUES (1, X'00112233445566778899AABBCCDDEEFF', 1, 1, 2, 'C245',
  1700000000000, 1700000001500, 350, 310, 40, 700, 1500, 88, 61.5, 'ok');
INSERT INTO joints VALUES (2, X'FFEEDDCCBBAA99887766554433221100', 1, 1, 2, 'C245',
  1700000060000, 1700000062000, 350, 280, 70, NULL, 2000, 100, 150.25, 'incomplete');
INSERT INTO events VALUES (1, X'0123456789ABCDEF0123456789ABCDEF', 1, 1, 2, 1700000000500,
  'write', 'info', 'ST2 = 350 °C', '{"code":"ST2","read_back":"match"}');
PRAGMA application_id = 1416187987;
PRAGMA user_version = 1
)";

QByteArray fileHash(const QString &path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256);
}

bool writeFile(const QString &path, const QString &script) {
    RawDatabase raw(path);
    QString error;
    const bool ok = raw.isOpen() && raw.execAll(script, &error);
    if (!ok)
        qWarning("%s", qPrintable(error));
    return ok;
}

} // namespace

class TestJournalSchema : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aNewFileGetsTheCurrentSchemaInWalMode();
    void aVersionOneFileIsMigratedKeepingItsRecordsUnsent();
    void aFileNotOursToChangeIsRefusedAndLeftUntouched_data();
    void aFileNotOursToChangeIsRefusedAndLeftUntouched();
    void theDefaultFileIsInTipScopesDataFolderForEveryProgram();
};

void TestJournalSchema::aNewFileGetsTheCurrentSchemaInWalMode() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("sub/folder/journal.sqlite"));
    {
        Journal journal(path);
        QVERIFY(waitOpened(journal));
        QCOMPARE(journal.state(), JournalState::Ready);
        QVERIFY(journal.errorText().isEmpty());
    }
    RawDatabase raw(path);
    QCOMPARE(raw.scalar(QStringLiteral("PRAGMA user_version")).toInt(),
             journal::kJournalSchemaVersion);
    QCOMPARE(raw.scalar(QStringLiteral("PRAGMA journal_mode")).toString(), QStringLiteral("wal"));
    QCOMPARE(raw.scalar(QStringLiteral("PRAGMA application_id")).toInt(),
             journal::kJournalApplicationId);
    QCOMPARE(raw.scalar(QStringLiteral("SELECT count(*) FROM sqlite_master WHERE name IN "
                                       "('joints', 'events', 'devices', 'contexts', "
                                       "'joints_unsent', 'events_unsent')"))
                 .toInt(),
             6);
}

void TestJournalSchema::aVersionOneFileIsMigratedKeepingItsRecordsUnsent() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
    QVERIFY(writeFile(path, QString::fromUtf8(kVersionOneFile)));
    {
        Journal journal(path, quickOptions());
        QVERIFY(waitOpened(journal));
        QCOMPARE(journal.state(), JournalState::Ready);
        model::JointRecord judged = sampleJoint(3, kT0 + 120'000, 2);
        judged.limits = model::JudgedLimits{4, 2500, 60};
        QVERIFY(!journal.append(judged).isNull());
        QVERIFY(journal.flush());
    }
    RawDatabase raw(path);
    QCOMPARE(raw.scalar(QStringLiteral("PRAGMA user_version")).toInt(),
             journal::kJournalSchemaVersion);
    // Schema 3's settings table is there, empty: the retention is the default until one is set.
    QCOMPARE(raw.scalar(QStringLiteral("SELECT count(*) FROM settings")).toInt(), 0);

    JournalReader reader;
    const auto opened = reader.open(path);
    QVERIFY2(opened, qPrintable(opened.error()));
    journal::JointFilter oldestFirst;
    oldestFirst.order = journal::Order::OldestFirst;
    const auto joints = reader.joints(oldestFirst);
    QVERIFY2(joints, qPrintable(joints.error()));
    QCOMPARE(joints->size(), 3);
    const journal::StoredJoint &first = joints->at(0);
    QCOMPARE(first.id, 1);
    QCOMPARE(first.uid, QUuid(QStringLiteral("{00112233-4455-6677-8899-aabbccddeeff}")));
    QCOMPARE(first.context.workOrder, QStringLiteral("WO-17"));
    QCOMPARE(first.context.operatorName, QStringLiteral("Ana"));
    QCOMPARE(first.record.device.key(), QStringLiteral("/dev/ttyUSB0|01|DME-2C|9996780"));
    QCOMPARE(first.record.recoveryMs, std::optional<qint64>(700));
    QCOMPARE(first.record.powerIntegral, 61.5);
    QCOMPARE(first.record.verdict, model::JointVerdict::Ok);
    QCOMPARE(joints->at(1).record.recoveryMs, std::nullopt);
    QCOMPARE(joints->at(1).record.verdict, model::JointVerdict::Incomplete);
    QCOMPARE(joints->at(2).id, 3); // AUTOINCREMENT goes on after the old rows
    // Nobody kept the limits of the old joints; a new one keeps those it was judged by.
    QCOMPARE(first.record.limits, std::nullopt);
    QCOMPARE(joints->at(2).record.limits, std::optional(model::JudgedLimits{4, 2500, 60}));
    QCOMPARE(raw.scalar(QStringLiteral("SELECT count(*) FROM sqlite_master WHERE name IN "
                                       "('joints_by_context', 'events_by_context')"))
                 .toInt(),
             2);

    const auto unsent = reader.unsentJoints(0, 10);
    QVERIFY2(unsent, qPrintable(unsent.error()));
    QCOMPARE(unsent->size(), 3);
    const auto events = reader.events({});
    QVERIFY2(events, qPrintable(events.error()));
    QCOMPARE(events->size(), 1);
    QCOMPARE(events->first().record.details.value(QStringLiteral("read_back")).toString(),
             QStringLiteral("match"));
    QVERIFY(!events->first().sent);
}

void TestJournalSchema::aFileNotOursToChangeIsRefusedAndLeftUntouched_data() {
    QTest::addColumn<QString>("script");
    QTest::addColumn<QString>("expected");
    QTest::newRow("newer schema")
        << QStringLiteral("CREATE TABLE joints (id INTEGER PRIMARY KEY, later TEXT);"
                          "PRAGMA application_id = 1416187987; PRAGMA user_version = %1")
               .arg(journal::kJournalSchemaVersion + 1)
        << QStringLiteral("newer TipScope (schema %1").arg(journal::kJournalSchemaVersion + 1);
    QTest::newRow("another program's database")
        << QStringLiteral("CREATE TABLE accounts (id INTEGER PRIMARY KEY, name TEXT);"
                          "INSERT INTO accounts VALUES (1, 'x')")
        << QStringLiteral("is not a TipScope journal");
    QTest::newRow("another program's id")
        << QStringLiteral("PRAGMA application_id = 1234; PRAGMA user_version = 1")
        << QStringLiteral("is not a TipScope journal");
}

void TestJournalSchema::aFileNotOursToChangeIsRefusedAndLeftUntouched() {
    QFETCH(QString, script);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("journal.sqlite"));
    QVERIFY(writeFile(path, script));
    const QByteArray before = fileHash(path);
    QVERIFY(!before.isEmpty());
    {
        Journal journal(path, quickOptions());
        QSignalSpy states(&journal, &Journal::stateChanged);
        QVERIFY(states.isValid());
        QVERIFY(waitOpened(journal));
        QCOMPARE(journal.state(), JournalState::Failed);
        QVERIFY2(journal.errorText().contains(expected), qPrintable(journal.errorText()));
        QVERIFY(journal.errorText().contains(path));
        QVERIFY(QTest::qWaitFor([&] { return !states.isEmpty(); }));
        QCOMPARE(states.constFirst().at(0).value<JournalState>(), JournalState::Failed);
        // Retries go on without touching the file either.
        QTest::qWait(200);
    }
    JournalReader reader;
    const auto opened = reader.open(path);
    QVERIFY(!opened);
    QVERIFY2(opened.error().contains(expected), qPrintable(opened.error()));
    QCOMPARE(fileHash(path), before);
    QVERIFY(!QFile::exists(path + QStringLiteral("-wal")));
}

void TestJournalSchema::theDefaultFileIsInTipScopesDataFolderForEveryProgram() {
    QStandardPaths::setTestModeEnabled(true);
    const QString data = QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation);
    QCoreApplication::setApplicationName(QStringLiteral("tipscope-cli"));
    const QString fromCli = Journal::defaultPath();
    QCoreApplication::setApplicationName(QStringLiteral("TipScope"));
    QCoreApplication::setOrganizationName(QStringLiteral("TipScope"));
    QCOMPARE(fromCli, Journal::defaultPath());
    QCOMPARE(fromCli, data + QStringLiteral("/TipScope/TipScope/journal.sqlite"));
    QCOMPARE(QFileInfo(fromCli).absolutePath(),
             QStandardPaths::writableLocation(QStandardPaths::AppDataLocation));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestJournalSchema)

} // namespace tst_journalschema
#include "tst_journalschema.moc"
