// DeferredRefresh: a widget hidden behind another page of a shown window refreshes once, when it
// is shown again; a visible widget, or one whose window is not shown at all, refreshes at once.
#include "testmain.h"
#include "widgets/deferredrefresh.h"

#include <QStackedWidget>
#include <QTest>

namespace tst_deferredrefresh {

using tipscope::gui::DeferredRefresh;

namespace {
// A shown window of two pages, the front one current.
struct TwoPages {
    TwoPages() {
        stack.addWidget(front);
        stack.addWidget(back);
        stack.show();
    }
    QStackedWidget stack;
    QWidget *front = new QWidget;
    QWidget *back = new QWidget;
};
} // namespace

class TestDeferredRefresh : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aHiddenPageRefreshesOnceWhenShown();
    void aVisibleWidgetRefreshesAtOnce();
    void aWidgetOfAnUnshownWindowRefreshesAtOnce();
    void flushBringsAHiddenWidgetUpToDate();
    void eachPartRequestedWhileHiddenRefreshesOnceInOrder();
    void aRefreshEndsWithItsOwner();
};

void TestDeferredRefresh::aHiddenPageRefreshesOnceWhenShown() {
    TwoPages pages;
    QVERIFY(QTest::qWaitForWindowExposed(&pages.stack));
    int refreshes = 0;
    DeferredRefresh refresh(*pages.back, [&refreshes] { ++refreshes; });
    for (int i = 0; i < 50; ++i)
        refresh.request();
    QCOMPARE(refreshes, 0);
    QVERIFY(refresh.isDue());
    pages.stack.setCurrentWidget(pages.back);
    QCOMPARE(refreshes, 1);
    QVERIFY(!refresh.isDue());
    pages.stack.setCurrentWidget(pages.front);
    pages.stack.setCurrentWidget(pages.back); // shown again with nothing due: no refresh
    QCOMPARE(refreshes, 1);
}

void TestDeferredRefresh::aVisibleWidgetRefreshesAtOnce() {
    QWidget window;
    auto *child = new QWidget(&window);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    int refreshes = 0;
    DeferredRefresh refresh(*child, [&refreshes] { ++refreshes; });
    refresh.request();
    refresh.request();
    QCOMPARE(refreshes, 2);
}

void TestDeferredRefresh::aWidgetOfAnUnshownWindowRefreshesAtOnce() {
    QWidget window;
    auto *child = new QWidget(&window);
    int refreshes = 0;
    DeferredRefresh refresh(*child, [&refreshes] { ++refreshes; });
    refresh.request();
    QCOMPARE(refreshes, 1);
}

void TestDeferredRefresh::flushBringsAHiddenWidgetUpToDate() {
    TwoPages pages;
    QVERIFY(QTest::qWaitForWindowExposed(&pages.stack));
    int refreshes = 0;
    DeferredRefresh refresh(*pages.back, [&refreshes] { ++refreshes; });
    refresh.flush();
    QCOMPARE(refreshes, 0); // nothing due
    refresh.request();
    refresh.flush();
    QCOMPARE(refreshes, 1);
}

void TestDeferredRefresh::eachPartRequestedWhileHiddenRefreshesOnceInOrder() {
    TwoPages pages;
    QVERIFY(QTest::qWaitForWindowExposed(&pages.stack));
    QList<int> refreshed;
    DeferredRefresh rows(*pages.back, [&refreshed](int row) { refreshed.append(row); });
    for (int row : {3, 1, 3, 7, 1, 3})
        rows.requestPart(row);
    QVERIFY(refreshed.isEmpty());
    pages.stack.setCurrentWidget(pages.back);
    QCOMPARE(refreshed, (QList<int>{3, 1, 7}));
    rows.requestPart(1); // shown: at once
    QCOMPARE(refreshed, (QList<int>{3, 1, 7, 1}));
}

void TestDeferredRefresh::aRefreshEndsWithItsOwner() {
    TwoPages pages;
    QVERIFY(QTest::qWaitForWindowExposed(&pages.stack));
    int refreshes = 0;
    auto *bindings = new QObject;
    auto *refresh = new DeferredRefresh(
        *pages.back, [&refreshes] { ++refreshes; }, bindings);
    QPointer<DeferredRefresh> alive(refresh);
    refresh->request();
    delete bindings; // a page rebuilding: what was due for the old rows is dropped
    QVERIFY(alive.isNull());
    pages.stack.setCurrentWidget(pages.back);
    QCOMPARE(refreshes, 0);
}

TIPSCOPE_TEST_MAIN(TestDeferredRefresh)

} // namespace tst_deferredrefresh
#include "tst_deferredrefresh.moc"
