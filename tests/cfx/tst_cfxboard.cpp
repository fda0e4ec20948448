// The per-board CFX messages of one station, against the SDK's names (docs/cfx.md): WorkStarted,
// WorkCompleted and UnitsProcessed share the board's transaction, the hand-soldering structure
// carries each joint as a SolderPoint, and the GenericProcessData carries what it has no field
// for, without inventing a figure the joint does not have.
#include "cfx/cfxboard.h"
#include "journalfixture.h"
#include "testmain.h"

#include <QTest>

namespace tst_cfxboard {

using namespace tipscope;
using namespace tipscope::cfx;

namespace {

journal::StoredJoint stored(int i, qint64 startMs, model::JointVerdict verdict) {
    journal::StoredJoint joint;
    joint.id = i + 1;
    joint.uid = QUuid::createUuid();
    joint.record = testing::sampleJoint(i, startMs);
    joint.record.verdict = verdict;
    joint.context.boardSerial = QStringLiteral("SN-42");
    joint.context.operatorName = QStringLiteral("ana");
    return joint;
}

BoardWork sampleWork(QList<model::JointVerdict> verdicts) {
    BoardWork work;
    work.serial = QStringLiteral("SN-42");
    work.transaction = QUuid::createUuid();
    work.workOrder = QStringLiteral("WO-7");
    work.startedMs = testing::kT0;
    work.finishedMs = testing::kT0 + 60000;
    for (int i = 0; i < verdicts.size(); ++i)
        work.joints.append(stored(i, testing::kT0 + 1000 * (i + 1), verdicts.at(i)));
    return work;
}

QJsonObject readingOf(const QJsonObject &stage, const QString &name) {
    for (const QJsonValue &reading : stage.value(QStringLiteral("Readings")).toArray())
        if (reading.toObject().value(QStringLiteral("Name")).toString() == name)
            return reading.toObject().value(QStringLiteral("Value")).toObject();
    return {};
}

// A port's status change as the station model journals it: the wire's numbers in its details.
journal::StoredEvent statusChange(int port, qint64 timeMs, std::optional<int> from,
                                  std::optional<int> to) {
    journal::StoredEvent event;
    event.record.kind = journal::JournalEvent::Kind::Status;
    event.record.port = port;
    event.record.timeMs = timeMs;
    event.record.text = QStringLiteral("a change");
    if (from)
        event.record.details.insert(QStringLiteral("from"), *from);
    if (to)
        event.record.details.insert(QStringLiteral("to"), *to);
    return event;
}

// The GenericProcessData of the station's UnitsProcessed for `work`.
QJsonObject genericDataOf(const BoardWork &work) {
    return unitsProcessed(work)
        .body.value(QStringLiteral("UnitProcessData"))
        .toArray()
        .at(0)
        .toObject()
        .value(QStringLiteral("UnitProcessData"))
        .toObject();
}

QString parameterOf(const QJsonObject &data, const QString &name) {
    for (const QJsonValue &parameter : data.value(QStringLiteral("Parameters")).toArray())
        if (parameter.toObject().value(QStringLiteral("Name")).toString() == name)
            return parameter.toObject().value(QStringLiteral("Value")).toString();
    return {};
}

} // namespace

class TstCfxBoard : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void theThreeMessagesShareTheTransaction() {
        const BoardWork work = sampleWork({model::JointVerdict::Ok});
        const QString transaction = work.transaction.toString(QUuid::WithoutBraces);
        const Message started = workStarted(work);
        const Message processed = unitsProcessed(work);
        const Message completed = workCompleted(work);
        QCOMPARE(started.name, QStringLiteral("CFX.Production.WorkStarted"));
        QCOMPARE(processed.name, QStringLiteral("CFX.Production.Processing.UnitsProcessed"));
        QCOMPARE(completed.name, QStringLiteral("CFX.Production.WorkCompleted"));
        // The SDK spells it TransactionID in two and TransactionId in the third.
        QCOMPARE(started.body.value(QStringLiteral("TransactionID")).toString(), transaction);
        QCOMPARE(completed.body.value(QStringLiteral("TransactionID")).toString(), transaction);
        QCOMPARE(processed.body.value(QStringLiteral("TransactionId")).toString(), transaction);
        QVERIFY(!processed.body.contains(QStringLiteral("TransactionID")));
        QCOMPARE(started.body.value(QStringLiteral("PrimaryIdentifier")).toString(), work.serial);
        QCOMPARE(started.body.value(QStringLiteral("WorkOrderIdentifier"))
                     .toObject()
                     .value(QStringLiteral("WorkOrderId"))
                     .toString(),
                 QStringLiteral("WO-7"));
        QCOMPARE(started.body.value(QStringLiteral("UnitCount")).toInt(),
                 started.body.value(QStringLiteral("Units")).toArray().size());
    }

