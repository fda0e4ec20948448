// FlowLayout: widgets in a row that wraps onto the next line when the row is too narrow, like words
// in a paragraph. A toolbar laid out with it never makes its window wider than the screen (the
// Charts page's buttons in German were 33 px wider than 1280), at the cost of a second line.
// Items are centred on their line, or at its top when their alignment says Qt::AlignTop.
#pragma once

#include <QLayout>
#include <QList>

namespace tipscope::gui {

class FlowLayout : public QLayout {
    Q_OBJECT
public:
    explicit FlowLayout(QWidget *parent = nullptr);
    ~FlowLayout() override;

    void addItem(QLayoutItem *item) override;
    [[nodiscard]] int count() const override { return int(m_items.size()); }
    [[nodiscard]] QLayoutItem *itemAt(int index) const override;
    QLayoutItem *takeAt(int index) override;

    [[nodiscard]] Qt::Orientations expandingDirections() const override { return {}; }
    [[nodiscard]] bool hasHeightForWidth() const override { return true; }
    [[nodiscard]] int heightForWidth(int width) const override;
    [[nodiscard]] QSize minimumSize() const override;
    [[nodiscard]] QSize sizeHint() const override;
    void setGeometry(const QRect &rect) override;

private:
    // Places the items in `rect` (only measures when `place` is false); returns the height used.
    int arrange(const QRect &rect, bool place) const;
    [[nodiscard]] int gap(Qt::Orientation orientation) const;

    QList<QLayoutItem *> m_items;
};

} // namespace tipscope::gui
