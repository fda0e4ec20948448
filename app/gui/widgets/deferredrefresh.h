// DeferredRefresh: holds back a widget's refresh while it sits hidden in a shown window (a page
// behind the current one) and runs it when the widget is shown again.
//
// Live values change many times a second, and a page nobody looks at repainting its labels for
// each of them was a measurable share of the GUI's CPU. A widget in a window that is not shown
// at all (a test, an export) refreshes at once, as before.
//
// One refresh may serve many parts of a widget (the rows of a table, its cells): each part
// requested while hidden is refreshed once, in the order first requested, on show.
#pragma once

#include <QList>
#include <QObject>
#include <QPointer>
#include <QWidget>
#include <functional>

namespace tipscope::gui {

class DeferredRefresh : public QObject {
public:
    // The refresh lives as long as `owner` (the widget when none is given): a page that
    // rebuilds its bindings passes the object that holds them.
    DeferredRefresh(QWidget &widget, std::function<void()> refresh, QObject *owner = nullptr);
    DeferredRefresh(QWidget &widget, std::function<void(int)> refresh, QObject *owner = nullptr);

    // Refreshes now, or marks the refresh due if the widget cannot be seen.
    void request() { requestPart(0); }
    void requestPart(int part);
    // Runs the refreshes that are due (before reading what the widget shows).
    void flush();
    [[nodiscard]] bool isDue() const { return !m_due.isEmpty(); }

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    QPointer<QWidget> m_widget;
    std::function<void(int)> m_refresh;
    QList<int> m_due;
};

} // namespace tipscope::gui
