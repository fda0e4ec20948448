// PlantDialog: where the plant's broker is and who to be there, for File › Connect to plant: the
// broker's host and port, a user name and password, and the site to watch (empty: every site).
// The address, user and site are remembered for next time; the password never is.
#pragma once

#include "mqtt/mqttsettings.h"

#include <QDialog>

class QLineEdit;
class QSpinBox;

namespace tipscope::gui {

class PlantDialog : public QDialog {
    Q_OBJECT
public:
    explicit PlantDialog(QWidget *parent = nullptr);

    [[nodiscard]] mqtt::MqttSettings settings() const;
    [[nodiscard]] QString site() const;
    void accept() override;

private:
    QLineEdit *m_host;
    QSpinBox *m_port;
    QLineEdit *m_user;
    QLineEdit *m_password;
    QLineEdit *m_site;
};

} // namespace tipscope::gui
