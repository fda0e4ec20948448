// EventLog stamps an event with the clock it is given (the session's sample clock), keeps a time
// the event already carries, and above its capacity lets the oldest go while counting them. A
// flood of one event collapses into one entry with a count and a time span, announced once as
// appended and then as repeated; anything else the same source says ends the flood.
#include "model/events/eventlog.h"
#include "testmain.h"

#include <QSignalSpy>
#include <QTest>

namespace tst_eventlog {

using namespace tipscope;
using model::Event;
using model::EventLog;

class TestEventLog : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void anEventIsStampedByTheGivenClock();
    void aTimeTheEventCarriesIsKept();
    void aChangeIsStampedWhenTheReadingShowingItWasTaken();
    void withoutAClockTheWallClockStamps();
    void beyondTheCapacityTheOldestGoAndAreCounted();
    void aFloodOfOneEventIsOneEntryWithItsCountAndSpan();
    void onlyTheSameKindSeveritySourceAndTextCollapse_data();
    void onlyTheSameKindSeveritySourceAndTextCollapse();
    void anotherEventOfTheSameSourceEndsTheFlood();
    void otherSourcesInBetweenDoNotEndTheFlood();
    void aRepeatAfterALongQuietIsANewEntry();
    void idsGrowAndAreNeverReused();
    void repeatsTakeNoRoomUnderTheBound();

private:
    static void addAt(EventLog &log, qint64 &now, qint64 stepMs, const QString &source,
                      const QString &text);
};

void TestEventLog::addAt(EventLog &log, qint64 &now, qint64 stepMs, const QString &source,
                         const QString &text) {
    now += stepMs;
    log.add(Event::Kind::Communication, Event::Severity::Warning, source, text);
}

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

