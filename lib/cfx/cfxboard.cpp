#include "cfxboard.h"

#include "journal/jointexport.h"

#include <QCoreApplication>

#include <cmath>
#include <map>
#include <optional>

namespace tipscope::cfx {

namespace {

// The SDK's NumericValue, in the UCUM units its own examples use ("Cel", "s").
QJsonObject numericValue(double value, const QString &units) {
    return {{QStringLiteral("Value"), value},
            {QStringLiteral("ValueUnits"), units},
            {QStringLiteral("ExpectedValue"), kCfxNull},
            {QStringLiteral("ExpectedValueUnits"), kCfxNull},
            {QStringLiteral("MinimumAcceptableValue"), kCfxNull},
            {QStringLiteral("MinimumAcceptableValueUnits"), kCfxNull},
            {QStringLiteral("MaximumAcceptableValue"), kCfxNull},
            {QStringLiteral("MaximumAcceptableValueUnits"), kCfxNull}};
}

// A value judged against a limit: acceptable from 0 up to it, in the value's units.
QJsonObject withMaximum(QJsonObject value, double maximum) {
    value.insert(QStringLiteral("MinimumAcceptableValue"), 0.0);
    value.insert(QStringLiteral("MinimumAcceptableValueUnits"),
                 value.value(QStringLiteral("ValueUnits")));
    value.insert(QStringLiteral("MaximumAcceptableValue"), maximum);
    value.insert(QStringLiteral("MaximumAcceptableValueUnits"),
                 value.value(QStringLiteral("ValueUnits")));
    return value;
}

QJsonObject genericValue(const QString &name, const QJsonObject &value) {
    return {{QStringLiteral("Name"), name}, {QStringLiteral("Value"), value}};
}

QJsonObject parameter(const QString &name, const QString &value) {
    return {{QStringLiteral("Name"), name}, {QStringLiteral("Value"), value}};
}

double seconds(qint64 ms) {
    return double(ms) / 1000;
}

// The journal's figures to the hundredth they mean, not to a double's last digit.
double hundredths(double value) {
    return std::round(value * 100) / 100;
}

QString solderPointName(int index, const model::JointRecord &joint) {
    return QStringLiteral("joint %1, port %2").arg(index + 1).arg(joint.port);
}

journal::BoardResult resultOf(const BoardWork &work) {
    QMap<model::JointVerdict, int> verdicts;
    for (const journal::StoredJoint &joint : work.joints)
        ++verdicts[joint.record.verdict];
    return journal::boardResultOf(verdicts);
}

QJsonObject solderPoint(int index, const model::JointRecord &joint) {
    // The tip is the one material TipScope knows of (MaterialType Tip, written as a number).
    QJsonValue materials = kCfxNull;
    if (!joint.tool.isEmpty())
        materials = QJsonArray{QJsonObject{{QStringLiteral("Name"), joint.tool},
                                           {QStringLiteral("Type"), 4},
                                           {QStringLiteral("CustomMaterial"), kCfxNull}}};
    return {{QStringLiteral("Name"), solderPointName(index, joint)},
            {QStringLiteral("Component"), kCfxNull},
            {QStringLiteral("Materials"), materials},
            {QStringLiteral("StartedAt"), journal::utcText(joint.startMs)},
            {QStringLiteral("FinishedAt"), journal::utcText(joint.endMs)},
            {QStringLiteral("SetSolderingPosition"), kCfxNull},
            {QStringLiteral("ReadSolderingPosition"), kCfxNull},
            {QStringLiteral("ResultPicture"), kCfxNull}};
}

// The SDK's hand-soldering structure. TelemetryData (a list since CFX 2.1) stays null: the
// journal keeps each joint's figures, not the tip's readings (docs/cfx.md).
QJsonObject handSolderingData(const BoardWork &work) {
    QJsonArray points;
    for (int i = 0; i < work.joints.size(); ++i)
        points.append(solderPoint(i, work.joints.at(i).record));
    const qint64 started =
        work.joints.isEmpty() ? work.startedMs : work.joints.first().record.startMs;
    const qint64 finished =
        work.joints.isEmpty() ? work.finishedMs : work.joints.last().record.endMs;
    return {{QStringLiteral("$type"),
             QStringLiteral("CFX.Structures.HandSoldering.HandSolderingBoardProcessData, CFX")},
            {QStringLiteral("BoardId"), boardId(work.serial).toString(QUuid::WithoutBraces)},
            {QStringLiteral("BoardName"), work.serial},
            {QStringLiteral("StartedAt"), journal::utcText(started)},
            {QStringLiteral("FinishedAt"), journal::utcText(finished)},
            {QStringLiteral("SolderPoints"), points},
            {QStringLiteral("TelemetryData"), kCfxNull},
            {QStringLiteral("File"), kCfxNull},
            {QStringLiteral("OrderNumber"), cfxText(work.workOrder)}};
}

// One joint as a GenericStageData: what a SolderPoint has no field for.
QJsonObject jointStage(int index, const journal::StoredJoint &stored) {
    const model::JointRecord &joint = stored.record;
    const QJsonObject stage{{QStringLiteral("StageSequence"), index + 1},
                            {QStringLiteral("StageName"), solderPointName(index, joint)},
                            {QStringLiteral("StageType"), QStringLiteral("Work")}};
    // The limits the verdict was judged by, where the journal kept them (not before schema 6).
    QJsonObject dip = numericValue(hundredths(joint.dipDepth), QStringLiteral("K"));
    QJsonArray setpoints{genericValue(QStringLiteral("TipTemperature"),
                                      numericValue(joint.setpoint, QStringLiteral("Cel")))};
    if (joint.limits) {
        dip = withMaximum(dip, joint.limits->maxDipK);
        // Within this of the setpoint the tip counts as recovered.
        setpoints.append(genericValue(QStringLiteral("RecoveryBand"),
                                      numericValue(joint.limits->bandK, QStringLiteral("K"))));
    }
    QJsonArray readings{
        genericValue(QStringLiteral("DipDepth"), dip),
        genericValue(QStringLiteral("DipDepthUncertainty"),
                     numericValue(hundredths(joint.dipUncertaintyK), QStringLiteral("K"))),
        genericValue(QStringLiteral("LowestTipTemperature"),
                     numericValue(hundredths(joint.lowestTip), QStringLiteral("Cel"))),
        genericValue(QStringLiteral("StartTimeUncertainty"),
                     numericValue(seconds(joint.startUncertaintyMs), QStringLiteral("s"))),
        genericValue(QStringLiteral("Duration"),
                     numericValue(seconds(joint.durationMs), QStringLiteral("s"))),
        genericValue(QStringLiteral("PowerPeak"),
                     numericValue(joint.powerPeak, QStringLiteral("%"))),
        genericValue(QStringLiteral("PowerIntegral"),
                     numericValue(hundredths(joint.powerIntegral), QStringLiteral("%.s")))};
    // A tip that never came back has no recovery time: no reading, rather than an invented one.
    if (joint.recoveryMs) {
        QJsonObject recovery = numericValue(seconds(*joint.recoveryMs), QStringLiteral("s"));
        if (joint.limits)
            recovery = withMaximum(recovery, seconds(joint.limits->maxRecoveryMs));
        readings.append(genericValue(QStringLiteral("RecoveryTime"), recovery));
        readings.append(
            genericValue(QStringLiteral("RecoveryTimeUncertainty"),
                         numericValue(seconds(joint.recoveryUncertaintyMs), QStringLiteral("s"))));
    }
    const QJsonArray parameters{
        parameter(QStringLiteral("JointId"), stored.uid.toString(QUuid::WithoutBraces)),
        parameter(QStringLiteral("Verdict"), model::jointVerdictName(joint.verdict)),
        parameter(QStringLiteral("Recovered"),
                  joint.recoveryMs ? QStringLiteral("true") : QStringLiteral("false")),
        // Bounded: the recovery lies somewhere in RecoveryTime ± its uncertainty (docs/joints.md).
        parameter(QStringLiteral("RecoveryBounded"),
                  joint.recoveryBounded ? QStringLiteral("true") : QStringLiteral("false")),
        parameter(QStringLiteral("Port"), QString::number(joint.port)),
        parameter(QStringLiteral("Tool"), joint.tool),
        parameter(QStringLiteral("StartedAt"), journal::utcText(joint.startMs))};
    return {{QStringLiteral("Stage"), stage},
            {QStringLiteral("Setpoints"), setpoints},
            {QStringLiteral("Readings"), readings},
            {QStringLiteral("Parameters"), parameters}};
}

// The station's own doing while the board was made: each port's time in each status.
QJsonArray statusReadings(const BoardWork &work) {
    static const char *const kStatus[] = {"Working", "Stand", "Sleep", "Hibernation"};
    QJsonArray readings;
    for (const PortStatusTimes &times : portStatusTimes(work))
        for (int s = 0; s < 4; ++s)
            readings.append(genericValue(
                QStringLiteral("Port%1%2Time").arg(times.port).arg(QLatin1String(kStatus[s])),
                numericValue(seconds(times.ms[s]), QStringLiteral("s"))));
    return readings;
}

QJsonObject genericData(const BoardWork &work) {
    QJsonArray stages;
    for (int i = 0; i < work.joints.size(); ++i)
        stages.append(jointStage(i, work.joints.at(i)));
    QJsonArray parameters{
        parameter(QStringLiteral("BoardSerial"), work.serial),
        parameter(QStringLiteral("BoardResult"), journal::boardResultName(resultOf(work))),
        parameter(QStringLiteral("Joints"), QString::number(work.joints.size())),
        parameter(QStringLiteral("Software"),
                  QStringLiteral("%1 %2").arg(QCoreApplication::applicationName(),
                                              QCoreApplication::applicationVersion()))};
    if (!work.workOrder.isEmpty())
        parameters.append(parameter(QStringLiteral("WorkOrder"), work.workOrder));
    QStringList operators;
    for (const journal::StoredJoint &joint : work.joints)
        if (!joint.context.operatorName.isEmpty() &&
            !operators.contains(joint.context.operatorName))
            operators.append(joint.context.operatorName);
    if (!operators.isEmpty())
        parameters.append(
            parameter(QStringLiteral("Operator"), operators.join(QStringLiteral(", "))));
    return {
        {QStringLiteral("$type"), QStringLiteral("CFX.Structures.Generic.GenericProcessData, CFX")},
        {QStringLiteral("Setpoints"), QJsonArray()},
        {QStringLiteral("Readings"), statusReadings(work)},
        {QStringLiteral("Parameters"), parameters},
        {QStringLiteral("StageData"), stages}};
}

} // namespace

QList<PortStatusTimes> portStatusTimes(const BoardWork &work) {
    struct Walk {
        PortStatusTimes times;
        std::optional<int> status; // the status digit since `sinceMs`
        qint64 sinceMs = 0;
    };
    std::map<int, Walk> ports;
    const auto digit = [](const QJsonValue &v) {
        return v.isDouble() ? std::optional<int>(int(v.toDouble()) % 10) : std::nullopt;
    };
    for (const journal::StoredEvent &stored : work.statusChanges) {
        const journal::JournalEvent &event = stored.record;
        const std::optional<int> from = digit(event.details.value(QStringLiteral("from")));
        const std::optional<int> to = digit(event.details.value(QStringLiteral("to")));
        if (!event.port || !to || *to < 0 || *to > 3)
            continue;
        Walk &walk = ports[*event.port];
        walk.times.port = *event.port;
        const qint64 at = qBound(work.startedMs, event.timeMs, work.finishedMs);
        // The status before this change: the one the last change went to, or this one's "from".
        const std::optional<int> before = walk.status ? walk.status : from;
        const qint64 since = walk.status ? walk.sinceMs : work.startedMs;
        if (before && *before >= 0 && *before <= 3 && at > since)
            walk.times.ms[*before] += at - since;
        walk.status = to;
        walk.sinceMs = at;
    }
    QList<PortStatusTimes> out;
    for (auto &[port, walk] : ports) {
        walk.times.ms[*walk.status] += work.finishedMs - walk.sinceMs;
        out.append(walk.times);
    }
    return out;
}

QString processingResultOf(journal::BoardResult result) {
    switch (result) {
    case journal::BoardResult::Fail:
        return QStringLiteral("Failed");
    case journal::BoardResult::NotJudged:
        return QStringLiteral("Error");
    case journal::BoardResult::Pass:
    case journal::BoardResult::NoJoints:
        break;
    }
    return QStringLiteral("Succeeded");
}

QUuid boardId(const QString &serial) {
    // A fixed namespace of TipScope's own: the id depends on the serial alone.
    static const QUuid kBoards(QStringLiteral("{6f1c2a52-8a0e-4c55-9a43-3c0b1f7d2e91}"));
    return QUuid::createUuidV5(kBoards, serial);
}

Message workStarted(const BoardWork &work) {
    QJsonValue workOrder = kCfxNull;
    if (!work.workOrder.isEmpty())
        workOrder = QJsonObject{{QStringLiteral("WorkOrderId"), work.workOrder},
                                {QStringLiteral("Batch"), kCfxNull}};
    // The board is named by PrimaryIdentifier; Units stays empty, as TipScope knows no position.
    return {QStringLiteral("CFX.Production.WorkStarted"),
            {{QStringLiteral("PrimaryIdentifier"), work.serial},
             {QStringLiteral("HermesIdentifier"), kCfxNull},
             {QStringLiteral("TransactionID"), work.transaction.toString(QUuid::WithoutBraces)},
             {QStringLiteral("Lane"), kCfxNull},
             {QStringLiteral("UnitCount"), 0},
             {QStringLiteral("Units"), QJsonArray()},
             {QStringLiteral("RecipeName"), kCfxNull},
             {QStringLiteral("Revision"), kCfxNull},
             {QStringLiteral("RelevantSurface"), QStringLiteral("Unspecified")},
             {QStringLiteral("WorkOrderIdentifier"), workOrder}}};
}

Message workCompleted(const BoardWork &work) {
    return {QStringLiteral("CFX.Production.WorkCompleted"),
            {{QStringLiteral("TransactionID"), work.transaction.toString(QUuid::WithoutBraces)},
             {QStringLiteral("Result"),
              work.joints.isEmpty() ? QStringLiteral("Skipped") : QStringLiteral("Completed")},
             {QStringLiteral("PrimaryIdentifier"), work.serial},
             {QStringLiteral("HermesIdentifier"), kCfxNull},
             {QStringLiteral("UnitCount"), 0},
             {QStringLiteral("Units"), QJsonArray()},
             {QStringLiteral("PerformanceImpacts"), kCfxNull}}};
}

Message unitsProcessed(const BoardWork &work) {
    const QString result = processingResultOf(resultOf(work));
    const QJsonObject unit{{QStringLiteral("UnitIdentifier"), work.serial},
                           {QStringLiteral("UnitPositionNumber"), kCfxNull},
                           {QStringLiteral("UnitResult"), result},
                           {QStringLiteral("UnitProcessData"), genericData(work)}};
    return {QStringLiteral("CFX.Production.Processing.UnitsProcessed"),
            {{QStringLiteral("TransactionId"), work.transaction.toString(QUuid::WithoutBraces)},
             {QStringLiteral("OverallResult"), result},
             {QStringLiteral("CommonProcessData"), handSolderingData(work)},
             {QStringLiteral("UnitProcessData"), QJsonArray{unit}}}};
}

} // namespace tipscope::cfx