    void theResultFollowsTheVerdicts_data() {
        QTest::addColumn<QList<model::JointVerdict>>("verdicts");
        QTest::addColumn<QString>("overall");
        QTest::addColumn<QString>("work");
        using V = model::JointVerdict;
        QTest::newRow("all ok") << QList<V>{V::Ok, V::Ok} << "Succeeded"
                                << "Completed";
        QTest::newRow("one slow") << QList<V>{V::Ok, V::SlowRecovery} << "Failed"
                                  << "Completed";
        QTest::newRow("one too deep and one not judged")
            << QList<V>{V::Incomplete, V::TooDeep} << "Failed"
            << "Completed";
        QTest::newRow("one not judged") << QList<V>{V::Ok, V::Incomplete} << "Error"
                                        << "Completed";
        QTest::newRow("none at this station") << QList<V>{} << "Succeeded"
                                              << "Skipped";
    }
    void theResultFollowsTheVerdicts() {
        QFETCH(QList<model::JointVerdict>, verdicts);
        QFETCH(QString, overall);
        QFETCH(QString, work);
        const BoardWork board = sampleWork(verdicts);
        const QJsonObject body = unitsProcessed(board).body;
        QCOMPARE(body.value(QStringLiteral("OverallResult")).toString(), overall);
        QCOMPARE(body.value(QStringLiteral("UnitProcessData"))
                     .toArray()
                     .at(0)
                     .toObject()
                     .value(QStringLiteral("UnitResult"))
                     .toString(),
                 overall);
        QCOMPARE(workCompleted(board).body.value(QStringLiteral("Result")).toString(), work);
    }

    void eachJointIsASolderPointWithItsTip() {
        const BoardWork work = sampleWork({model::JointVerdict::Ok, model::JointVerdict::TooDeep});
        const QJsonObject common =
            unitsProcessed(work).body.value(QStringLiteral("CommonProcessData")).toObject();
        QCOMPARE(common.value(QStringLiteral("$type")).toString(),
                 QStringLiteral("CFX.Structures.HandSoldering.HandSolderingBoardProcessData, CFX"));
        QCOMPARE(common.value(QStringLiteral("BoardName")).toString(), work.serial);
        QCOMPARE(common.value(QStringLiteral("BoardId")).toString(),
                 boardId(work.serial).toString(QUuid::WithoutBraces));
        QCOMPARE(common.value(QStringLiteral("OrderNumber")).toString(), QStringLiteral("WO-7"));
        const QJsonArray points = common.value(QStringLiteral("SolderPoints")).toArray();
        QCOMPARE(points.size(), 2);
        const QJsonObject second = points.at(1).toObject();
        const model::JointRecord &joint = work.joints.at(1).record;
        QCOMPARE(second.value(QStringLiteral("StartedAt")).toString(),
                 cfxDateTime(QDateTime::fromMSecsSinceEpoch(joint.startMs, Qt::UTC)));
        QCOMPARE(second.value(QStringLiteral("FinishedAt")).toString(),
                 cfxDateTime(QDateTime::fromMSecsSinceEpoch(joint.endMs, Qt::UTC)));
        const QJsonObject tip =
            second.value(QStringLiteral("Materials")).toArray().at(0).toObject();
        QCOMPARE(tip.value(QStringLiteral("Name")).toString(), joint.tool);
        // MaterialType is one of the SDK's enumerations written as a number: 4 is Tip.
        QVERIFY(tip.value(QStringLiteral("Type")).isDouble());
        QCOMPARE(tip.value(QStringLiteral("Type")).toInt(), 4);
        // The journal keeps no readings of the tip: no telemetry is made up.
        QVERIFY(common.value(QStringLiteral("TelemetryData")).isNull());
        // The same board at another station, or in another message, has the same id.
        QCOMPARE(boardId(QStringLiteral("SN-42")), boardId(work.serial));
        QVERIFY(boardId(QStringLiteral("SN-43")) != boardId(work.serial));
    }

