// Queries of the journal: joints and events by time range, device, port, tool, verdict and work
// order, with a limit, newest or oldest first, each checked against the same filter applied by
// hand to what was appended; verdict counts and recovery quantiles per port; known devices.
#include "journalfixture.h"
#include "testmain.h"

#include "journal/journalreader.h"

#include <QTemporaryDir>
#include <QTest>
#include <algorithm>
#include <functional>

namespace tst_journalquery {

using namespace tipscope;
using namespace tipscope::testing;
using journal::EventFilter;
using journal::JointFilter;
using journal::Journal;
using journal::JournalEvent;
using journal::JournalReader;
using journal::Order;
using model::JointVerdict;

constexpr int kJoints = 48;
constexpr qint64 kStepMs = 60'000;

// Joint i: device i % 2, port 1 + i / 2 % 3, a minute apart but appended out of time order;
// work order WO-A for the first half, WO-B after.
struct Appended {
    model::JointRecord joint;
    QString workOrder;
};

QList<Appended> appendedJoints() {
    QList<Appended> out;
    for (int i = 0; i < kJoints; ++i) {
        const int slot = (i * 7) % kJoints; // a permutation of the minutes
        out.append({sampleJoint(i, kT0 + slot * kStepMs, 1 + i / 2 % 3, i % 2),
                    i < kJoints / 2 ? QStringLiteral("WO-A") : QStringLiteral("WO-B")});
    }
    return out;
}

using JointPredicate = std::function<bool(const Appended &)>;

class TestJournalQuery : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void jointsMatchTheFilterInTheAskedOrder_data();
    void jointsMatchTheFilterInTheAskedOrder();
    void eventsMatchTheFilter_data();
    void eventsMatchTheFilter();
    void verdictsAreCountedOverTheFilteredJoints();
    void recoveryQuantilesArePerDeviceAndPort();
    void everyDeviceWithARecordIsListed();
    void aMissingFileIsNotCreatedByAReader();

private:
    QTemporaryDir m_dir;
    QString m_path;
    QList<Appended> m_joints;
    JournalReader m_reader;
};

void TestJournalQuery::initTestCase() {
    m_path = m_dir.filePath(QStringLiteral("journal.sqlite"));
    m_joints = appendedJoints();
    Journal journal(m_path, quickOptions());
    for (int i = 0; i < m_joints.size(); ++i) {
        journal.setContext({m_joints.at(i).workOrder, QString(), QString()});
        journal.append(m_joints.at(i).joint);
        JournalEvent e = sampleEvent(i, kT0 + i * kStepMs, 1 + i % 4);
        e.kind = i % 3 ? JournalEvent::Kind::Write : JournalEvent::Kind::ToolChange;
        if (i % 5 == 0)
            e.device = sampleDevice(1);
        journal.append(e);
    }
    QVERIFY(journal.flush());
    const auto opened = m_reader.open(m_path);
    QVERIFY2(opened, qPrintable(opened.error()));
}

