// DeferredRefresh: holds back a widget's refresh while it sits hidden in a shown window (a page
// behind the current one) and runs it when the widget is shown again.
//
// Live values change many times a second, and a page nobody looks at repainting its labels for
// each of them was a measurable share of the GUI's CPU. A widget in a window that is not shown
// at all (a test, an export) refreshes at once, as before.
#pragma once

#include <QObject>
#include <QPointer>
#include <QWidget>
#include <functional>

namespace tipscope::gui {

class DeferredRefresh : public QObject {
public:
    DeferredRefresh(QWidget &widget, std::function<void()> refresh);

    // Refreshes now, or marks the refresh due if the widget cannot be seen.
    void request();
    // Refreshes if a refresh is due (before reading what the widget shows).
    void flush();
    [[nodiscard]] bool isDue() const { return m_due; }

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    QPointer<QWidget> m_widget;
    std::function<void()> m_refresh;
    bool m_due = false;
};

} // namespace tipscope::gui
