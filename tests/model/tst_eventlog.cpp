// EventLog stamps an event with the clock it is given (the session's sample clock), keeps a time
// the event already carries, and above its capacity lets the oldest go while counting them.
#include "model/eventlog.h"

#include <QSignalSpy>
#include <QTest>

using namespace tipscope;
using model::Event;
using model::EventLog;

class TestEventLog : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void anEventIsStampedByTheGivenClock();
    void aTimeTheEventCarriesIsKept();
    void withoutAClockTheWallClockStamps();
    void beyondTheCapacityTheOldestGoAndAreCounted();
};

void TestEventLog::anEventIsStampedByTheGivenClock() {
    EventLog log;
    // Far from the wall clock on purpose: a stamp from the wall clock cannot pass for it.
    qint64 now = 1'000'000'000'000;
    log.setClock([&now] { return now; });
    QSignalSpy appended(&log, &EventLog::appended);
    log.add(Event::Kind::Status, Event::Severity::Info, QStringLiteral("port 1"),
            QStringLiteral("sleep"));
    now += 1234;
    log.add(Event::Kind::Write, Event::Severity::Info, QStringLiteral("port 1"),
            QStringLiteral("SLT = 200 °C"));
    const QList<Event> events = log.events();
    QCOMPARE(events.size(), 2);
    QCOMPARE(events.at(0).time.toMSecsSinceEpoch(), 1'000'000'000'000);
    QCOMPARE(events.at(1).time.toMSecsSinceEpoch(), 1'000'000'001'234);
    QCOMPARE(appended.count(), 2);
    QCOMPARE(appended.at(1).at(0).value<Event>().time, events.at(1).time);
}

void TestEventLog::aTimeTheEventCarriesIsKept() {
    EventLog log;
    log.setClock([] { return qint64(5); });
    const QDateTime when = QDateTime::fromMSecsSinceEpoch(1'700'000'000'000);
    log.append({when, Event::Kind::Alarm, Event::Severity::Warning, QStringLiteral("port 2"),
                QStringLiteral("upper limit")});
    QCOMPARE(log.events().constFirst().time, when);
}

void TestEventLog::withoutAClockTheWallClockStamps() {
    EventLog log;
    const qint64 before = QDateTime::currentMSecsSinceEpoch();
    log.add(Event::Kind::Connection, Event::Severity::Info, QStringLiteral("line"),
            QStringLiteral("connected"));
    const qint64 after = QDateTime::currentMSecsSinceEpoch();
    const qint64 stamped = log.events().constFirst().time.toMSecsSinceEpoch();
    QVERIFY2(stamped >= before && stamped <= after, qPrintable(QString::number(stamped)));
}

void TestEventLog::beyondTheCapacityTheOldestGoAndAreCounted() {
    EventLog log(nullptr, 3);
    for (int i = 0; i < 5; ++i)
        log.add(Event::Kind::Status, Event::Severity::Info, QStringLiteral("port 1"),
                QString::number(i));
    const QList<Event> events = log.events();
    QCOMPARE(events.size(), 3);
    QCOMPARE(events.constFirst().text, QStringLiteral("2"));
    QCOMPARE(events.constLast().text, QStringLiteral("4"));
    QCOMPARE(log.dropped(), 2);
}

QTEST_GUILESS_MAIN(TestEventLog)
#include "tst_eventlog.moc"
