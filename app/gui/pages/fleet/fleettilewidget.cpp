#include "pages/fleet/fleettilewidget.h"

#include "pages/levelstyle.h"

#include "model/joints/jointtable.h"

#include <QKeyEvent>
#include <QPainter>

namespace tipscope::gui {

using model::Level;

namespace {
constexpr int kMargin = 8;
constexpr int kLineGap = 2;
constexpr int kWidthInChars = 46; // a port's row unabridged in German, four tiles on 1920 px
constexpr int kBorder = 2;
constexpr int kMaxProblemRows = 3; // the reason a line is down is read in full, not guessed at
} // namespace

FleetTileWidget::FleetTileWidget(model::FleetTileSource *tile, QWidget *parent)
    : QWidget(parent)
    , m_tile(tile) {
    m_tile->setParent(this);
    setFocusPolicy(Qt::StrongFocus);
    setCursor(Qt::PointingHandCursor);
    setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
    m_clock.start();
    connect(m_tile, &model::FleetTileSource::changed, this, &FleetTileWidget::markDirty);
    connect(m_tile, &model::FleetTileSource::sampleArrived, this, [this] {
        if (m_arrivedNs < 0)
            m_arrivedNs = m_clock.nsecsElapsed();
        markDirty();
    });
    refresh();
}

void FleetTileWidget::markDirty() {
    if (m_dirty)
        return;
    m_dirty = true;
    m_dirtySinceNs = m_clock.nsecsElapsed();
    Q_EMIT dirtied();
}

bool FleetTileWidget::refresh() {
    if (!m_dirty)
        return false;
    m_dirty = false;
    model::FleetTileState state = m_tile->state();
    if (state == m_shown) {
        // Nothing to show for the readings that came: they are not late, they are the same.
        m_arrivedNs = -1;
        return false;
    }
    m_shown = std::move(state);
    // A tile out of sight is not drawn: its readings would count as late when it reappears.
    m_repaintDueNs = isVisible() ? m_arrivedNs : -1;
    m_arrivedNs = -1;
    // Laid out once per change; paints between changes (exposures, scrolling) reuse it.
    const qsizetype before = m_lines.size();
    QList<Line> lines = layoutLines();
    keepShapedText(lines);
    m_lines = std::move(lines);
    setAccessibleName(m_shown.deviceName);
    if (m_lines.size() != before)
        updateGeometry();
    update();
    return true;
}

// The tool goes last: a long tool name ("T245/T470 (TR245/TR470)") is what the elision cuts, never
// the temperatures. The joints have a line of their own: on the port's row they pushed the tool
// out of the tile.
QString FleetTileWidget::portLine(const model::FleetPortState &port) const {
    return tr("P%1  %2 / %3  %4  %5")
               .arg(port.number)
               .arg(port.tipText, port.setpointText, port.powerText, port.statusText) +
           QStringLiteral("  ") + port.toolText;
}

QList<FleetTileWidget::Line> FleetTileWidget::layoutLines() const {
    const model::FleetTileState &s = m_shown;
    QList<Line> lines;
    lines.append({s.deviceName, Level::Unknown, true});
    QStringList where = {s.lineName};
    if (!s.cell.isEmpty())
        where.append(s.cell);
    if (!s.model.isEmpty())
        where.append(s.model);
    lines.append({where.join(QStringLiteral(" · ")), Level::Unknown, false});
    if (!s.lineUp)
        lines.append({s.lineText, Level::Unknown, true});
    for (const model::FleetPortState &port : s.ports)
        lines.append({portLine(port), Level::Unknown, false});
    if (!s.feederText.isEmpty())
        lines.append({s.feederText, Level::Unknown, false});
    for (const model::FleetProblem &problem : s.problems)
        appendProblem(lines, problem);
    if (s.lastJoint)
        lines.append({tr("Last joint: %1 (port %2)")
                          .arg(model::JointTableModel::verdictText(*s.lastJoint))
                          .arg(s.lastJointPort),
                      model::jointLevel(*s.lastJoint), false});
    return lines;
}

// A problem says why: it wraps at its spaces instead of losing its end ("…: Connection refused")
// to the tile's edge; only what passes kMaxProblemRows is cut.
void FleetTileWidget::appendProblem(QList<Line> &lines, const model::FleetProblem &problem) const {
    const QFontMetrics metrics = fontMetrics();
    const int width = sizeHint().width() - 2 * kMargin - metrics.height() - kLineGap * 2;
    const QStringList words = problem.text.split(QLatin1Char(' '));
    QString row;
    int rows = 0;
    for (qsizetype i = 0; i < words.size(); ++i) {
        const QString wider = row.isEmpty() ? words.at(i) : row + QLatin1Char(' ') + words.at(i);
        if (row.isEmpty() || metrics.horizontalAdvance(wider) <= width ||
            rows == kMaxProblemRows - 1) {
            row = wider;
            continue;
        }
        lines.append({row, problem.level, false, rows > 0});
        ++rows;
        row = words.at(i);
    }
    lines.append({row, problem.level, false, rows > 0});
}

// A row whose text did not change keeps its shaped glyphs; on a station tile only the rows of
// the ports whose readings moved are shaped again.
void FleetTileWidget::keepShapedText(QList<Line> &lines) const {
    for (qsizetype i = 0; i < qMin(lines.size(), m_lines.size()); ++i) {
        const Line &was = m_lines.at(i);
        if (was.text == lines.at(i).text && was.bold == lines.at(i).bold) {
            lines[i].glyphs = was.glyphs;
            lines[i].glyphsWidth = was.glyphsWidth;
        }
    }
}

QFont FleetTileWidget::fontOf(const Line &line) const {
    QFont font = this->font();
    font.setBold(line.bold);
    return font;
}

QStringList FleetTileWidget::lines() const {
    QStringList texts;
    for (const Line &line : m_lines)
        texts.append(line.text);
    return texts;
}

int FleetTileWidget::lineHeight() const {
    return fontMetrics().height() + kLineGap;
}

QSize FleetTileWidget::sizeHint() const {
    return {fontMetrics().averageCharWidth() * kWidthInChars + 2 * kMargin,
            qMax(int(m_lines.size()), 2) * lineHeight() + 2 * kMargin};
}

void FleetTileWidget::paintEvent(QPaintEvent *) {
    if (m_repaintDueNs >= 0) {
        Q_EMIT latencyMeasured(double(m_clock.nsecsElapsed() - m_repaintDueNs) / 1e6);
        m_repaintDueNs = -1;
    }
    QPainter painter(this);
    // A line's own tile shows nothing stale: what it says of the line is current.
    const bool stale = !m_shown.lineUp && !m_shown.lineOnly;
    const QPalette::ColorGroup group = stale ? QPalette::Disabled : QPalette::Active;
    const QRect frame = rect().adjusted(1, 1, -1, -1);
    painter.fillRect(frame, palette().color(group, stale ? QPalette::Window : QPalette::Base));
    if (const QVariant tint = levelTint(m_shown.worst()); tint.isValid() && !stale)
        painter.fillRect(frame, tint.value<QColor>());
    painter.setPen(
        QPen(palette().color(group, hasFocus() ? QPalette::Highlight : QPalette::Mid), kBorder));
    painter.drawRect(frame);
    painter.setPen(palette().color(group, QPalette::Text));
    const int height = lineHeight();
    const int iconSize = fontMetrics().height();
    int y = kMargin;
    for (Line &line : m_lines) {
        const QFont font = fontOf(line);
        painter.setFont(font);
        int x = kMargin;
        if (line.continued) {
            x += iconSize + kLineGap * 2;
        } else if (line.level != Level::Unknown) {
            QIcon &icon = m_icons.at(size_t(line.level));
            if (icon.isNull())
                icon = levelIcon(line.level);
            icon.paint(&painter, QRect(x, y, iconSize, iconSize), Qt::AlignCenter,
                       stale ? QIcon::Disabled : QIcon::Normal);
            x += iconSize + kLineGap * 2;
        }
        const int width = this->width() - kMargin - x;
        const QFontMetrics metrics(font);
        if (line.glyphsWidth != width) {
            line.glyphs.setTextFormat(Qt::PlainText);
            line.glyphs.setText(metrics.elidedText(line.text, Qt::ElideRight, width));
            line.glyphs.prepare(QTransform(), font);
            line.glyphsWidth = width;
        }
        painter.drawStaticText(QPointF(x, y + (height - metrics.height()) / 2.0), line.glyphs);
        y += height;
    }
}

void FleetTileWidget::mouseReleaseEvent(QMouseEvent *event) {
    if (event->button() == Qt::LeftButton && rect().contains(event->position().toPoint()))
        Q_EMIT activated();
    QWidget::mouseReleaseEvent(event);
}

void FleetTileWidget::keyPressEvent(QKeyEvent *event) {
    if (event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter ||
        event->key() == Qt::Key_Space) {
        Q_EMIT activated();
        return;
    }
    QWidget::keyPressEvent(event);
}

void FleetTileWidget::hideEvent(QHideEvent *event) {
    m_arrivedNs = -1;
    m_repaintDueNs = -1;
    QWidget::hideEvent(event);
}

} // namespace tipscope::gui
