#include "dialogs/plantdialog.h"

#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QSysInfo>

namespace tipscope::gui {

namespace {
const QString kHostKey = QStringLiteral("plant/host");
const QString kPortKey = QStringLiteral("plant/port");
const QString kUserKey = QStringLiteral("plant/user");
const QString kSiteKey = QStringLiteral("plant/site");
} // namespace

PlantDialog::PlantDialog(QWidget *parent)
    : QDialog(parent) {
    setWindowTitle(tr("Connect to plant"));
    const QSettings store;
    m_host = new QLineEdit(store.value(kHostKey, QStringLiteral("localhost")).toString(), this);
    m_port = new QSpinBox(this);
    m_port->setRange(1, 65535);
    m_port->setValue(store.value(kPortKey, 1883).toInt());
    m_user = new QLineEdit(store.value(kUserKey).toString(), this);
    m_password = new QLineEdit(this);
    m_password->setEchoMode(QLineEdit::Password);
    m_site = new QLineEdit(store.value(kSiteKey).toString(), this);
    m_site->setPlaceholderText(tr("every site"));
    auto *note = new QLabel(tr("The fleet overview shows every device the line PCs publish there; "
                               "their pages are read-only. This window publishes nothing."),
                            this);
    note->setWordWrap(true);
    auto *form = new QFormLayout;
    form->addRow(tr("&Broker:"), m_host);
    form->addRow(tr("P&ort:"), m_port);
    form->addRow(tr("&User name:"), m_user);
    form->addRow(tr("&Password:"), m_password);
    form->addRow(tr("&Site:"), m_site);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Connect"));
    connect(buttons, &QDialogButtonBox::accepted, this, &PlantDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(note);
    layout->addLayout(form);
    layout->addWidget(buttons);
}

mqtt::MqttSettings PlantDialog::settings() const {
    mqtt::MqttSettings s;
    s.host = m_host->text().trimmed();
    s.port = m_port->value();
    s.username = m_user->text().trimmed();
    s.password = m_password->text().toUtf8();
    s.clientId = QStringLiteral("tipscope-view-%1-%2")
                     .arg(QSysInfo::machineHostName())
                     .arg(QCoreApplication::applicationPid());
    return s;
}

QString PlantDialog::site() const {
    return m_site->text().trimmed();
}

void PlantDialog::accept() {
    if (m_host->text().trimmed().isEmpty()) {
        m_host->setFocus();
        m_host->setPlaceholderText(tr("the broker's host name or address"));
        return;
    }
    QSettings store;
    store.setValue(kHostKey, m_host->text().trimmed());
    store.setValue(kPortKey, m_port->value());
    store.setValue(kUserKey, m_user->text().trimmed());
    store.setValue(kSiteKey, site());
    QDialog::accept();
}

} // namespace tipscope::gui
