// Sparkline: the last minute of one port at a glance, for the Overview's cards: the tip
// temperature (a solid line, min and max per pixel column so a dip is never lost), the setpoint
// (dashed) and the power (a filled band at the bottom, 0-100 %), drawn from the session's
// telemetry buffer of the port, with the window's lowest and highest tip temperature written at
// the left. It draws only what was recorded: no line before the first sample, a gap where none
// came. Disabled (the line is down), it is drawn in the disabled palette, ending at the last
// sample it has.
//
// A line makes some seventy samples a second, while a minute across a card's width moves by a
// pixel column about every 150 ms: repaints follow the samples no more often than that (and at
// most kMaxRepaintsPerSecond), so four cards cost the window little and never the wire.
#pragma once

#include <QTimer>
#include <QWidget>
#include <functional>

class QPainter;

namespace tipscope::model {
class Telemetry;
class TelemetryBuffer;
} // namespace tipscope::model

namespace tipscope::gui {

class Sparkline : public QWidget {
    Q_OBJECT
public:
    static constexpr qint64 kWindowMs = 60000;
    static constexpr int kMaxRepaintsPerSecond = 10;

    Sparkline(model::Telemetry &telemetry, const QString &key, QWidget *parent = nullptr);

    // How a tip temperature in wire units (°C) reads, for the range text; set by the owner, which
    // knows the unit people chose.
    void setTemperatureText(std::function<QString(qint32)> text);
    // The lowest and highest tip temperature of the window as shown ("—" without samples).
    [[nodiscard]] QString rangeText() const;
    [[nodiscard]] QSize sizeHint() const override { return {240, 64}; }
    [[nodiscard]] QSize minimumSizeHint() const override { return {80, 36}; }

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    [[nodiscard]] const model::TelemetryBuffer *buffer() const;
    void paintSeries(QPainter &painter, const model::TelemetryBuffer &b, qint64 t0, qint64 t1);

    model::Telemetry &m_telemetry;
    QString m_key;
    std::function<QString(qint32)> m_temperatureText;
    QTimer m_repaint;
};

} // namespace tipscope::gui
