// The journal in the window: what a session does reaches the journal file by the time the window
// is closed, the work context typed in its dialog is shown in the status bar and stamped on what
// follows, and the joint limits dialog checks what is typed and saves the shared file.
#include "dialogs/jointlimitsdialog.h"
#include "dialogs/workcontextdialog.h"
#include "journalstatusbutton.h"
#include "mainwindow.h"
#include "testmain.h"

#include "journal/journalreader.h"
#include "journal/workcontextfile.h"
#include "model/joints/jointlimitsfile.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

namespace tst_journalgui {

using namespace tipscope;
using namespace tipscope::gui;
using namespace tipscope::model;

class TestJournalGui : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void theSessionAndTheWorkContextReachTheJournal();
    void theLimitsDialogRefusesABadRuleAndSavesAGoodOne();
};

void TestJournalGui::initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("TipScopeTests"));
    QLocale::setDefault(QLocale(QLocale::English));
    // What an earlier run of this test left in its home.
    QFileInfo(journal::Journal::defaultPath()).dir().removeRecursively();
}

void TestJournalGui::theSessionAndTheWorkContextReachTheJournal() {
    QString path;
    {
        MainWindow w;
        w.show();
        path = w.journal().path();
        auto *status = w.statusBar()->findChild<JournalStatusButton *>();
        QVERIFY(status);
        QCOMPARE(status->text(), QStringLiteral("No work order"));

        WorkContextDialog dialog(w.workContext(), &w);
        dialog.findChild<QLineEdit *>(QStringLiteral("workOrder"))->setText(QStringLiteral("WO-7"));
        dialog.findChild<QLineEdit *>(QStringLiteral("operator"))->setText(QStringLiteral(" ana "));
        dialog.accept();
        QCOMPARE(dialog.result(), int(QDialog::Accepted));
        QTRY_COMPARE_WITH_TIMEOUT(status->text(), QStringLiteral("WO-7 · ana"), 5000);

        AppSettings demo;
        demo.kind = AppSettings::Kind::Demo;
        w.connectWith(demo);
        QTRY_COMPARE_WITH_TIMEOUT(w.session().state(), Session::State::Connected, 15000);
        w.close(); // disconnects and waits for the journal
    }
    journal::JournalReader reader;
    QVERIFY(reader.open(path));
    journal::EventFilter connections;
    connections.kinds = {journal::JournalEvent::Kind::Connection};
    const auto events = reader.events(connections);
    QVERIFY2(events, qPrintable(events.error()));
    QVERIFY(events.value().size() >= 2); // connected, and disconnected at the close
    QCOMPARE(events.value().first().context.workOrder, QStringLiteral("WO-7"));
    QCOMPARE(events.value().first().context.operatorName, QStringLiteral("ana"));
}

void TestJournalGui::theLimitsDialogRefusesABadRuleAndSavesAGoodOne() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("joint-limits.json"));
    JointLimitRules rules;
    rules.add({1, QStringLiteral("C245"), 3000, std::nullopt, std::nullopt});
    JointLimitsDialog dialog(rules, path);
    auto *table = dialog.findChild<QTableWidget *>(QStringLiteral("rules"));
    auto *problem = dialog.findChild<QLabel *>(QStringLiteral("problem"));
    auto *ok = dialog.findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
    QVERIFY(table && problem && ok);
    QCOMPARE(table->rowCount(), 1);
    QCOMPARE(table->item(0, 2)->text(), QStringLiteral("3"));
    QVERIFY(ok->isEnabled());

    dialog.addRule({});
    QVERIFY(!ok->isEnabled()); // a rule that sets no limit
    QVERIFY2(problem->text().startsWith(QStringLiteral("Rule 2:")), qPrintable(problem->text()));
    table->item(1, 3)->setText(QStringLiteral("60.5"));
    QVERIFY2(problem->text().contains(QStringLiteral("whole number of kelvin")),
             qPrintable(problem->text()));
    QVERIFY(!ok->isEnabled());
    table->item(1, 1)->setText(QStringLiteral("C470"));
    table->item(1, 3)->setText(QStringLiteral("60"));
    qobject_cast<QComboBox *>(table->cellWidget(1, 0))->setCurrentIndex(2);
    QVERIFY2(ok->isEnabled(), qPrintable(problem->text()));
    dialog.findChild<QDoubleSpinBox *>(QStringLiteral("defaultRecovery"))->setValue(4.5);
    dialog.accept();
    QCOMPARE(dialog.result(), int(QDialog::Accepted));

    const auto saved = loadJointLimits(path);
    QVERIFY2(saved, qPrintable(saved.error()));
    QCOMPARE(saved.value().defaults().maxRecoveryMs, 4500);
    QCOMPARE(saved.value().limitsFor(2, QStringLiteral("C470")).maxDipK, 60);
    QCOMPARE(saved.value().limitsFor(1, QStringLiteral("C245")).maxRecoveryMs, 3000);
    QCOMPARE(saved.value().limitsFor(1, QStringLiteral("C470")).maxDipK, 80);
}

TIPSCOPE_TEST_MAIN(TestJournalGui)

} // namespace tst_journalgui
#include "tst_journalgui.moc"
