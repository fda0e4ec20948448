// ProfileDialog with a profile that would break the device's limits: the refusal and each broken
// limit are shown at the top, where the eye is, and the dialog writes nothing.
#include "../model/simfixture.h"
#include "dialogs/profiledialog.h"

#include <QTest>

using namespace tipscope;
using tipscope::gui::ProfileDialog;

class TestProfileDialog : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aProfileThatBreaksTheLimitsSaysWhyAtTheTopAndWritesNothing();
};

void TestProfileDialog::aProfileThatBreaksTheLimitsSaysWhyAtTheTopAndWritesNothing() {
    testing::SimFixture f(testing::singleDevice(QStringLiteral("DME")));
    sim::SimDevice &dev = *f.simLine->devices().first();
    dev.setSetting("MAT", 500);
    dev.setSetting("ST1", 450);
    auto station = f.station();
    QString error;
    const auto profile = model::Profile::fromJson(
        R"({"format":"tipscope-profile","schema":1,"family":"DME",
            "values":{"MAT":"00400","A11":"00005"}})",
        &error);
    QVERIFY2(profile, qPrintable(error));
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

QTEST_MAIN(TestProfileDialog)
#include "tst_profiledialog.moc"
