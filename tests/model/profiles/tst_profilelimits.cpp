// Profile limits against a simulated DME: a profile that would leave MIT <= STx <= MAT broken,
// within itself or against what the device holds, is refused with every broken bound named and
// where each value comes from; a value the device did not answer is not taken as current; and a
// profile that keeps the limits is written in an order that keeps them after every single write.
#include "model/profiles/profilelimits.h"
#include "model/simfixture.h"
#include "testmain.h"

#include "model/device/parameter.h"

namespace tst_profilelimits {

using namespace tipscope;
using namespace tipscope::model;
using namespace tipscope::protocol;
using namespace tipscope::testing;

namespace {
Profile profileOf(const DeviceModel &device, const QList<QPair<QByteArray, qint64>> &values) {
    Profile profile;
    profile.family = device.family();
    for (const auto &[code, value] : values)
        profile.values.append({code, *encodeWrite(device.parameter(code)->spec(), value)});
    return profile;
}

// The device's value of `code` once `profile` is applied.
qint64 endValue(const Profile &profile, const DeviceModel &device, const QByteArray &code) {
    for (const auto &[c, data] : profile.values)
        if (c == code)
            return decodeAnswer(device.parameter(code)->spec(), data)->number;
    return *device.parameter(code)->number();
}
} // namespace

class TestProfileLimits : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void aProfileThatKeepsTheLimitsHasNoConflict();
    void aBoundBrokenWithinTheProfileIsNamed();
    void aBoundBrokenAgainstTheDeviceIsNamed();
    void aValueTheDeviceDidNotAnswerIsNotTakenAsCurrent();
    void theWritesKeepTheLimitsAfterEachOne();

private:
    // Reads what the check needs and returns the device's values of MIT, MAT and ST1.
    void readFor(const Profile &profile);
    std::unique_ptr<SimFixture> m_fixture;
    std::unique_ptr<StationModel> m_station;
};

void TestProfileLimits::init() {
    m_fixture = std::make_unique<SimFixture>(singleDevice(QStringLiteral("DME")));
    m_station = m_fixture->station();
}

void TestProfileLimits::cleanup() {
    m_station.reset();
    m_fixture.reset();
}

void TestProfileLimits::readFor(const Profile &profile) {
    for (const QByteArray &code : limitRelatedCodes(profile, *m_station))
        m_station->parameter(code)->refresh();
    m_fixture->settle();
}

void TestProfileLimits::aProfileThatKeepsTheLimitsHasNoConflict() {
    const Profile profile = profileOf(*m_station, {{"ST1", 380}, {"MAT", 450}});
    const QList<QByteArray> related = limitRelatedCodes(profile, *m_station);
    for (const char *code : {"ST1", "MAT", "MIT", "ST2"}) // every port's setpoint is bound by MAT
        QVERIFY2(related.contains(code), code);
    readFor(profile);
    QCOMPARE(limitConflicts(profile, *m_station), QStringList());
}

void TestProfileLimits::aBoundBrokenWithinTheProfileIsNamed() {
    const Profile profile = profileOf(*m_station, {{"MAT", 400}, {"ST1", 450}});
    readFor(profile);
    const QStringList conflicts = limitConflicts(profile, *m_station);
    QCOMPARE(conflicts, QStringList{QStringLiteral(
                            "ST1 450 °C (in the profile) is above MAT 400 °C (in the profile)")});
}

void TestProfileLimits::aBoundBrokenAgainstTheDeviceIsNamed() {
    readFor(profileOf(*m_station, {{"MAT", 450}}));
    const qint64 setpoint = *m_station->parameter("ST1")->number();
    const Profile profile = profileOf(*m_station, {{"MAT", setpoint - 50}});
    const QStringList conflicts = limitConflicts(profile, *m_station);
    QVERIFY2(conflicts.contains(QStringLiteral("ST1 %1 °C (on the device now) is above MAT %2 °C "
                                               "(in the profile)")
                                    .arg(setpoint)
                                    .arg(setpoint - 50)),
             qPrintable(conflicts.join('\n')));
}

void TestProfileLimits::aValueTheDeviceDidNotAnswerIsNotTakenAsCurrent() {
    const Profile profile = profileOf(*m_station, {{"MAT", 450}});
    readFor(profile);
    // ST1 was read once (a poll, say), but its read for this check failed.
    const QStringList conflicts = limitConflicts(profile, *m_station, {"ST1"});
    QVERIFY2(conflicts.contains(QStringLiteral("ST1 is not known (the device did not answer), so "
                                               "MAT cannot be checked against it")),
             qPrintable(conflicts.join('\n')));
}

// From MAT 450, ST1 350 to MIT 300, MAT 480, ST1 470: ST1 first would sit above MAT, so MAT
// widens first, then ST1, then MIT narrows (the other ports stay at 350, above the new MIT).
void TestProfileLimits::theWritesKeepTheLimitsAfterEachOne() {
    Parameter *maximum = m_station->parameter("MAT");
    QSignalSpy written(maximum, &Parameter::writeFinished);
    QCOMPARE(maximum->setEdit(450), QString());
    maximum->apply();
    QVERIFY(written.wait(10000));
    QVERIFY2(written.first().at(0).toBool(), qPrintable(written.first().at(1).toString()));
    const Profile profile = profileOf(*m_station, {{"MIT", 300}, {"ST1", 470}, {"MAT", 480}});
    readFor(profile);
    QCOMPARE(*m_station->parameter("ST1")->number(), 350);
    QCOMPARE(limitConflicts(profile, *m_station), QStringList());
    const QList<QByteArray> codes{"MIT", "ST1", "MAT"};
    const QList<QByteArray> order = limitSafeOrder(codes, profile, *m_station);
    QCOMPARE(order, (QList<QByteArray>{"MAT", "ST1", "MIT"}));
    // Every state in between keeps MIT <= ST1 <= MAT.
    QMap<QByteArray, qint64> state;
    for (const QByteArray &code : codes)
        state[code] = *m_station->parameter(code)->number();
    for (const QByteArray &code : order) {
        state[code] = endValue(profile, *m_station, code);
        QVERIFY2(state["MIT"] <= state["ST1"] && state["ST1"] <= state["MAT"],
                 qPrintable(QStringLiteral("after %1: MIT %2, ST1 %3, MAT %4")
                                .arg(QString::fromLatin1(code))
                                .arg(state["MIT"])
                                .arg(state["ST1"])
                                .arg(state["MAT"])));
    }
}

TIPSCOPE_TEST_MAIN(TestProfileLimits)

} // namespace tst_profilelimits
#include "tst_profilelimits.moc"
