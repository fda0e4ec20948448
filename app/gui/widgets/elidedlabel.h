// ElidedLabel: one line of status text that takes the room it is given and no more. A long text
// (a recording's file name, a replay's row count) ends in "…" instead of widening the window past
// the screen; the whole text is then its tooltip and stays its accessible description.
#pragma once

#include <QLabel>

namespace tipscope::gui {

class ElidedLabel : public QLabel {
    Q_OBJECT
public:
    explicit ElidedLabel(QWidget *parent = nullptr);

    void setFullText(const QString &text);
    [[nodiscard]] const QString &fullText() const { return m_full; }
    // Whether the text shown is cut short.
    [[nodiscard]] bool isElided() const { return text() != m_full; }

    [[nodiscard]] QSize minimumSizeHint() const override;
    [[nodiscard]] QSize sizeHint() const override;

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    void elide();
    [[nodiscard]] int textWidth() const; // of the full text, in whole pixels that hold it all

    QString m_full;
};

} // namespace tipscope::gui
