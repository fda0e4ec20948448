// A station's condition for CFX's StationStateChanged, from its live model against the simulator:
// unknown before any status was read, the most active port otherwise, an error before that and a
// lost link before all; the watcher says each change once, and how long the old condition lasted
// only when it saw that condition begin.
#include "cfx/stationstate.h"
#include "model/simfixture.h"
#include "testmain.h"

namespace tst_stationstate {

using namespace tipscope;
using namespace tipscope::cfx;
using namespace tipscope::testing;
using protocol::Role;

namespace {

constexpr int kWorking = 0, kStand = 1, kSleep = 2, kHibernation = 3;

void readStatuses(SimFixture &f, model::StationModel &station) {
    for (model::PortModel *port : station.ports()) {
        port->parameter(Role::Status)->refresh();
        port->parameter(Role::Error)->refresh();
    }
    station.setLineUp(true);
    f.settle();
}

} // namespace

class TstStationState : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void theMostActivePortIsTheStations_data() {
        QTest::addColumn<QList<int>>("modes");
        QTest::addColumn<StationCondition>("condition");
        QTest::newRow("one tool out of its stand")
            << QList<int>{kStand, kWorking, kSleep, kStand} << StationCondition::Working;
        QTest::newRow("in the stand beside one asleep")
            << QList<int>{kSleep, kStand, kHibernation, kSleep} << StationCondition::InStand;
        QTest::newRow("asleep beside one hibernating")
            << QList<int>{kHibernation, kSleep, kHibernation, kHibernation}
            << StationCondition::Sleep;
        QTest::newRow("every one hibernating")
            << QList<int>{kHibernation, kHibernation, kHibernation, kHibernation}
            << StationCondition::Hibernation;
    }
    void theMostActivePortIsTheStations() {
        QFETCH(QList<int>, modes);
        QFETCH(StationCondition, condition);
        SimFixture f(singleDevice(QStringLiteral("DME")));
        auto station = f.station();
        QCOMPARE(conditionOf(*station), std::nullopt); // nothing read yet
        for (int port = 1; port <= modes.size(); ++port)
            f.simLine->station()->setStatus(port, modes.at(port - 1));
        readStatuses(f, *station);
        QCOMPARE(conditionOf(*station), std::optional(condition));
    }

    void anErrorComesFirstAndALostLinkBeforeIt() {
        SimFixture f(singleDevice(QStringLiteral("DME")));
        auto station = f.station();
        f.simLine->station()->setStatus(1, kWorking);
        f.simLine->station()->setPortError(2, 9); // a warning: the station still works
        readStatuses(f, *station);
        QCOMPARE(conditionOf(*station), std::optional(StationCondition::Working));
        f.simLine->station()->setPortError(2, 1); // short circuit
        readStatuses(f, *station);
        QCOMPARE(conditionOf(*station), std::optional(StationCondition::Error));
        station->setLineUp(false); // what it said last is no longer known
        QCOMPARE(conditionOf(*station), std::optional(StationCondition::LinkLost));
    }

    void theWatcherSaysEachChangeOnce() {
        SimFixture f(singleDevice(QStringLiteral("DME")));
        auto station = f.station();
        StationStateWatcher watcher(*station);
        QSignalSpy changes(&watcher, &StationStateWatcher::changed);
        for (int port = 1; port <= 4; ++port)
            f.simLine->station()->setStatus(port, kStand);
        readStatuses(f, *station);
        QCOMPARE(watcher.condition(), std::optional(StationCondition::InStand));
        QCOMPARE(changes.size(), 0); // the first reading is no change
        f.simLine->station()->setStatus(3, kWorking);
        readStatuses(f, *station);
        QCOMPARE(changes.size(), 1);
        QCOMPARE(changes.at(0).at(0).value<StationCondition>(), StationCondition::InStand);
        // In the stand since before the watcher looked: how long is not known.
        QCOMPARE(changes.at(0).at(1).value<std::optional<qint64>>(), std::nullopt);
        QCOMPARE(changes.at(0).at(2).value<StationCondition>(), StationCondition::Working);
        readStatuses(f, *station); // the same again: no change
        QCOMPARE(changes.size(), 1);
        f.simLine->station()->setStatus(3, kStand);
        readStatuses(f, *station);
        QCOMPARE(changes.size(), 2);
        QVERIFY(changes.at(1).at(1).value<std::optional<qint64>>().has_value());
    }
};

TIPSCOPE_TEST_GUILESS_MAIN(TstStationState)

} // namespace tst_stationstate
#include "tst_stationstate.moc"
