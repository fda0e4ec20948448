// PortCard: one port of a station at a glance, readable from two metres: the tip temperature
// large, the setpoint, a power bar, the status (working, stand, sleep, hibernation, with
// cooling and suction), the tool, the transistor temperature, and any error or alarm in words,
// and a sparkline of the last minute that takes the room the page has. Under it the robot's own
// controls: work / stand / cool, and the selected temperature (a value out of range is refused
// with the reason, never clamped). Beside the title, the port's last joint: its recovery time
// and verdict, in words and in the verdict's colour.
//
// A port in error says so in its status line, in red, and the whole card turns red (an alarm:
// amber), so it cannot be read as working. While the line is down the card is greyed and says
// when its values were last read, and the controls are off (the page says why).
//
// A busy line changes a port's values some fifteen times a second; the card shows them at most
// kMaxRefreshesPerSecond times a second (at once when it has not for that long), which a person
// cannot tell from every change and costs a repaint of every label a fraction as often. The line
// going down or up and another unit show at once.
#pragma once

#include "model/events/problemlevel.h"

#include <QElapsedTimer>
#include <QFrame>
#include <QPointer>
#include <QTimer>

class QLabel;
class QProgressBar;
class QPushButton;

namespace tipscope::model {
struct JointRecord;
class PortModel;
class Telemetry;
} // namespace tipscope::model

namespace tipscope::gui {

class DeferredRefresh;
class Sparkline;
class ValueSpinBox;

class PortCard : public QFrame {
    Q_OBJECT
public:
    static constexpr int kMaxRefreshesPerSecond = 5;

    PortCard(model::PortModel &port, model::Telemetry &telemetry, const QString &telemetryKey,
             QWidget *parent = nullptr);

    // Off in monitor-only mode and while the line is down; the page says why.
    void setWritesAllowed(bool allowed);
    // What the card shows (brought up to date first if it was hidden).
    [[nodiscard]] QString tipText();
    [[nodiscard]] QString statusText();
    [[nodiscard]] QString problemText();
    [[nodiscard]] QString staleText(); // "last read 14:02:11" while the line is down
    [[nodiscard]] QString feedbackText() const;
    // The power as written beside its bar ("power 40.7 %").
    [[nodiscard]] QString powerText();
    [[nodiscard]] model::PortModel *port() const { return m_port; }
    // The port's last joint beside the title ("last joint 1.4 s, ok").
    void showJoint(const model::JointRecord &joint);
    [[nodiscard]] QString jointText() const;
    // The card's look: Error, Warning or Ok; Unknown while its values are stale.
    [[nodiscard]] model::Level look();
    [[nodiscard]] bool controlsEnabled() const;
    // The robot controls, for keyboard users and tests: 0 work, 1 stand, 10 cool.
    QString requestMode(int mode);
    QString requestSetpoint(double displayValue);

private:
    static void showLine(QLabel *label, const QString &text);
    void onPortChanged();
    // Shows what is due now, paced or deferred, before what the card shows is read.
    void settle();
    void refresh();
    void refreshProblem();
    void refreshSetpointEditor();
    void applyLook(model::Level level);
    void showFeedback(const QString &why);

    QPointer<model::PortModel> m_port;
    DeferredRefresh *m_refresh = nullptr;
    QTimer m_pace;
    QElapsedTimer m_lastRefresh;
    // What the setpoint editor was last set to, so that an unchanged range or unit costs nothing.
    struct EditorFrame {
        QString suffix;
        double step = 0;
        double minimum = 0;
        double maximum = 0;
        [[nodiscard]] bool sameAs(const EditorFrame &o) const {
            return suffix == o.suffix && step == o.step && minimum == o.minimum &&
                   maximum == o.maximum;
        }
    } m_editorFrame;
    QLabel *m_title;
    QLabel *m_joint;
    QLabel *m_tip;
    QLabel *m_setpoint;
    QLabel *m_powerText = nullptr;
    QProgressBar *m_power;
    QLabel *m_status;
    QLabel *m_details;
    QLabel *m_problem;
    QLabel *m_stale;
    Sparkline *m_sparkline;
    QWidget *m_values; // everything that greys while the line is down
    QPushButton *m_work;
    QPushButton *m_stand;
    QPushButton *m_cool;
    ValueSpinBox *m_newSetpoint;
    QPushButton *m_set;
    QLabel *m_feedback;
    model::Level m_look = model::Level::Ok;      // what the port's values say
    model::Level m_shownLook = model::Level::Ok; // Unknown instead while they are stale
};

} // namespace tipscope::gui
