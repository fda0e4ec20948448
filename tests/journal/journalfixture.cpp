#include "journalfixture.h"

#include "journal/journalreader.h"
#include "model/joints/tipwear.h"

#include <QSignalSpy>
#include <QSqlError>
#include <QSqlQuery>
#include <QTest>

namespace tipscope::testing {

model::DeviceIdentity sampleDevice(int n) {
    return {QStringLiteral("/dev/serial/by-id/usb-JBC_%1-if00").arg(n), 1, QStringLiteral("DDE-2C"),
            QStringLiteral("98765%1").arg(n)};
}

model::JointRecord sampleJoint(int i, qint64 startMs, int port, int deviceNo) {
    model::JointRecord j;
    j.device = sampleDevice(deviceNo);
    j.port = port;
    j.tool = i % 2 ? QStringLiteral("C245") : QStringLiteral("C210");
    j.startMs = startMs;
    j.endMs = startMs + 1500 + i;
    j.setpoint = 350 + i % 7;
    j.lowestTip = 300 + i % 11;
    j.dipDepth = j.setpoint - j.lowestTip;
    if (i % 5 != 4)
        j.recoveryMs = 400 + 10 * (i % 50);
    j.durationMs = 1500 + i;
    j.powerPeak = 60 + i % 40;
    j.powerIntegral = 42.125 + i;
    j.verdict = model::kJointVerdicts[i % 4];
    return j;
}

journal::JournalEvent sampleEvent(int i, qint64 timeMs, int port) {
    journal::JournalEvent e;
    e.kind = journal::JournalEvent::Kind::Write;
    e.severity = journal::JournalEvent::Severity::Info;
    e.device = sampleDevice(0);
    e.port = port;
    e.timeMs = timeMs;
    e.text = QStringLiteral("ST%1 = %2 °C").arg(port).arg(300 + i);
    e.details = {{QStringLiteral("code"), QStringLiteral("ST%1").arg(port)},
                 {QStringLiteral("value"), QStringLiteral("%1").arg(300 + i, 5, 10, QChar('0'))},
                 {QStringLiteral("read_back"), QStringLiteral("match")}};
    return e;
}

journal::JournalEvent portEvent(journal::JournalEvent::Kind kind,
                                journal::JournalEvent::Severity severity, int port, qint64 timeMs) {
    journal::JournalEvent event;
    event.kind = kind;
    event.severity = severity;
    event.device = sampleDevice(0);
    event.port = port;
    event.timeMs = timeMs;
    event.text = severity == journal::JournalEvent::Severity::Info
                     ? QStringLiteral("error cleared")
                     : QStringLiteral("Short circuit");
    return event;
}

namespace {
journal::JournalEvent boardEvent(journal::JournalEvent::Kind kind, int deviceNo,
                                 std::optional<int> port, qint64 timeMs, const QString &text) {
    journal::JournalEvent e;
    e.kind = kind;
    e.severity = kind == journal::JournalEvent::Kind::Status
                     ? journal::JournalEvent::Severity::Info
                     : journal::JournalEvent::Severity::Error;
    e.device = sampleDevice(deviceNo);
    e.port = port;
    e.timeMs = timeMs;
    e.text = text;
    return e;
}

model::JointRecord boardJoint(int i, qint64 startMs, qint64 recoveryMs,
                              model::JointVerdict verdict) {
    model::JointRecord j = sampleJoint(i, startMs);
    j.tool = QStringLiteral("C245");
    j.setpoint = 350;
    j.lowestTip = 310;
    j.dipDepth = 40;
    j.recoveryMs = recoveryMs;
    j.verdict = verdict;
    j.startUncertaintyMs = 40;
    j.dipUncertaintyK = 0.5;
    j.recoveryUncertaintyMs = 60;
    return j;
}
} // namespace

SampleBoard writeSampleBoard(const QString &path) {
    using Kind = journal::JournalEvent::Kind;
    using model::JointVerdict;
    const model::WorkContext before{QStringLiteral("WO-7"), QStringLiteral("SN-41"),
                                    QStringLiteral("bo")};
    const model::WorkContext board{QStringLiteral("WO-7"), QStringLiteral("SN-42"),
                                   QStringLiteral("ana")};
    const model::WorkContext otherLine{QStringLiteral("WO-9"), QStringLiteral("SN-99"),
                                       QStringLiteral("eve")};
    const model::WorkContext after{QStringLiteral("WO-7"), QStringLiteral("SN-43"),
                                   QStringLiteral("ana")};
    SampleBoard sample;
    journal::Journal journal(path, quickOptions());
    journal.append(boardEvent(Kind::ToolChange, 0, 1, kT0, QStringLiteral("tool C245 plugged")),
                   before);
    sample.tipJointsBefore = model::TipWear::kWindow + 2;
    for (int i = 0; i < sample.tipJointsBefore; ++i)
        journal.append(boardJoint(i, kT0 + 1000 + i * 10'000, 1000, JointVerdict::Ok), before);
    sample.profileBefore = boardEvent(Kind::ProfileApply, 0, std::nullopt, kT0 + 200'000,
                                      QStringLiteral("profile 0123456789ab applied"));
    sample.profileBefore.severity = journal::JournalEvent::Severity::Info;
    sample.profileBefore.details = {{QStringLiteral("profileSha256"), QStringLiteral("0123")}};
    journal.append(sample.profileBefore, before);

    const qint64 t = kT0 + 300'000;
    for (int i = 0; i < 6; ++i)
        sample.joints.append(boardJoint(100 + i, t + i * 5000, 1300, JointVerdict::Ok));
    sample.joints[3].recoveryMs = 6000;
    sample.joints[3].verdict = JointVerdict::SlowRecovery;
    sample.joints[4].recoveryBounded = true;
    sample.joints[4].recoveryUncertaintyMs = 500;
    sample.joints[4].verdict = JointVerdict::Incomplete;
    sample.joints[5].port = 2;
    sample.joints[5].tool = QStringLiteral("C210");
    sample.joints[5].dipDepth = 95;
    sample.joints[5].lowestTip = 255;
    sample.joints[5].verdict = JointVerdict::TooDeep;
    // The first was journaled before the journal kept the limits a joint was judged by.
    for (int i = 1; i < sample.joints.size(); ++i)
        sample.joints[i].limits = model::JudgedLimits{5, 5000, 80};
    for (const model::JointRecord &j : std::as_const(sample.joints))
        journal.append(j, board);
    sample.events = {
        boardEvent(Kind::PortError, 0, 1, t + 7000, QStringLiteral("E-PT1: tip sensor open")),
        boardEvent(Kind::Status, 0, 2, t + 12'000, QStringLiteral("port 2 in the stand")),
        boardEvent(Kind::JointWarning, 0, 2, t + 26'600,
                   QStringLiteral("joint too deep: the tip fell 95.0 K below the setpoint "
                                  "(limit 80 K)"))};
    journal.append(sample.events[0], board);
    journal.append(sample.events[1], otherLine);
    journal.append(sample.events[2], board);
    journal.append(boardEvent(Kind::Status, 1, 1, t + 12'000, QStringLiteral("not the board's")),
                   otherLine);
    journal.append(boardJoint(200, t + 60'000, 1300, JointVerdict::Ok), after);
    sample.written = journal.flush();
    journal.close();
    return sample;
}

base::Outcome<journal::BoardRecord> writeAndReadSampleBoard(const QString &path) {
    if (!writeSampleBoard(path).written)
        return base::failure(QStringLiteral("the sample board was not written"));
    journal::JournalReader reader;
    if (const auto opened = reader.open(path); !opened)
        return base::failure(opened.error());
    return journal::buildBoardRecord(reader, QStringLiteral("SN-42"));
}

journal::JournalOptions quickOptions() {
    journal::JournalOptions options;
    options.retentionDays = 0;
    options.retryIntervalMs = 50;
    return options;
}

bool waitOpened(journal::Journal &journal, int timeoutMs) {
    return QTest::qWaitFor([&] { return journal.state() != journal::JournalState::Opening; },
                           timeoutMs);
}

RawDatabase::RawDatabase(const QString &path)
    : m_name(QStringLiteral("test.raw.%1").arg(quintptr(this), 0, 16)) {
    m_db = QSqlDatabase::addDatabase(QStringLiteral("QSQLITE"), m_name);
    m_db.setDatabaseName(path);
    m_db.open();
}

RawDatabase::~RawDatabase() {
    m_db.close();
    m_db = QSqlDatabase();
    QSqlDatabase::removeDatabase(m_name);
}

QVariant RawDatabase::scalar(const QString &sql) {
    QSqlQuery query(m_db);
    if (!query.exec(sql) || !query.next())
        return {};
    return query.value(0);
}

bool RawDatabase::execAll(const QString &script, QString *error) {
    const QStringList statements = script.split(QLatin1Char(';'), Qt::SkipEmptyParts);
    for (const QString &statement : statements) {
        if (statement.trimmed().isEmpty())
            continue;
        QSqlQuery query(m_db);
        if (!query.exec(statement)) {
            *error = statement.trimmed() + QStringLiteral(": ") + query.lastError().text();
            return false;
        }
    }
    return true;
}

} // namespace tipscope::testing
