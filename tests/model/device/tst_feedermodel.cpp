// FeederModel against the simulated SFR: its lists follow the catalog's groups, its values are
// found by role, the feeding commands and the error reset reach the feeder, and error changes
// reach the event log with their level.
#include "model/simfixture.h"
#include "testmain.h"

namespace tst_feedermodel {

using namespace tipscope;
using namespace tipscope::model;
using namespace tipscope::protocol;
using namespace tipscope::testing;

class TestFeederModel : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void listsAreTheCatalogsFeederAndCounterGroups();
    void countersPairIntoRowsWithThePartialsReset();
    void valuesAreFoundByRole();
    void feedingCommandsReachTheFeeder();
    void errorHasItsWordsLevelAndReset();
    void aPartialCounterResetNeedsConfirmationAndItsCode();
};

void TestFeederModel::listsAreTheCatalogsFeederAndCounterGroups() {
    SimFixture f(singleDevice(QStringLiteral("SFR")));
    auto fd = f.feeder();
    QCOMPARE(codesOf(fd->settings()), (QList<QByteArray>{"MOD", "SPD", "LEN", "THI", "TES"}));
    QCOMPARE(codesOf(fd->liveParameters()), (QList<QByteArray>{"FDS", "FDL"}));
    QCOMPARE(codesOf(fd->counters()),
             (QList<QByteArray>{"CPT", "CPP", "CFT", "CFP", "CTT", "CTP"}));
}

void TestFeederModel::countersPairIntoRowsWithThePartialsReset() {
    SimFixture f(singleDevice(QStringLiteral("SFR")));
    auto fd = f.feeder();
    QStringList rows;
    for (const FeederModel::CounterRow &r : fd->counterRows())
        rows.append(QStringLiteral("%1: %2 %3 %4")
                        .arg(r.quantity, QString::fromLatin1(r.total->code()),
                             QString::fromLatin1(r.partial->code()),
                             QString::fromLatin1(r.reset->code())));
    QCOMPARE(rows, (QStringList{"Plugged hours: CPT CPP CPP", "Feeding hours: CFT CFP CFP",
                                "Fed length: CTT CTP CTP"}));
    QVERIFY(fd->counterRows().first().reset->isDangerous());
}

void TestFeederModel::valuesAreFoundByRole() {
    SimFixture f(singleDevice(QStringLiteral("SFR")));
    auto fd = f.feeder();
    QCOMPARE(fd->parameter(Role::FedLength)->code(), QByteArray("FDL"));
    QCOMPARE(fd->parameter(Role::Error)->code(), QByteArray("ECV"));
    QCOMPARE(fd->action(Role::ResetError)->code(), QByteArray("ECV"));
    QVERIFY(!fd->isFeeding()); // not read yet
    fd->refreshAll();
    f.settle();
    QCOMPARE(fd->isFeeding(), std::optional<bool>(false));
    QCOMPARE(fd->feedSpeed(), fd->parameter("SPD")->number());
    QVERIFY(fd->feedSpeed().value_or(0) > 0);
    QCOMPARE(fd->fedLength(), fd->parameter("FDL")->number());
}

void TestFeederModel::feedingCommandsReachTheFeeder() {
    SimFixture f(singleDevice(QStringLiteral("SFR")));
    auto fd = f.feeder();
    QSignalSpy started(fd->action(Role::Start), &Action::finished);
    QVERIFY(started.isValid());
    QCOMPARE(fd->startFeeding(false), QString());
    QVERIFY(started.wait());
    QVERIFY(f.simLine->feeder()->isFeeding());
    QSignalSpy stopped(fd->action(Role::Stop), &Action::finished);
    QVERIFY(stopped.isValid());
    QCOMPARE(fd->stopFeeding(), QString());
    QVERIFY(stopped.wait());
    QVERIFY(!f.simLine->feeder()->isFeeding());
    QSignalSpy loading(fd->action(Role::Loading), &Action::finished);
    QVERIFY(loading.isValid());
    QCOMPARE(fd->setLoading(true), QString());
    QVERIFY(loading.wait());
    QVERIFY2(loading.first().at(0).toBool(), qPrintable(loading.first().at(1).toString()));
}

void TestFeederModel::errorHasItsWordsLevelAndReset() {
    SimFixture f(singleDevice(QStringLiteral("SFR")));
    auto fd = f.feeder();
    EventLog log;
    fd->setEventLog(&log);
    QCOMPARE(fd->errorLevel(), Level::Unknown);
    f.simLine->feeder()->setError(5);
    fd->parameter(Role::Error)->refresh();
    f.settle();
    QCOMPARE(fd->errorCode(), std::optional<int>(5));
    QCOMPARE(fd->errorLevel(), Level::Error);
    QVERIFY(fd->errorText().contains(QStringLiteral("5")));
    QSignalSpy reset(fd->action(Role::ResetError), &Action::finished);
    QVERIFY(reset.isValid());
    QCOMPARE(fd->resetError(), QString());
    QVERIFY(reset.wait());
    QCOMPARE(f.simLine->feeder()->error(), 0);
    fd->parameter(Role::Error)->refresh();
    f.settle();
    QCOMPARE(fd->errorLevel(), Level::Ok);
    QCOMPARE(fd->errorText(), QStringLiteral("No error"));
    QList<Event> errors;
    for (const Event &e : log.events())
        if (e.kind == Event::Kind::FeederError)
            errors.append(e);
    QCOMPARE(errors.size(), 2);
    QCOMPARE(errors.first().severity, Event::Severity::Error);
    QCOMPARE(errors.last().text, QStringLiteral("error cleared"));
}

void TestFeederModel::aPartialCounterResetNeedsConfirmationAndItsCode() {
    SimFixture f(singleDevice(QStringLiteral("SFR")));
    auto fd = f.feeder();
    QVERIFY(!fd->resetPartialCounter("CFP", Confirmation::None).isEmpty());
    QVERIFY(fd->resetPartialCounter("XYZ", Confirmation::Confirmed)
                .contains(QStringLiteral("has no command XYZ")));
    QSignalSpy reset(fd->action("CFP"), &Action::finished);
    QVERIFY(reset.isValid());
    QCOMPARE(fd->resetPartialCounter("CFP", Confirmation::Confirmed), QString());
    QVERIFY(reset.wait());
    QVERIFY(reset.first().at(0).toBool());
}

TIPSCOPE_TEST_GUILESS_MAIN(TestFeederModel)

} // namespace tst_feedermodel
#include "tst_feedermodel.moc"