void TestJournalQuery::jointsMatchTheFilterInTheAskedOrder_data() {
    QTest::addColumn<JointFilter>("filter");
    QTest::addColumn<JointPredicate>("expected");
    const auto inRange = [](qint64 from, qint64 to) {
        return [=](const Appended &a) { return a.joint.startMs >= from && a.joint.startMs < to; };
    };
    JointFilter f;
    QTest::newRow("everything") << f << JointPredicate([](const Appended &) { return true; });
    f.sinceMs = kT0 + 10 * kStepMs;
    f.untilMs = kT0 + 30 * kStepMs;
    QTest::newRow("time range, end excluded")
        << f << JointPredicate(inRange(kT0 + 10 * kStepMs, kT0 + 30 * kStepMs));
    f.port = 2;
    QTest::newRow("time range and port") << f << JointPredicate([=](const Appended &a) {
        return inRange(kT0 + 10 * kStepMs, kT0 + 30 * kStepMs)(a) && a.joint.port == 2;
    });
    f.deviceKey = sampleDevice(1).key();
    QTest::newRow("time range, port and device") << f << JointPredicate([=](const Appended &a) {
        return inRange(kT0 + 10 * kStepMs, kT0 + 30 * kStepMs)(a) && a.joint.port == 2 &&
               a.joint.device == sampleDevice(1);
    });
    JointFilter tool;
    tool.tool = QStringLiteral("C245");
    QTest::newRow("tool") << tool << JointPredicate([](const Appended &a) {
        return a.joint.tool == QStringLiteral("C245");
    });
    JointFilter verdict;
    verdict.verdict = JointVerdict::TooDeep;
    QTest::newRow("verdict") << verdict << JointPredicate([](const Appended &a) {
        return a.joint.verdict == JointVerdict::TooDeep;
    });
    JointFilter order;
    order.workOrder = QStringLiteral("WO-B");
    order.order = Order::OldestFirst;
    order.limit = 5;
    QTest::newRow("work order, oldest five")
        << order
        << JointPredicate([](const Appended &a) { return a.workOrder == QStringLiteral("WO-B"); });
    JointFilter newest;
    newest.limit = 3;
    QTest::newRow("newest three") << newest
                                  << JointPredicate([](const Appended &) { return true; });
    JointFilter none;
    none.deviceKey = QStringLiteral("no such device");
    QTest::newRow("unknown device")
        << none << JointPredicate([](const Appended &) { return false; });
}

void TestJournalQuery::jointsMatchTheFilterInTheAskedOrder() {
    QFETCH(JointFilter, filter);
    QFETCH(JointPredicate, expected);
    QList<Appended> wanted;
    std::copy_if(m_joints.begin(), m_joints.end(), std::back_inserter(wanted), expected);
    std::sort(wanted.begin(), wanted.end(), [&](const Appended &a, const Appended &b) {
        return filter.order == Order::OldestFirst ? a.joint.startMs < b.joint.startMs
                                                  : a.joint.startMs > b.joint.startMs;
    });
    if (filter.limit > 0)
        wanted = wanted.mid(0, filter.limit);

    const auto joints = m_reader.joints(filter);
    QVERIFY2(joints, qPrintable(joints.error()));
    QCOMPARE(joints->size(), wanted.size());
    for (int i = 0; i < wanted.size(); ++i) {
        QVERIFY2(joints->at(i).record == wanted.at(i).joint, qPrintable(QString::number(i)));
        QCOMPARE(joints->at(i).context.workOrder, wanted.at(i).workOrder);
    }
    filter.limit = 0;
    const auto count = m_reader.countJoints(filter);
    QVERIFY2(count, qPrintable(count.error()));
    QCOMPARE(*count, std::count_if(m_joints.begin(), m_joints.end(), expected));
}

void TestJournalQuery::eventsMatchTheFilter_data() {
    QTest::addColumn<EventFilter>("filter");
    QTest::addColumn<QList<int>>("expected"); // event numbers, in the filter's order
    EventFilter range;
    range.sinceMs = kT0 + 3 * kStepMs;
    range.untilMs = kT0 + 7 * kStepMs;
    QTest::newRow("time range, newest first") << range << QList<int>{6, 5, 4, 3};
    EventFilter port;
    port.port = 3;
    port.order = Order::OldestFirst;
    port.limit = 4;
    QTest::newRow("port, oldest four") << port << QList<int>{2, 6, 10, 14};
    EventFilter kinds;
    kinds.kinds = {JournalEvent::Kind::ToolChange};
    kinds.untilMs = kT0 + 10 * kStepMs;
    QTest::newRow("kind") << kinds << QList<int>{9, 6, 3, 0};
    EventFilter device;
    device.deviceKey = sampleDevice(1).key();
    device.sinceMs = kT0 + 20 * kStepMs;
    QTest::newRow("device") << device << QList<int>{45, 40, 35, 30, 25, 20};
    EventFilter order;
    order.workOrder = QStringLiteral("WO-A");
    order.kinds = {JournalEvent::Kind::Write, JournalEvent::Kind::Alarm};
    order.sinceMs = kT0 + 18 * kStepMs;
    QTest::newRow("work order and kinds") << order << QList<int>{23, 22, 20, 19};
}

