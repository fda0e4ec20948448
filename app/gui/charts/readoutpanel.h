// ReadoutPanel: the values under the Charts page's crosshair, every one whole. The instant comes
// first, then one cell per channel (a port's tip, setpoint and power; the feeder's length and
// speed), in as many columns as the width holds and as many rows as that takes. Without a hover
// it shows how to read and move the charts instead.
//
// Its height follows its width and the widest the cells can be (learned from a template of the
// panes' traces, and from any wider cell shown), never the values under the pointer: pointing at
// a plot never moves the plots.
#pragma once

#include <QStringList>
#include <QWidget>

namespace tipscope::gui {

class ReadoutPanel : public QWidget {
    Q_OBJECT
public:
    explicit ReadoutPanel(QWidget *parent = nullptr);

    // The cells at their widest (a value of every trace at its widest): sets the cells' width
    // and count the height is reserved for. Called when the panes are rebuilt.
    void setTemplate(const QStringList &cells);
    void showValues(const QString &time, const QStringList &cells);
    void showHint(const QStringList &lines);

    // What a person reads: the hint's lines, or the instant and every cell, " · " between them.
    [[nodiscard]] QString text() const;
    [[nodiscard]] int columns() const { return columnsFor(width()); }

    [[nodiscard]] bool hasHeightForWidth() const override { return true; }
    [[nodiscard]] int heightForWidth(int width) const override;
    [[nodiscard]] QSize sizeHint() const override;
    [[nodiscard]] QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    [[nodiscard]] int columnsFor(int width) const;
    [[nodiscard]] int cellRowsFor(int width) const;
    [[nodiscard]] int timeWidth() const;
    void learnWidths(const QStringList &cells);

    QString m_time;
    QStringList m_cells;
    QStringList m_hint;
    QStringList m_template;
    bool m_hovering = false;
    int m_cellWidth = 0;
    int m_cellCount = 0;
};

} // namespace tipscope::gui
