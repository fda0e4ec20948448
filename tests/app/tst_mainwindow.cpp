// The real main window on the offscreen platform, driven against the demo simulator.
#include "connectionbar.h"
#include "devicetree.h"
#include "mainwindow.h"
#include "pages/jointspage.h"
#include "pages/overviewpage.h"
#include "pages/portcard.h"
#include "pages/settingspage.h"
#include "testmain.h"
#include "widgets/parametereditor.h"
#include "widgets/startfolder.h"

#include "i18n/translations.h"
#include "link/simtransport.h"
#include "sim/simline.h"

#include <QSettings>
#include <QStandardPaths>
#include <QStyle>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTranslator>
#include <QTreeWidgetItemIterator>

namespace tst_mainwindow {

using namespace tipscope;
using namespace tipscope::gui;
using namespace tipscope::model;

class TestMainWindow : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void demoConnectsAndShowsEveryPortLive();
    void aSettingEditedAndAppliedReachesTheStation();
    void anInvalidEntryIsRefusedAndNothingIsSent();
    void monitorOnlyBlocksTheRobotControls();
    void robotControlsSetStatusAndSetpoint();
    void unplugShowsRetryingAndRecovers();
    void badConnectionSettingsAreRefusedWithAReason();
    void germanDeviceTreeLabelsAreShownWholeAt1280();
    void theJointsPageReadsTheWindowsJournalAndFollowsItsWorkOrder();
    void fileDialogsOfferAFolderThatExistsOnAFreshAccount();

private:
    void connectDemo(MainWindow &w);
};

void TestMainWindow::initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("TipScopeTests"));
    QSettings().clear();
}

void TestMainWindow::connectDemo(MainWindow &w) {
    AppSettings s;
    s.kind = AppSettings::Kind::Demo;
    w.connectWith(s);
    QTRY_COMPARE_WITH_TIMEOUT(w.session().state(), Session::State::Connected, 10000);
    QCOMPARE(w.session().devices().size(), 2);
}

void TestMainWindow::demoConnectsAndShowsEveryPortLive() {
    MainWindow w;
    w.show();
    connectDemo(w);
    QVERIFY(w.connectionBar().stateText().startsWith(QStringLiteral("Connected")));
    auto *overview = qobject_cast<OverviewPage *>(w.page(QStringLiteral("Overview")));
    QVERIFY(overview);
    for (int port = 1; port <= 4; ++port) {
        QVERIFY(overview->card(port));
        QTRY_VERIFY_WITH_TIMEOUT(overview->card(port)->tipText().contains(QStringLiteral("°C")),
                                 10000);
    }
    QTRY_VERIFY_WITH_TIMEOUT(overview->stationText().contains(QStringLiteral("DME-2C")), 5000);
    QCOMPARE(w.deviceTree().topLevelItem(0)->childCount(), 2);
}

void TestMainWindow::aSettingEditedAndAppliedReachesTheStation() {
    MainWindow w;
    w.show();
    connectDemo(w);
    auto *settings = qobject_cast<SettingsPage *>(w.page(QStringLiteral("Settings")));
    w.pages().setCurrentWidget(settings);
    Parameter *matParam = w.session().station()->parameter("MAT");
    QTRY_VERIFY_WITH_TIMEOUT(matParam->value().has_value(), 15000);
    ParameterEditor *mat = settings->editorFor("MAT");
    QVERIFY(mat);
    QCOMPARE(mat->enterText(QStringLiteral("450")), QString());
    QCOMPARE(settings->editedCount(), 1);
    settings->applyEdits();
    QTRY_COMPARE_WITH_TIMEOUT(matParam->state(), Parameter::State::InSync, 10000);
    QCOMPARE(w.session().demoLine()->station()->setting("MAT").value(), 450);
}

void TestMainWindow::anInvalidEntryIsRefusedAndNothingIsSent() {
    MainWindow w;
    w.show();
    connectDemo(w);
    auto *settings = qobject_cast<SettingsPage *>(w.page(QStringLiteral("Settings")));
    QTRY_VERIFY_WITH_TIMEOUT(w.session().station()->parameter("ST1")->value().has_value(), 15000);
    ParameterEditor *st = settings->editorFor("ST1");
    QVERIFY(st);
    const qint64 writes = w.session().demoLine()->stats().writeRequests;
    const QString why = st->enterText(QStringLiteral("353"));
    QVERIFY2(why.contains(QStringLiteral("steps of 5")), qPrintable(why));
    QCOMPARE(settings->editedCount(), 0);
    settings->applyEdits();
    QTest::qWait(300);
    QCOMPARE(w.session().demoLine()->stats().writeRequests, writes);
}

void TestMainWindow::monitorOnlyBlocksTheRobotControls() {
    MainWindow w;
    w.show();
    connectDemo(w);
    w.session().setMonitorOnly(true);
    auto *overview = qobject_cast<OverviewPage *>(w.page(QStringLiteral("Overview")));
    QVERIFY(overview->card(1)->requestMode(1).contains(QStringLiteral("monitor-only")));
    QTest::qWait(200);
    QCOMPARE(w.session().demoLine()->stats().writeRequests, 0);
}

void TestMainWindow::robotControlsSetStatusAndSetpoint() {
    MainWindow w;
    w.show();
    connectDemo(w);
    auto *overview = qobject_cast<OverviewPage *>(w.page(QStringLiteral("Overview")));
    QTRY_VERIFY_WITH_TIMEOUT(
        w.session().station()->port(2)->parameter(protocol::Role::Setpoint)->value().has_value(),
        10000);
    QCOMPARE(overview->card(2)->requestMode(10), QString());
    QTRY_VERIFY_WITH_TIMEOUT(w.session().demoLine()->station()->port(2).cooling, 10000);
    QCOMPARE(overview->card(2)->requestSetpoint(300), QString());
    QTRY_COMPARE_WITH_TIMEOUT(w.session().demoLine()->station()->setting("ST2").value_or(0), 300,
                              10000);
    QVERIFY(!overview->card(2)->requestSetpoint(302).isEmpty());
}

