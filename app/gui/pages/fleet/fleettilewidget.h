// FleetTileWidget: one device of the fleet overview, drawn from a model::FleetTile: its name, its
// line, cell and model, a row per port (tool, tip temperature against setpoint, power, status,
// the port's last joint), the feeder's state, the errors and alarms each with its level's icon,
// the last joint's verdict, and the line down with since when.
//
// The tile is tinted by its worst level (levelstyle); while its line is down it is greyed and
// says since when, so nothing on it reads as current. It repaints only when refresh() finds its
// state changed since it was last drawn; refresh() is the owner's to call at a bounded rate,
// whatever the rate of the readings. Every tip reading that arrives is stamped; the first
// repaint after it reports how late it was (latencyMeasured(), in ms), and a reading that changes
// nothing shown is dropped from the measure. A click, Enter or Space is activated().
#pragma once

#include "model/workspace/fleettile.h"

#include <QElapsedTimer>
#include <QIcon>
#include <QStaticText>
#include <QWidget>
#include <array>

namespace tipscope::gui {

class FleetTileWidget : public QWidget {
    Q_OBJECT
public:
    // Takes ownership of `tile`.
    FleetTileWidget(model::FleetTileSource *tile, QWidget *parent = nullptr);

    [[nodiscard]] model::FleetTileSource &tile() const { return *m_tile; }
    // The state as last drawn (or about to be).
    [[nodiscard]] const model::FleetTileState &shown() const { return m_shown; }
    // Whether a reading or a change arrived since the last refresh().
    [[nodiscard]] bool isDirty() const { return m_dirty; }
    // How long it has been dirty, in ms; -1 when it is not.
    [[nodiscard]] qint64 dirtyForMs() const {
        return m_dirty ? (m_clock.nsecsElapsed() - m_dirtySinceNs) / 1'000'000 : -1;
    }
    // Takes the tile's state if it may have changed; true (and a repaint scheduled) when it did.
    bool refresh();
    // The lines the tile draws, top to bottom, as text (for tests and screen readers).
    [[nodiscard]] QStringList lines() const;

    [[nodiscard]] QSize sizeHint() const override;
    [[nodiscard]] QSize minimumSizeHint() const override { return sizeHint(); }

Q_SIGNALS:
    // Something may have changed: the owner should refresh() soon.
    void dirtied();
    void activated();
    void latencyMeasured(double ms);

protected:
    void paintEvent(QPaintEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void hideEvent(QHideEvent *event) override;

private:
    struct Line {
        Line(QString text, model::Level level, bool bold, bool continued = false)
            : text(std::move(text))
            , level(level)
            , bold(bold)
            , continued(continued) {}

        QString text;
        model::Level level = model::Level::Unknown; // an icon for problems, none otherwise
        bool bold = false;
        bool continued = false; // a wrapped problem's further row: under its text, no icon
        // The text elided to `glyphsWidth` and shaped, kept while the text is: shaping at every
        // paint was the tiles' largest cost with 128 ports changing.
        QStaticText glyphs;
        int glyphsWidth = -1;
    };

    void markDirty();
    [[nodiscard]] QList<Line> layoutLines() const;
    [[nodiscard]] QString portLine(const model::FleetPortState &port) const;
    void appendProblem(QList<Line> &lines, const model::FleetProblem &problem) const;
    [[nodiscard]] int lineHeight() const;
    [[nodiscard]] QFont fontOf(const Line &line) const;
    void keepShapedText(QList<Line> &lines) const;

    model::FleetTileSource *m_tile;
    model::FleetTileState m_shown;
    bool m_dirty = true;
    QElapsedTimer m_clock;
    qint64 m_dirtySinceNs = 0;
    qint64 m_arrivedNs = -1;    // the oldest reading not yet shown
    qint64 m_repaintDueNs = -1; // its stamp, once a repaint is scheduled for it
    QList<Line> m_lines;        // what m_shown draws
    // The style's icon of each level, made once: a QIcon made at every paint decodes its PNG
    // again (6 % of the fleet bench's CPU).
    std::array<QIcon, 5> m_icons;
};

} // namespace tipscope::gui
