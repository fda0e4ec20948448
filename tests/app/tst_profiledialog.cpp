// ProfileDialog against a simulated station: a profile that would break the device's limits says
// why at the top, where the eye is, and writes nothing; a profile of another family is compared
// all the same, greyed, its skipped settings named with the reason, until "apply anyway" is
// ticked, which compares again; after an apply the table shows the device as it now is; every
// row names its setting's tool and port.
#include "../model/simfixture.h"
#include "dialogs/profiledialog.h"
#include "testmain.h"

#include <QTest>

namespace tst_profiledialog {

using namespace tipscope;
using tipscope::gui::ProfileDialog;

class TestProfileDialog : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aProfileThatBreaksTheLimitsSaysWhyAtTheTopAndWritesNothing();
    void anotherFamilysProfileIsComparedGreyedWithItsSkippedSettingsNamed();
    void afterAnApplyTheTableShowsTheDeviceAsItNowIs();
};

void TestProfileDialog::aProfileThatBreaksTheLimitsSaysWhyAtTheTopAndWritesNothing() {
    testing::SimFixture f(testing::singleDevice(QStringLiteral("DME")));
    sim::SimDevice &dev = *f.simLine->devices().first();
    dev.setSetting("MAT", 500);
    dev.setSetting("ST1", 450);
    auto station = f.station();
    const auto profile = model::Profile::fromJson(
        R"({"format":"tipscope-profile","schema":1,"family":"DME",
            "values":{"MAT":"00400","A11":"00005"}})");
    QVERIFY2(profile.ok(), qPrintable(profile.error()));
    ProfileDialog dialog(*station, *profile);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    QTRY_VERIFY_WITH_TIMEOUT(!dialog.isRunning(), 20000);
    const QString why = QStringLiteral("ST1 450 °C (on the device now) is above MAT 400 °C (in "
                                       "the profile)");
    QVERIFY2(dialog.summaryText().contains(QStringLiteral("cannot be applied")) &&
                 dialog.summaryText().contains(why),
             qPrintable(dialog.summaryText()));
    QCOMPARE(dialog.differenceRows(), 2); // the difference is still shown below
    QVERIFY(!dialog.canApply());

    dialog.run(model::ProfileApplier::Mode::Apply); // as a shortcut or a script would
    QTRY_VERIFY_WITH_TIMEOUT(!dialog.isRunning(), 20000);
    QVERIFY2(dialog.summaryText().contains(QStringLiteral("Refused")) &&
                 dialog.summaryText().contains(why),
             qPrintable(dialog.summaryText()));
    f.settle();
    QCOMPARE(f.simLine->stats().writeRequests, 0);

    dev.setSetting("ST1", 350); // the technician lowers ST1 first, then compares again
    dialog.run(model::ProfileApplier::Mode::Diff);
    QTRY_VERIFY_WITH_TIMEOUT(!dialog.isRunning(), 20000);
    QVERIFY2(!dialog.summaryText().contains(QStringLiteral("cannot be applied")),
             qPrintable(dialog.summaryText()));
    QVERIFY(dialog.canApply());
}

void TestProfileDialog::anotherFamilysProfileIsComparedGreyedWithItsSkippedSettingsNamed() {
    // No translator is loaded here, so the plural reads "setting(s)".
    const QString kTwoSkipped = QStringLiteral("2 setting(s) of the profile skipped");
    testing::SimFixture f(testing::singleDevice(QStringLiteral("DDR")));
    f.simLine->devices().first()->setSetting("ST1", 350);
    auto station = f.station();
    const auto profile = model::Profile::fromJson(
        R"({"format":"tipscope-profile","schema":1,"family":"DME",
            "values":{"ST1":"00300","ST4":"00300","S17":"00200"}})");
    QVERIFY2(profile.ok(), qPrintable(profile.error()));
    ProfileDialog dialog(*station, *profile);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    QTRY_VERIFY_WITH_TIMEOUT(!dialog.isRunning(), 20000);
    QVERIFY2(dialog.summaryText().contains(QStringLiteral("Refused")) &&
                 dialog.summaryText().contains(kTwoSkipped),
             qPrintable(dialog.summaryText()));
    QVERIFY(dialog.isTableGreyed());
    QVERIFY(!dialog.canApply());
    QCOMPARE(dialog.differenceRows(), 3); // ST1 differs; S17 (tool 7) and ST4 (port 4) are skipped
    QCOMPARE(dialog.cellText(0, 0), QStringLiteral("Selected temperature, port 1 (ST1)"));
    QCOMPARE(dialog.cellText(0, 1), QStringLiteral("350 °C"));
    QCOMPARE(dialog.cellText(0, 2), QStringLiteral("300 °C"));
    QCOMPARE(dialog.cellText(1, 0), QStringLiteral("Sleep temperature, NT115, port 1 (S17)"));
    QVERIFY2(dialog.cellText(1, 3).startsWith(QStringLiteral("skipped: ")) &&
                 dialog.cellText(1, 3).contains(QStringLiteral("DDR")),
             qPrintable(dialog.cellText(1, 3)));
    QCOMPARE(dialog.cellText(2, 0), QStringLiteral("Selected temperature, port 4 (ST4)"));

    dialog.setForce(true); // ticking the box compares again
    QTRY_VERIFY_WITH_TIMEOUT(!dialog.isRunning(), 20000);
    QVERIFY2(!dialog.summaryText().contains(QStringLiteral("Refused")),
             qPrintable(dialog.summaryText()));
    QVERIFY(dialog.summaryText().contains(kTwoSkipped));
    QVERIFY(!dialog.isTableGreyed());
    QVERIFY(dialog.canApply());
    f.settle();
    QCOMPARE(f.simLine->stats().writeRequests, 0);
}

void TestProfileDialog::afterAnApplyTheTableShowsTheDeviceAsItNowIs() {
    testing::SimFixture f(testing::singleDevice(QStringLiteral("DME")));
    sim::SimDevice &dev = *f.simLine->devices().first();
    dev.setSetting("ST2", 350);
    auto station = f.station();
    const auto profile = model::Profile::fromJson(
        R"({"format":"tipscope-profile","schema":1,"family":"DME","values":{"ST2":"00320"}})");
    QVERIFY2(profile.ok(), qPrintable(profile.error()));
    ProfileDialog dialog(*station, *profile);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    QTRY_VERIFY_WITH_TIMEOUT(!dialog.isRunning(), 20000);
    QCOMPARE(dialog.cellText(0, 1), QStringLiteral("350 °C"));
    dialog.run(model::ProfileApplier::Mode::Apply);
    QTRY_VERIFY_WITH_TIMEOUT(!dialog.isRunning(), 20000);
    QCOMPARE(dev.setting("ST2").value(), 320);
    QVERIFY2(dialog.summaryText().contains(QStringLiteral("as it now is")),
             qPrintable(dialog.summaryText()));
    QCOMPARE(dialog.differenceRows(), 1);
    QCOMPARE(dialog.cellText(0, 0), QStringLiteral("Selected temperature, port 2 (ST2)"));
    QCOMPARE(dialog.cellText(0, 1), QStringLiteral("320 °C")); // read back, not the old 350
    QCOMPARE(dialog.cellText(0, 3), QStringLiteral("✓ changed from 350 °C"));
}

TIPSCOPE_TEST_MAIN(TestProfileDialog)

} // namespace tst_profiledialog
#include "tst_profiledialog.moc"
