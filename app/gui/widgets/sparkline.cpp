#include "sparkline.h"

#include "model/telemetry/telemetry.h"

#include <QPainter>
#include <QPainterPath>

namespace tipscope::gui {

using namespace tipscope::model;

namespace {
constexpr qint32 kMinSpanCelsius = 20; // a flat line stays flat, not a magnified noise
constexpr int kTextMargin = 3;

// Samples further apart than this (and than a few columns) are a gap in the recording, drawn as
// one; a port polled slowly (one in error) is not a gap at every sample on a wide card.
constexpr int kGapColumns = 4;
constexpr qint64 kGapMs = 3000;

struct Scale {
    QRectF area;
    qint64 t0 = 0;
    qint64 t1 = 1;
    double low = 0;
    double high = 1;
    [[nodiscard]] double x(qint64 t) const {
        return area.left() + area.width() * double(t - t0) / double(qMax<qint64>(1, t1 - t0));
    }
    [[nodiscard]] double y(double v) const {
        return area.bottom() - area.height() * (v - low) / qMax(1e-9, high - low);
    }
};

// A run through each column's maximum and minimum: a line when flat, a band when dense, a
// break where the recording has a gap.
QPainterPath columnPath(const QList<MinMaxBucket> &buckets, const Scale &s, qint64 columnMs,
                        bool minAndMax) {
    QPainterPath path;
    qint64 previous = std::numeric_limits<qint64>::min();
    for (const MinMaxBucket &b : buckets) {
        const double x = s.x(b.startMs + columnMs / 2);
        const bool gap = previous == std::numeric_limits<qint64>::min() ||
                         b.startMs - previous > qMax(kGapColumns * columnMs, kGapMs);
        if (gap)
            path.moveTo(x, s.y(b.max));
        else
            path.lineTo(x, s.y(b.max));
        if (minAndMax && b.min != b.max)
            path.lineTo(x, s.y(b.min));
        previous = b.startMs;
    }
    return path;
}
} // namespace

Sparkline::Sparkline(Telemetry &telemetry, const QString &key, QWidget *parent)
    : QWidget(parent)
    , m_telemetry(telemetry)
    , m_key(key)
    , m_temperatureText([](qint32 c) { return QStringLiteral("%1 °C").arg(c); }) {
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setAccessibleName(tr("Last minute of tip temperature and power"));
    m_repaint.setSingleShot(true);
    connect(&m_repaint, &QTimer::timeout, this, qOverload<>(&QWidget::update));
    connect(&telemetry, &Telemetry::samplesAdded, this, [this](const QStringList &keys) {
        if (!keys.contains(m_key) || m_repaint.isActive() || !isVisible())
            return;
        const qint64 columnMs = kWindowMs / qMax(1, width() - 2);
        m_repaint.start(int(qBound(qint64(1000 / kMaxRepaintsPerSecond), columnMs, qint64(1000))));
    });
}

void Sparkline::setTemperatureText(std::function<QString(qint32)> text) {
    m_temperatureText = std::move(text);
    update();
}

const TelemetryBuffer *Sparkline::buffer() const {
    return m_telemetry.buffer(m_key);
}

QString Sparkline::rangeText() const {
    const TelemetryBuffer *b = buffer();
    const int tip = b ? b->seriesIndex(QStringLiteral("tip")) : -1;
    if (!b || tip < 0 || b->isEmpty())
        return tr("—");
    const qint64 t1 = b->lastTime() + 1;
    const auto stats = b->windowStats(tip, t1 - kWindowMs, t1);
    if (stats.count == 0)
        return tr("—");
    return tr("%1 to %2").arg(m_temperatureText(stats.min), m_temperatureText(stats.max));
}

void Sparkline::paintEvent(QPaintEvent *) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const QPalette::ColorGroup group = isEnabled() ? QPalette::Active : QPalette::Disabled;
    painter.setPen(palette().color(group, QPalette::Mid));
    painter.drawRect(rect().adjusted(0, 0, -1, -1));
    const TelemetryBuffer *b = buffer();
    if (!b || b->isEmpty()) {
        painter.setPen(palette().color(QPalette::Disabled, QPalette::WindowText));
        painter.drawText(rect(), Qt::AlignCenter, tr("no samples yet"));
        return;
    }
    const qint64 t1 = b->lastTime() + 1;
    paintSeries(painter, *b, t1 - kWindowMs, t1);
}

