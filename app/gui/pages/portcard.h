// PortCard: one port of a station at a glance, readable from two metres: the tip temperature
// large, the setpoint, a power bar, the status (working, stand, sleep, hibernation, with
// cooling and suction), the tool, the transistor temperature, and any error or alarm in words.
// Under it the robot's own controls: work / stand / cool, and the selected temperature.
#pragma once

#include <QFrame>
#include <QPointer>

class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;

namespace tipscope::model {
class PortModel;
}

namespace tipscope::gui {

class DeferredRefresh;

class PortCard : public QFrame {
    Q_OBJECT
public:
    explicit PortCard(model::PortModel &port, QWidget *parent = nullptr);

    void setWritesAllowed(bool allowed);
    // What the card shows (brought up to date first if it was hidden).
    [[nodiscard]] QString tipText();
    [[nodiscard]] QString statusText();
    [[nodiscard]] QString problemText();
    // The robot controls, for keyboard users and tests: 0 work, 1 stand, 10 cool.
    QString requestMode(int mode);
    QString requestSetpoint(double displayValue);

private:
    void refresh();

    QPointer<model::PortModel> m_port;
    DeferredRefresh *m_refresh = nullptr;
    QLabel *m_title;
    QLabel *m_tip;
    QLabel *m_setpoint;
    QProgressBar *m_power;
    QLabel *m_status;
    QLabel *m_details;
    QLabel *m_problem;
    QPushButton *m_work;
    QPushButton *m_stand;
    QPushButton *m_cool;
    QDoubleSpinBox *m_newSetpoint;
    QPushButton *m_set;
    QLabel *m_feedback;
};

} // namespace tipscope::gui
