#include "journalfixture.h"

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