void Sparkline::paintSeries(QPainter &painter, const TelemetryBuffer &b, qint64 t0, qint64 t1) {
    const int tip = b.seriesIndex(QStringLiteral("tip"));
    const int setpoint = b.seriesIndex(QStringLiteral("setpoint"));
    const int power = b.seriesIndex(QStringLiteral("power"));
    const int columns = qMax(1, width() - 2);
    const auto data = b.decimate({tip, setpoint, power}, t0, t1, columns);
    const qint64 columnMs = qMax<qint64>(1, (t1 - t0) / columns);
    const auto tipStats = b.windowStats(tip, t0, t1);
    const auto setStats = b.windowStats(setpoint, t0, t1);
    qint32 low = qMin(tipStats.min, setStats.count ? setStats.min : tipStats.min);
    qint32 high = qMax(tipStats.max, setStats.count ? setStats.max : tipStats.max);
    if (high - low < kMinSpanCelsius) {
        const qint32 mid = (high + low) / 2;
        low = mid - kMinSpanCelsius / 2;
        high = mid + kMinSpanCelsius / 2;
    }
    const bool on = isEnabled();
    const QRectF area = QRectF(rect()).adjusted(1, 4, -1, -4);
    // Power: 0-100 % of the height, a translucent band under the temperatures.
    const Scale ps{area, t0, t1, 0, 1000};
    QColor powerColour =
        on ? QColor(0x00, 0x72, 0xB2) : palette().color(QPalette::Disabled, QPalette::WindowText);
    powerColour.setAlpha(70);
    // One filled pixel column per bucket: an antialiased line per column went through the
    // raster engine's stroker, which hands each one to a thread pool, and a full minute of them
    // took a quarter of a core at the line's sample rate.
    painter.setRenderHint(QPainter::Antialiasing, false);
    const int bottom = qRound(area.bottom());
    for (const MinMaxBucket &c : data.value(2)) {
        const int top = qRound(ps.y(c.max));
        if (top < bottom)
            painter.fillRect(qRound(ps.x(c.startMs + columnMs / 2)), top, 1, bottom - top,
                             powerColour);
    }
    painter.setRenderHint(QPainter::Antialiasing);
    Scale ts{area, t0, t1, double(low), double(high)};
    const QColor ink =
        palette().color(on ? QPalette::Active : QPalette::Disabled, QPalette::WindowText);
    painter.setPen(QPen(ink, 1, Qt::DashLine));
    painter.drawPath(columnPath(data.value(1), ts, columnMs, false));
    painter.setPen(QPen(on ? QColor(0xD5, 0x5E, 0x00) : ink, 1.6));
    painter.drawPath(columnPath(data.value(0), ts, columnMs, true));
    if (tipStats.count == 0)
        return;
    QFont small = font();
    small.setPointSizeF(small.pointSizeF() * 0.85);
    painter.setFont(small);
    painter.setPen(ink);
    const QRect text = rect().adjusted(kTextMargin, 1, -kTextMargin, -1);
    painter.drawText(text, Qt::AlignLeft | Qt::AlignTop, m_temperatureText(tipStats.max));
    painter.drawText(text, Qt::AlignLeft | Qt::AlignBottom, m_temperatureText(tipStats.min));
    painter.drawText(text, Qt::AlignRight | Qt::AlignBottom, tr("1 min"));
}

} // namespace tipscope::gui