// A tool or an error changed when the station took the reading that shows it, not when its
// answer was decoded (Parameter::reportedAgeMs); never before the newest entry, so the log keeps
// its order.
void TestEventLog::aChangeIsStampedWhenTheReadingShowingItWasTaken() {
    EventLog log;
    qint64 now = 1'000'000'000'000;
    log.setClock([&now] { return now; });
    log.append(Event({}, Event::Kind::ToolChange, Event::Severity::Info, QStringLiteral("port 1"),
                     QStringLiteral("No tool → T245")),
               12.4);
    now += 5;
    log.append(Event({}, Event::Kind::PortError, Event::Severity::Info, QStringLiteral("port 1"),
                     QStringLiteral("error cleared")),
               30);
    const QList<Event> events = log.events();
    QCOMPARE(events.at(0).time.toMSecsSinceEpoch(), 1'000'000'000'000 - 12);
    QCOMPARE(events.at(1).time.toMSecsSinceEpoch(), 1'000'000'000'000 - 12);
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

void TestEventLog::aFloodOfOneEventIsOneEntryWithItsCountAndSpan() {
    EventLog log;
    qint64 now = 1'700'000'000'000;
    log.setClock([&now] { return now; });
    QSignalSpy appended(&log, &EventLog::appended);
    QSignalSpy repeated(&log, &EventLog::repeated);
    QVERIFY(appended.isValid() && repeated.isValid());
    const qint64 first = now + 100;
    // 75 failed requests during a 10 s unplug.
    for (int i = 0; i < 75; ++i)
        addAt(log, now, i == 0 ? 100 : 135, QStringLiteral("DME-2C at 01"),
              QStringLiteral("not sent: the line is not connected"));
    const QList<Event> events = log.events();
    QCOMPARE(events.size(), 1);
    QCOMPARE(events.at(0).count, 75);
    QCOMPARE(events.at(0).time.toMSecsSinceEpoch(), first);
    QCOMPARE(events.at(0).lastTime.toMSecsSinceEpoch(), first + 74 * 135);
    QCOMPARE(appended.count(), 1);
    QCOMPARE(repeated.count(), 74);
    const Event last = repeated.constLast().at(0).value<Event>();
    QCOMPARE(last.id, appended.at(0).at(0).value<Event>().id);
    QCOMPARE(last.count, 75);
}

void TestEventLog::onlyTheSameKindSeveritySourceAndTextCollapse_data() {
    QTest::addColumn<int>("kind");
    QTest::addColumn<int>("severity");
    QTest::addColumn<QString>("source");
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("entries");
    const int comm = int(Event::Kind::Communication);
    const int warning = int(Event::Severity::Warning);
    QTest::newRow("the same") << comm << warning << "DME-2C at 01"
                              << "timeout" << 1;
    QTest::newRow("another source") << comm << warning << "SFR-A at 10"
                                    << "timeout" << 2;
    QTest::newRow("another text") << comm << warning << "DME-2C at 01"
                                  << "NAK 3" << 2;
    QTest::newRow("another severity") << comm << int(Event::Severity::Error) << "DME-2C at 01"
                                      << "timeout" << 2;
    QTest::newRow("another kind") << int(Event::Kind::Connection) << warning << "DME-2C at 01"
                                  << "timeout" << 2;
}

void TestEventLog::onlyTheSameKindSeveritySourceAndTextCollapse() {
    QFETCH(int, kind);
    QFETCH(int, severity);
    QFETCH(QString, source);
    QFETCH(QString, text);
    QFETCH(int, entries);
    EventLog log;
    log.add(Event::Kind::Communication, Event::Severity::Warning, QStringLiteral("DME-2C at 01"),
            QStringLiteral("timeout"));
    log.add(Event::Kind(kind), Event::Severity(severity), source, text);
    QCOMPARE(log.size(), entries);
    QCOMPARE(log.events().constFirst().count, 3 - entries);
}

void TestEventLog::anotherEventOfTheSameSourceEndsTheFlood() {
    // A port error that comes, goes and comes again is three facts in their order, not two.
    EventLog log;
    const QString port = QStringLiteral("DME-2C at 01, port 2");
    for (const char *text : {"Short circuit", "error cleared", "Short circuit"})
        log.add(Event::Kind::PortError, Event::Severity::Error, port, QString::fromLatin1(text));
    const QList<Event> events = log.events();
    QCOMPARE(events.size(), 3);
    for (const Event &e : events)
        QCOMPARE(e.count, 1);
}

void TestEventLog::otherSourcesInBetweenDoNotEndTheFlood() {
    EventLog log;
    qint64 now = 1'700'000'000'000;
    log.setClock([&now] { return now; });
    const QString notSent = QStringLiteral("not sent: the line is not connected");
    for (int i = 0; i < 10; ++i) {
        addAt(log, now, 100, QStringLiteral("DME-2C at 01"), notSent);
        addAt(log, now, 100, QStringLiteral("SFR-A at 10"), notSent);
        log.add(Event::Kind::Connection, Event::Severity::Error, QStringLiteral("line"),
                QStringLiteral("disconnected, retrying"));
    }
    const QList<Event> events = log.events();
    QCOMPARE(events.size(), 3);
    for (const Event &e : events)
        QCOMPARE(e.count, 10);
    QCOMPARE(events.at(0).lastTime.toMSecsSinceEpoch() - events.at(0).time.toMSecsSinceEpoch(),
             9 * 200);
}

void TestEventLog::aRepeatAfterALongQuietIsANewEntry() {
    EventLog log;
    qint64 now = 1'700'000'000'000;
    log.setClock([&now] { return now; });
    addAt(log, now, 0, QStringLiteral("DME-2C at 01"), QStringLiteral("timeout"));
    addAt(log, now, EventLog::kRepeatWindowMs, QStringLiteral("DME-2C at 01"),
          QStringLiteral("timeout"));
    QCOMPARE(log.size(), 1);
    addAt(log, now, EventLog::kRepeatWindowMs + 1, QStringLiteral("DME-2C at 01"),
          QStringLiteral("timeout"));
    QCOMPARE(log.size(), 2);
    QCOMPARE(log.events().constLast().count, 1);
}

void TestEventLog::idsGrowAndAreNeverReused() {
    EventLog log(nullptr, 2);
    QSignalSpy appended(&log, &EventLog::appended);
    QVERIFY(appended.isValid());
    for (int i = 0; i < 3; ++i)
        log.add(Event::Kind::Status, Event::Severity::Info, QStringLiteral("port 1"),
                QString::number(i));
    log.clear();
    log.add(Event::Kind::Status, Event::Severity::Info, QStringLiteral("port 1"),
            QStringLiteral("after"));
    QList<quint64> ids;
    for (const QList<QVariant> &args : std::as_const(appended))
        ids.append(args.at(0).value<Event>().id);
    QCOMPARE(ids, QList<quint64>({1, 2, 3, 4}));
    QCOMPARE(log.events().constFirst().id, quint64(4));
}

void TestEventLog::repeatsTakeNoRoomUnderTheBound() {
    EventLog log(nullptr, 3);
    log.add(Event::Kind::Status, Event::Severity::Info, QStringLiteral("port 1"),
            QStringLiteral("first"));
    for (int i = 0; i < 100; ++i)
        log.add(Event::Kind::Communication, Event::Severity::Warning, QStringLiteral("DME"),
                QStringLiteral("timeout"));
    QCOMPARE(log.size(), 2);
    QCOMPARE(log.dropped(), 0);
    QCOMPARE(log.events().constFirst().text, QStringLiteral("first"));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestEventLog)

} // namespace tst_eventlog
#include "tst_eventlog.moc"
