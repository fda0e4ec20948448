// DeferredRefresh: a widget hidden behind another page of a shown window refreshes once, when it
// is shown again; a visible widget, or one whose window is not shown at all, refreshes at once.
#include "widgets/deferredrefresh.h"

#include <QStackedWidget>
#include <QTest>

using tipscope::gui::DeferredRefresh;

class TestDeferredRefresh : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aHiddenPageRefreshesOnceWhenShown();
    void aVisibleWidgetRefreshesAtOnce();
    void aWidgetOfAnUnshownWindowRefreshesAtOnce();
    void flushBringsAHiddenWidgetUpToDate();
};

void TestDeferredRefresh::aHiddenPageRefreshesOnceWhenShown() {
    QStackedWidget pages;
    auto *front = new QWidget;
    auto *back = new QWidget;
    pages.addWidget(front);
    pages.addWidget(back);
    pages.show();
    QVERIFY(QTest::qWaitForWindowExposed(&pages));
    int refreshes = 0;
    DeferredRefresh refresh(*back, [&refreshes] { ++refreshes; });
    for (int i = 0; i < 50; ++i)
        refresh.request();
    QCOMPARE(refreshes, 0);
    QVERIFY(refresh.isDue());
    pages.setCurrentWidget(back);
    QCOMPARE(refreshes, 1);
    QVERIFY(!refresh.isDue());
    pages.setCurrentWidget(front);
    pages.setCurrentWidget(back); // shown again with nothing due: no refresh
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
    QStackedWidget pages;
    pages.addWidget(new QWidget);
    auto *back = new QWidget;
    pages.addWidget(back);
    pages.show();
    QVERIFY(QTest::qWaitForWindowExposed(&pages));
    int refreshes = 0;
    DeferredRefresh refresh(*back, [&refreshes] { ++refreshes; });
    refresh.flush();
    QCOMPARE(refreshes, 0); // nothing due
    refresh.request();
    refresh.flush();
    QCOMPARE(refreshes, 1);
}

QTEST_MAIN(TestDeferredRefresh)
#include "tst_deferredrefresh.moc"