void TestJournalQuery::eventsMatchTheFilter() {
    QFETCH(EventFilter, filter);
    QFETCH(QList<int>, expected);
    const auto events = m_reader.events(filter);
    QVERIFY2(events, qPrintable(events.error()));
    QList<int> numbers;
    for (const journal::StoredEvent &e : *events)
        numbers.append(int((e.record.timeMs - kT0) / kStepMs));
    QCOMPARE(numbers, expected);
}

void TestJournalQuery::verdictsAreCountedOverTheFilteredJoints() {
    JointFilter filter;
    filter.port = 1;
    filter.limit = 1; // ignored by aggregates
    const auto counts = m_reader.verdictCounts(filter);
    QVERIFY2(counts, qPrintable(counts.error()));
    QMap<JointVerdict, qint64> expected;
    for (const JointVerdict v : model::kJointVerdicts)
        expected.insert(v, 0);
    for (const Appended &a : m_joints) {
        if (a.joint.port == 1)
            ++expected[a.joint.verdict];
    }
    QCOMPARE(*counts, expected);
    QVERIFY(expected.value(JointVerdict::Ok) > 0);
    QVERIFY(expected.value(JointVerdict::Incomplete) > 0);
}

void TestJournalQuery::recoveryQuantilesArePerDeviceAndPort() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("recovery.sqlite"));
    {
        Journal journal(path, quickOptions());
        // Port 1 of device 0: recoveries 1..100 ms in a shuffled order, plus 3 never recovered.
        for (int i = 0; i < 103; ++i) {
            model::JointRecord j = sampleJoint(i, kT0 + i, 1, 0);
            j.recoveryMs = i < 100 ? std::optional<qint64>((i * 37) % 100 + 1) : std::nullopt;
            journal.append(j);
        }
        // Port 2 of device 1: a single joint of 900 ms; port 3 out of the range.
        model::JointRecord single = sampleJoint(0, kT0 + 50, 2, 1);
        single.recoveryMs = 900;
        journal.append(single);
        journal.append(sampleJoint(1, kT0 + 1'000'000, 3, 1));
        QVERIFY(journal.flush());
    }
    JournalReader reader;
    const auto opened = reader.open(path);
    QVERIFY2(opened, qPrintable(opened.error()));
    JointFilter range;
    range.sinceMs = kT0;
    range.untilMs = kT0 + 1000;
    const auto ports = reader.recoveryByPort(range);
    QVERIFY2(ports, qPrintable(ports.error()));
    QCOMPARE(ports->size(), 2);
    const journal::PortRecovery &first = ports->at(0);
    QVERIFY(first.device == sampleDevice(0));
    QCOMPARE(first.port, 1);
    QCOMPARE(first.joints, 103);
    QCOMPARE(first.recovered, 100);
    QCOMPARE(first.medianMs, 50);
    QCOMPARE(first.p95Ms, 95);
    const journal::PortRecovery &second = ports->at(1);
    QVERIFY(second.device == sampleDevice(1));
    QCOMPARE(second.port, 2);
    QCOMPARE(second.joints, 1);
    QCOMPARE(second.medianMs, 900);
    QCOMPARE(second.p95Ms, 900);
}

void TestJournalQuery::everyDeviceWithARecordIsListed() {
    const auto devices = m_reader.devices();
    QVERIFY2(devices, qPrintable(devices.error()));
    QCOMPARE(devices->size(), 2);
    QVERIFY(devices->at(0) == sampleDevice(0));
    QVERIFY(devices->at(1) == sampleDevice(1));
}

void TestJournalQuery::aMissingFileIsNotCreatedByAReader() {
    const QString path = m_dir.filePath(QStringLiteral("missing.sqlite"));
    JournalReader reader;
    const auto opened = reader.open(path);
    QVERIFY(!opened);
    QCOMPARE(opened.error(), QStringLiteral("There is no journal at %1.").arg(path));
    QVERIFY(!QFile::exists(path));
    const auto joints = reader.joints({});
    QVERIFY(!joints);
    QCOMPARE(joints.error(), QStringLiteral("No journal is open."));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestJournalQuery)

} // namespace tst_journalquery
#include "tst_journalquery.moc"
