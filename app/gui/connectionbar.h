// ConnectionBar: where the line is and how to talk to it: a serial port (listed with its
// adapter, refreshed when adapters come and go; plain RS-232 ports too), a TCP serial server, or
// the built-in demo; baud, parity, stop bits; addressing (auto, with, without) and addresses;
// Connect / Disconnect; monitor-only; and the line's state, always visible, in words and colour.
#pragma once

#include "model/appsettings.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace tipscope::link {
class SerialPortList;
}

namespace tipscope::gui {

class ConnectionBar : public QWidget {
    Q_OBJECT
public:
    explicit ConnectionBar(QWidget *parent = nullptr);

    void setSettings(const model::AppSettings &settings);
    // The bar's fields written over `base` (which carries the preferences).
    [[nodiscard]] model::AppSettings settings(const model::AppSettings &base) const;
    void setState(model::Session::State state, const QString &text);
    // What else the window runs, said beside an unused bar ("the workspace's 32 lines are in
    // the tree"), so that its "Disconnected" is not read as the fleet's; empty: nothing else.
    void setBesideNote(const QString &note);
    void setMonitorOnly(bool on);
    [[nodiscard]] QString stateText() const;

Q_SIGNALS:
    void connectRequested();
    void disconnectRequested();
    void monitorOnlyToggled(bool on);

private:
    void updateVisibility();
    void refreshPorts();

    QComboBox *m_kind;
    QComboBox *m_port;
    QLineEdit *m_tcp;
    QComboBox *m_baud;
    QComboBox *m_parity;
    QComboBox *m_stopBits;
    QComboBox *m_addressing;
    QSpinBox *m_robot;
    QSpinBox *m_target;
    QPushButton *m_connect;
    QCheckBox *m_monitorOnly;
    QLabel *m_state;
    link::SerialPortList *m_ports;
    bool m_connected = false;
    model::Session::State m_stateShown = model::Session::State::Disconnected;
    QString m_stateText;
    QString m_besideNote;
};

} // namespace tipscope::gui
