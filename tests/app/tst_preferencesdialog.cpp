// PreferencesDialog shows the counters' poll interval in seconds ("60 s", not "60000 ms") and
// stores it in milliseconds as before; a stored interval that is not whole seconds is kept
// unless the field is changed. The journal's retention reads in days, 0 as "Keep everything".
#include "dialogs/preferencesdialog.h"
#include "testmain.h"

#include <QLabel>
#include <QSpinBox>
#include <QTest>

namespace tst_preferencesdialog {

using namespace tipscope;

namespace {
QSpinBox *fieldOf(const QDialog &dialog, const QString &label) {
    for (QLabel *l : dialog.findChildren<QLabel *>())
        if (l->text() == label)
            return qobject_cast<QSpinBox *>(l->buddy());
    return nullptr;
}
} // namespace

class TestPreferencesDialog : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void theCountersIntervalReadsInSeconds_data();
    void theCountersIntervalReadsInSeconds();
    void aChangedCountersIntervalIsStoredInMilliseconds();
    void anUntouchedIntervalOfNoWholeSecondsIsKept();
    void theJournalRetentionReadsInDaysAndZeroKeepsEverything();
};

void TestPreferencesDialog::theCountersIntervalReadsInSeconds_data() {
    QTest::addColumn<int>("storedMs");
    QTest::addColumn<QString>("shown");
    QTest::newRow("the default minute") << 60000 << "60 s";
    QTest::newRow("the shortest") << 1000 << "1 s";
    QTest::newRow("the longest") << 3600000 << "3600 s";
}

void TestPreferencesDialog::theCountersIntervalReadsInSeconds() {
    QFETCH(int, storedMs);
    QFETCH(QString, shown);
    model::AppSettings settings;
    settings.counterMs = storedMs;
    gui::PreferencesDialog dialog(settings, 365);
    QSpinBox *counters = fieldOf(dialog, QStringLiteral("Counters every:"));
    QVERIFY(counters);
    QCOMPARE(counters->text(), shown);
    QCOMPARE(dialog.result().counterMs, storedMs);
}

void TestPreferencesDialog::aChangedCountersIntervalIsStoredInMilliseconds() {
    gui::PreferencesDialog dialog(model::AppSettings{}, 365);
    QSpinBox *counters = fieldOf(dialog, QStringLiteral("Counters every:"));
    QVERIFY(counters);
    counters->setValue(90);
    QCOMPARE(counters->text(), QStringLiteral("90 s"));
    QCOMPARE(dialog.result().counterMs, 90000);
}

void TestPreferencesDialog::anUntouchedIntervalOfNoWholeSecondsIsKept() {
    model::AppSettings settings;
    settings.counterMs = 1500;
    gui::PreferencesDialog dialog(settings, 365);
    QCOMPARE(dialog.result().counterMs, 1500);
}

void TestPreferencesDialog::theJournalRetentionReadsInDaysAndZeroKeepsEverything() {
    gui::PreferencesDialog dialog(model::AppSettings{}, 365);
    QSpinBox *retention = fieldOf(dialog, QStringLiteral("Keep journal records for:"));
    QVERIFY(retention);
    QCOMPARE(retention->text(), QStringLiteral("365 days"));
    QCOMPARE(dialog.journalRetentionDays(), 365);
    retention->setValue(0);
    QCOMPARE(retention->text(), QStringLiteral("Keep everything"));
    QCOMPARE(dialog.journalRetentionDays(), 0);
    retention->setValue(90);
    QCOMPARE(dialog.journalRetentionDays(), 90);
}

TIPSCOPE_TEST_MAIN(TestPreferencesDialog)

} // namespace tst_preferencesdialog
#include "tst_preferencesdialog.moc"