    void theJointsFiguresAreInTheGenericProcessData() {
        BoardWork work = sampleWork({model::JointVerdict::Ok, model::JointVerdict::Incomplete});
        work.joints[0].record.recoveryMs = 1250;
        work.joints[0].record.recoveryUncertaintyMs = 40;
        work.joints[0].record.dipDepth = 41.5;
        work.joints[0].record.limits = model::JudgedLimits{5, 4000, 70};
        work.joints[1].record.recoveryMs.reset(); // the tip never came back
        const QJsonObject data = genericDataOf(work);
        QCOMPARE(data.value(QStringLiteral("$type")).toString(),
                 QStringLiteral("CFX.Structures.Generic.GenericProcessData, CFX"));
        QCOMPARE(parameterOf(data, QStringLiteral("BoardSerial")), work.serial);
        QCOMPARE(parameterOf(data, QStringLiteral("BoardResult")), QStringLiteral("not judged"));
        QCOMPARE(parameterOf(data, QStringLiteral("Operator")), QStringLiteral("ana"));
        const QJsonArray stages = data.value(QStringLiteral("StageData")).toArray();
        QCOMPARE(stages.size(), 2);
        const QJsonObject first = stages.at(0).toObject();
        QCOMPARE(first.value(QStringLiteral("Stage"))
                     .toObject()
                     .value(QStringLiteral("StageSequence"))
                     .toInt(),
                 1);
        const QJsonObject recovery = readingOf(first, QStringLiteral("RecoveryTime"));
        QCOMPARE(recovery.value(QStringLiteral("Value")).toDouble(), 1.25);
        QCOMPARE(recovery.value(QStringLiteral("ValueUnits")).toString(), QStringLiteral("s"));
        QCOMPARE(readingOf(first, QStringLiteral("RecoveryTimeUncertainty"))
                     .value(QStringLiteral("Value"))
                     .toDouble(),
                 0.04);
        const QJsonObject dip = readingOf(first, QStringLiteral("DipDepth"));
        QCOMPARE(dip.value(QStringLiteral("Value")).toDouble(), 41.5);
        QCOMPARE(dip.value(QStringLiteral("ValueUnits")).toString(), QStringLiteral("K"));
        // Judged by limits the journal kept: the acceptable range, in the value's units.
        QCOMPARE(dip.value(QStringLiteral("MaximumAcceptableValue")).toDouble(), 70.0);
        QCOMPARE(dip.value(QStringLiteral("MaximumAcceptableValueUnits")).toString(),
                 QStringLiteral("K"));
        QCOMPARE(recovery.value(QStringLiteral("MaximumAcceptableValue")).toDouble(), 4.0);
        QCOMPARE(recovery.value(QStringLiteral("MinimumAcceptableValue")).toDouble(), 0.0);
        QCOMPARE(parameterOf(first, QStringLiteral("Verdict")), QStringLiteral("ok"));
        QCOMPARE(parameterOf(first, QStringLiteral("JointId")),
                 work.joints.at(0).uid.toString(QUuid::WithoutBraces));
        QCOMPARE(parameterOf(first, QStringLiteral("Tool")), work.joints.at(0).record.tool);
        // A joint that never recovered has no recovery reading, and says so.
        const QJsonObject second = stages.at(1).toObject();
        QVERIFY(readingOf(second, QStringLiteral("RecoveryTime")).isEmpty());
        // Journaled before the limits were kept: no range is made up.
        QVERIFY(readingOf(second, QStringLiteral("DipDepth"))
                    .value(QStringLiteral("MaximumAcceptableValue"))
                    .isNull());
        QCOMPARE(parameterOf(second, QStringLiteral("Recovered")), QStringLiteral("false"));
        QCOMPARE(parameterOf(second, QStringLiteral("Verdict")), QStringLiteral("incomplete"));
    }

    // The station's own doing while the board was made: each port's time in each status, from
    // the status it began in (the last change before the board) and its changes during it; the
    // flags beyond the status digit (cooling, suction) change nothing.
    void eachPortsTimeInEachStatusIsInTheGenericProcessData() {
        BoardWork work = sampleWork({model::JointVerdict::Ok});
        work.finishedMs = work.startedMs + 10000;
        const qint64 t0 = work.startedMs;
        work.statusChanges = {
            statusChange(1, t0 - 5000, 1, 0),  // working when the board began
            statusChange(2, t0 + 2000, 11, 0), // in the stand, cooling, until then
            statusChange(1, t0 + 4000, 0, 1),
            statusChange(1, t0 + 7000, 1, 2),
            statusChange(3, t0 + 5000, std::nullopt, std::nullopt), // journaled without numbers
        };
        const QList<PortStatusTimes> times = portStatusTimes(work);
        QCOMPARE(times.size(), 2);
        QCOMPARE(times.at(0).port, 1);
        QCOMPARE(QList<qint64>(times.at(0).ms, times.at(0).ms + 4),
                 (QList<qint64>{4000, 3000, 3000, 0}));
        QCOMPARE(times.at(1).port, 2);
        QCOMPARE(QList<qint64>(times.at(1).ms, times.at(1).ms + 4),
                 (QList<qint64>{8000, 2000, 0, 0}));

        const QJsonObject data = genericDataOf(work);
        const QJsonObject sleeping = readingOf(data, QStringLiteral("Port1SleepTime"));
        QCOMPARE(sleeping.value(QStringLiteral("Value")).toDouble(), 3.0);
        QCOMPARE(sleeping.value(QStringLiteral("ValueUnits")).toString(), QStringLiteral("s"));
        QCOMPARE(readingOf(data, QStringLiteral("Port2WorkingTime"))
                     .value(QStringLiteral("Value"))
                     .toDouble(),
                 8.0);
        QVERIFY(readingOf(data, QStringLiteral("Port3WorkingTime")).isEmpty());
    }
};

TIPSCOPE_TEST_GUILESS_MAIN(TstCfxBoard)

} // namespace tst_cfxboard
#include "tst_cfxboard.moc"
