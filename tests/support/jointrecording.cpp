#include "jointrecording.h"

#include "model/chart/chartevents.h"
#include "model/recording/chartcsv.h"

#include <QFile>
#include <cmath>
#include <random>

namespace tipscope::testing {

namespace {
constexpr qint64 kStartMs = 1'780'000'000'000; // 2026-05-28, a fixed instant
constexpr qint64 kLengthMs = 120'000;
constexpr int kSetpoint = 350;
constexpr int kPorts = 4;
// Status numbers as the station gives them (PortStatus::fromNumber()).
constexpr int kWorking = 0;
constexpr int kStand = 1;
// The power series in wire units (‰): holding the tip, and fighting a joint.
constexpr int kIdlePower = 60;
constexpr int kJointPower = 850;

struct Planned {
    qint64 atMs; // from the recording's start
    sim::JointSpec spec;
};

// Per port, the joints it makes; every kind of joint the detector must measure.
QList<QList<Planned>> plannedJoints() {
    using sim::RecoveryForm;
    return {
        {{3'000, {40, 1'200, 0, RecoveryForm::Exponential, 0}},
         {12'000, {90, 3'400, 150, RecoveryForm::Exponential, 0}},
         {24'000, {25, 700, 60, RecoveryForm::Linear, 0}},
         {25'900, {30, 900, 0, RecoveryForm::Exponential, 0}}, // within 1.5 s of the one before
         {50'000, {60, 2'000, 0, RecoveryForm::Exponential, 3}},
         {80'000, {110, 5'500, 400, RecoveryForm::Exponential, 0}},
         {100'000, {15, 400, 50, RecoveryForm::Linear, 0}}},
        {{5'000, {35, 1'000, 0, RecoveryForm::Exponential, 2}},
         {30'000, {70, 2'600, 0, RecoveryForm::Linear, 0}},
         {64'000, {50, 1'500, 300, RecoveryForm::Exponential, 0}},
         {kLengthMs - 350, {80, 3'000, 0, RecoveryForm::Exponential, 0}}}, // still going at the end
        {{8'000, {45, 1'800, 0, RecoveryForm::Exponential, 0}},
         {52'000, {55, 2'200, 0, RecoveryForm::Linear, 1}}, // after port 3's gap
         {90'000, {20, 600, 0, RecoveryForm::Exponential, 0}}},
        {{10'000, {65, 2'400, 0, RecoveryForm::Exponential, 0}},
         {95'000, {30, 1'100, 0, RecoveryForm::Linear, 0}}},
    };
}

// Port 3 stops answering for these six seconds; port 4 rests in its stand for fifteen.
constexpr qint64 kGapPort = 3, kGapFromMs = 40'000, kGapToMs = 46'000;
constexpr qint64 kRestPort = 4, kRestFromMs = 60'000, kRestToMs = 75'000;

// The tip in its stand: it cools towards the stand's temperature, then heats back once lifted.
double restingTip(qint64 ms) {
    if (ms < kRestToMs)
        return 200 + (kSetpoint - 200) * std::exp(-double(ms - kRestFromMs) / 4'000.0);
    const double cooled =
        200 + (kSetpoint - 200) * std::exp(-double(kRestToMs - kRestFromMs) / 4'000.0);
    return qMin<double>(kSetpoint, cooled + double(ms - kRestToMs) * 0.08);
}
} // namespace

bool writeJointRecording(const QString &path, RecordedJoints *truth, QString *error) {
    model::Telemetry telemetry;
    QList<model::ChartChannel> channels;
    const QStringList series = {QStringLiteral("tip"), QStringLiteral("setpoint"),
                                QStringLiteral("power"), QStringLiteral("status")};
    for (int port = 1; port <= kPorts; ++port) {
        model::ChartChannel c;
        c.id = QStringLiteral("port%1").arg(port);
        c.key = c.id;
        c.port = port;
        c.title = QStringLiteral("Port %1").arg(port);
        c.deviceModel = QStringLiteral("DDE-4C");
        c.deviceName = QStringLiteral("DDE-4C at 01");
        c.address = QStringLiteral("01");
        c.softwareVersion = QStringLiteral("9996780");
        c.tool = port % 2 ? QStringLiteral("T245") : QStringLiteral("T210");
        c.series = series;
        channels.append(c);
        telemetry.ensureBuffer(c.key, series);
    }
    std::mt19937 random(20261206);
    std::uniform_int_distribution<int> spacing(70, 130);
    std::uniform_int_distribution<int> wobble(-1, 1);
    const QList<QList<Planned>> planned = plannedJoints();
    *truth = {};
    truth->firstMs = kStartMs;
    for (int port = 1; port <= kPorts; ++port) {
        const QList<Planned> &joints = planned.at(port - 1);
        const QString &key = channels.at(port - 1).key;
        for (const Planned &p : joints) {
            sim::SimJoint made;
            const sim::JointShape shape(p.spec);
            made.port = port;
            made.startMs = kStartMs + p.atMs + qint64(shape.leaveMs());
            made.depthK = shape.depthK();
            made.recoveryMs = p.spec.recoveryMs;
            made.dropMs = p.spec.dropMs;
            made.form = p.spec.form;
            made.overshootK = p.spec.overshootK;
            truth->made.append(made);
        }
        bool gapMarked = false;
        for (qint64 ms = spacing(random); ms < kLengthMs; ms += spacing(random)) {
            if (port == kGapPort && ms >= kGapFromMs && ms < kGapToMs) {
                if (!gapMarked)
                    telemetry.markGap(key, kStartMs + kGapFromMs,
                                      model::TelemetryGap::Cause::NoAnswer);
                gapMarked = true;
                continue;
            }
            double tip = kSetpoint + wobble(random);
            int power = kIdlePower;
            int status = kWorking;
            for (const Planned &p : joints) {
                const sim::JointShape shape(p.spec);
                const double since = double(ms - p.atMs);
                if (since >= 0 && !shape.isOver(since)) {
                    tip = kSetpoint - shape.belowTargetK(since);
                    power = kJointPower;
                }
            }
            if (port == kRestPort && ms >= kRestFromMs && ms < kRestToMs + 3'000) {
                tip = restingTip(ms);
                status = ms < kRestToMs ? kStand : kWorking;
                power = status == kStand ? 0 : kJointPower;
            }
            telemetry.append(key, kStartMs + ms,
                             {qint32(std::lround(tip)), kSetpoint, power, status});
            ++truth->samples;
            truth->lastMs = qMax(truth->lastMs, kStartMs + ms);
        }
    }
    std::sort(truth->made.begin(), truth->made.end(),
              [](const sim::SimJoint &a, const sim::SimJoint &b) { return a.startMs < b.startMs; });

    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate)) {
        *error = file.errorString();
        return false;
    }
    model::ChartCsvWriter writer(file, channels, model::TemperatureUnit::Celsius);
    const model::ChartEvents events;
    if (!writer.writeHeader(QStringLiteral("test")) ||
        !writer.writeWindow(telemetry, events, kStartMs, truth->lastMs + 1)) {
        *error = writer.errorString();
        return false;
    }
    return true;
}

} // namespace tipscope::testing
