// Adding a command is one catalog entry: a session built on a catalog with entries the built-in
// one lacks (a station setting, a port counter, a feeder total and partial counter with its
// reset; tests/support/testcatalog.h) shows them on the Settings and Counters pages, real
// widgets on the demo line, without any other change. The simulator does not know the new codes
// and refuses them; the pages show them all the same, as not read.
#include "pages/counterspage.h"
#include "pages/settingspage.h"
#include "testmain.h"
#include "widgets/parametereditor.h"

#include "demosession.h"
#include "support/testcatalog.h"

#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QTest>

namespace tst_newcatalogentry {

using namespace tipscope;
using namespace tipscope::model;
using tipscope::gui::CountersPage;
using tipscope::gui::ParameterEditor;
using tipscope::gui::SettingsPage;

namespace {

constexpr int kConnectMs = 60000;

int rowNamed(const QTableWidget *table, const QString &name) {
    for (int r = 0; r < table->rowCount(); ++r)
        if (table->verticalHeaderItem(r) && table->verticalHeaderItem(r)->text() == name)
            return r;
    return -1;
}

QString cellTip(const QTableWidget *table, int row, int column) {
    const QTableWidgetItem *item = table->item(row, column);
    return item ? item->toolTip() : QString();
}

} // namespace

class TestNewCatalogEntry : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();

    void aNewStationSettingIsEditedOnTheSettingsPage();
    void aNewPortCounterIsARowOfTheStationsCounters();
    void aNewFeederCounterPairIsARowWithItsResetButton();

private:
    std::optional<protocol::Catalog> m_catalog;
    std::unique_ptr<Session> m_session;
};

void TestNewCatalogEntry::initTestCase() {
    auto catalog = testing::catalogWith(testing::newCommandEntries());
    QVERIFY2(catalog, qPrintable(catalog.error()));
    m_catalog = std::move(catalog).value();
    m_session = std::make_unique<Session>(*m_catalog);
    Session::Settings settings = tipscope::testing::unpacedDemoSettings();
    m_session->connectTo(settings);
    QTRY_VERIFY_WITH_TIMEOUT(m_session->state() == Session::State::Connected &&
                                 m_session->station() && m_session->feeder(),
                             kConnectMs);
}

void TestNewCatalogEntry::cleanupTestCase() {
    m_session.reset();
}

void TestNewCatalogEntry::aNewStationSettingIsEditedOnTheSettingsPage() {
    SettingsPage page(*m_session);
    page.setSelection(m_session->station(), 1);
    page.resize(1100, 800);
    page.show();
    QVERIFY(QTest::qWaitForWindowExposed(&page));
    ParameterEditor *editor = page.editorFor("BRT");
    QVERIFY(editor);
    auto *box = qobject_cast<QGroupBox *>(editor->parentWidget());
    QVERIFY(box);
    QCOMPARE(box->title(), QStringLiteral("Station"));
    QStringList labels;
    for (const QLabel *label : box->findChildren<QLabel *>())
        if (label->buddy() == editor)
            labels.append(label->text());
    QCOMPARE(labels, QStringList{QStringLiteral("Display brightness")});
    // A setting like any other: validated against the entry's range before anything is sent.
    QVERIFY(!editor->enterText(QStringLiteral("12")).isEmpty());
    QCOMPARE(editor->enterText(QStringLiteral("7")), QString());
    QCOMPARE(page.editedCount(), 1);
}

void TestNewCatalogEntry::aNewPortCounterIsARowOfTheStationsCounters() {
    CountersPage page(*m_session);
    page.resize(1100, 800);
    page.show();
    QVERIFY(QTest::qWaitForWindowExposed(&page));
    const auto *table = page.findChild<QTableWidget *>(QStringLiteral("stationCounters"));
    QVERIFY(table);
    QCOMPARE(table->rowCount(), 8); // the DME's seven counters and the new one
    const int row = rowNamed(table, QStringLiteral("Tip changes"));
    QCOMPARE(row, 7);
    QCOMPARE(table->columnCount(), 4);
    for (int c = 0; c < table->columnCount(); ++c)
        QVERIFY2(
            cellTip(table, row, c).startsWith(QStringLiteral("Tip changes (R-CK%1)").arg(c + 1)),
            qPrintable(cellTip(table, row, c)));
}

void TestNewCatalogEntry::aNewFeederCounterPairIsARowWithItsResetButton() {
    CountersPage page(*m_session);
    page.resize(1100, 800);
    page.show();
    QVERIFY(QTest::qWaitForWindowExposed(&page));
    const auto *table = page.findChild<QTableWidget *>(QStringLiteral("feederCounters"));
    QVERIFY(table);
    QCOMPARE(table->rowCount(), 4);
    const int row = rowNamed(table, QStringLiteral("Wire jams"));
    QCOMPARE(row, 3);
    QVERIFY(cellTip(table, row, 0).startsWith(QStringLiteral("Wire jams (total) (R-CJT)")));
    QVERIFY(cellTip(table, row, 1).startsWith(QStringLiteral("Wire jams (partial) (R-CJP)")));
    const auto *reset = page.findChild<QPushButton *>(QStringLiteral("resetCJP"));
    QVERIFY(reset);
    QCOMPARE(reset->text(), QStringLiteral("Reset partial wire jams…"));
    QVERIFY(reset->isEnabled());
}

TIPSCOPE_TEST_MAIN(TestNewCatalogEntry)

} // namespace tst_newcatalogentry
#include "tst_newcatalogentry.moc"