void TestMainWindow::unplugShowsRetryingAndRecovers() {
    MainWindow w;
    w.show();
    connectDemo(w);
    auto *transport = qobject_cast<link::SimTransport *>(&w.session().line()->transport());
    QVERIFY(transport);
    transport->setPlugged(false);
    QTRY_COMPARE_WITH_TIMEOUT(w.session().state(), Session::State::Retrying, 5000);
    QVERIFY(w.connectionBar().stateText().contains(QStringLiteral("retrying")));
    transport->setPlugged(true);
    QTRY_COMPARE_WITH_TIMEOUT(w.session().state(), Session::State::Connected, 5000);
    QCOMPARE(w.session().devices().size(), 2);
}

void TestMainWindow::badConnectionSettingsAreRefusedWithAReason() {
    MainWindow w;
    AppSettings s;
    s.kind = AppSettings::Kind::Tcp;
    s.tcpAddress = QStringLiteral("no-port-here");
    w.connectionBar().setSettings(s);
    QVERIFY(w.connectLine().contains(QStringLiteral("HOST:PORT")));
    QCOMPARE(w.session().state(), Session::State::Disconnected);
    s.kind = AppSettings::Kind::Serial;
    s.serialPort = QStringLiteral("/dev/tipscope-missing");
    w.connectWith(s);
    QTRY_VERIFY_WITH_TIMEOUT(
        w.connectionBar().stateText().contains(QStringLiteral("no such port"), Qt::CaseInsensitive),
        5000);
}

// German device labels are long ("SFR-A, Adresse 10 (Lotdrahtvorschub)") and so are some tools'
// names: at 1280 px each label is shown whole, on as many lines as it takes, and is its tooltip.
void TestMainWindow::theJointsPageReadsTheWindowsJournalAndFollowsItsWorkOrder() {
    MainWindow w;
    auto *joints = qobject_cast<JointsPage *>(w.page(QStringLiteral("Joints")));
    QVERIFY(joints);
    QCOMPARE(joints->journalPath(), w.journal().path());
    const QString before = w.journal().context().workOrder;
    QCOMPARE(joints->workOrder(), before);
    const QString next = before + QStringLiteral("-next");
    QVERIFY(w.workContext().set(WorkContext{next, {}, {}}).ok());
    QTRY_COMPARE(joints->workOrder(), next);
    QVERIFY(w.workContext().set(WorkContext{before, {}, {}}).ok());
}

void TestMainWindow::germanDeviceTreeLabelsAreShownWholeAt1280() {
    QCOMPARE(i18n::installTranslators(*QCoreApplication::instance(), QStringLiteral("de")),
             QStringLiteral("de"));
    {
        MainWindow w;
        w.resize(1280, 720);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        connectDemo(w);
        DeviceTree &tree = w.deviceTree();
        QTreeWidgetItem *station = tree.topLevelItem(0)->child(0);
        QTRY_VERIFY_WITH_TIMEOUT(station->child(1)->text(0).contains(QStringLiteral("TR245")),
                                 10000);
        QTest::qWait(300); // the relabelled rows laid out
        const QFontMetrics metrics(tree.font());
        const int margins =
            2 * (tree.style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, &tree) + 1);
        for (QTreeWidgetItemIterator it(&tree); *it; ++it) {
            const QString text = (*it)->text(0);
            const QRect cell = tree.visualItemRect(*it);
            const QRect needed = metrics.boundingRect(QRect(0, 0, cell.width() - margins, 0),
                                                      Qt::TextWordWrap, text);
            QVERIFY2(cell.height() >= needed.height() && needed.width() <= cell.width() - margins,
                     qPrintable(QStringLiteral("%1: %2 px high, needs %3")
                                    .arg(text)
                                    .arg(cell.height())
                                    .arg(needed.height())));
        }
        for (QTreeWidgetItemIterator it(&tree); *it; ++it)
            QCOMPARE((*it)->toolTip(0), (*it)->text(0));
    }
    qDeleteAll(QCoreApplication::instance()->findChildren<QTranslator *>());
}

// A fresh account has no Documents folder yet: the support report's folder dialog (and every
// export) starts in the home folder then, not in a folder that is not there.
void TestMainWindow::fileDialogsOfferAFolderThatExistsOnAFreshAccount() {
    QTemporaryDir home;
    QVERIFY(home.isValid());
    const QByteArray oldHome = qgetenv("HOME");
    const QByteArray oldConfig = qgetenv("XDG_CONFIG_HOME");
    qputenv("HOME", QFile::encodeName(home.path()));
    qputenv("XDG_CONFIG_HOME", QFile::encodeName(home.filePath(QStringLiteral(".config"))));
    const QString fresh = startFolder();
    QVERIFY(QDir(home.path()).mkdir(QStringLiteral("Documents")));
    const QString withDocuments = startFolder();
    qputenv("HOME", oldHome);
    if (oldConfig.isNull())
        qunsetenv("XDG_CONFIG_HOME");
    else
        qputenv("XDG_CONFIG_HOME", oldConfig);
    QCOMPARE(QDir(fresh).canonicalPath(), QDir(home.path()).canonicalPath());
    QCOMPARE(QDir(withDocuments).canonicalPath(),
             QDir(home.filePath(QStringLiteral("Documents"))).canonicalPath());
}

TIPSCOPE_TEST_MAIN(TestMainWindow)

} // namespace tst_mainwindow
#include "tst_mainwindow.moc"
