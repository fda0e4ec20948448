// MainWindow's plant view: File › Connect to plant watches the plant's broker (PlantWatch) and
// puts every device the line PCs publish on the fleet overview; a remote tile opens that
// device's read-only page. The status bar says where the broker connection stands.
#include "mainwindow.h"

#include "devicetree.h"
#include "dialogs/plantdialog.h"
#include "pages/fleet/fleetpage.h"
#include "pages/fleet/remotedevicepage.h"

#include <QLabel>
#include <QMenu>
#include <QStackedWidget>

namespace tipscope::gui {

void MainWindow::buildPlantMenu(QMenu &file) {
    file.addAction(tr("Connect to &plant…"), this, [this] {
        PlantDialog dialog(this);
        if (dialog.exec() == QDialog::Accepted)
            watchPlant(dialog.settings(), dialog.site());
    });
    m_stopWatchingPlant =
        file.addAction(tr("Disconnect from p&lant"), this, &MainWindow::stopWatchingPlant);
    m_stopWatchingPlant->setEnabled(false);
}

void MainWindow::watchPlant(const mqtt::MqttSettings &broker, const QString &site) {
    m_plant.start(broker, site);
    connect(&m_plant.client(), &mqtt::MqttClient::stateChanged, this,
            &MainWindow::updatePlantStatus);
    m_fleet->watchPlant(&m_plant);
    m_tree->setPlantWatched(true);
    m_tree->selectFleet();
    m_stopWatchingPlant->setEnabled(true);
    m_plantWhere = QStringLiteral("%1:%2").arg(broker.host).arg(broker.port);
    updatePlantStatus();
    updateBarNote();
}

void MainWindow::stopWatchingPlant() {
    m_fleet->watchPlant(nullptr);
    m_plant.stop();
    m_tree->setPlantWatched(false);
    m_stopWatchingPlant->setEnabled(false);
    if (m_stack->currentWidget() == m_remotePage)
        showFleet();
    m_plantWhere.clear();
    updatePlantStatus();
    updateBarNote();
}

void MainWindow::showRemoteDevice(const QString &root) {
    m_remotePage->showDevice(root);
    m_stack->setCurrentWidget(m_remotePage);
}

void MainWindow::updatePlantStatus() {
    m_plantLabel->setVisible(!m_plantWhere.isEmpty());
    if (m_plantWhere.isEmpty())
        return;
    const bool up = m_plant.client().state() == mqtt::MqttClient::State::Connected;
    const QString problem = m_plant.client().problemText();
    m_plantLabel->setText(up ? tr("Plant: %1").arg(m_plantWhere)
                             : tr("Plant: %1 not connected").arg(m_plantWhere));
    m_plantLabel->setToolTip(up ? tr("Watching %1 on the plant's broker").arg(m_plant.filter())
                                : problem);
    m_plantLabel->setStyleSheet(up ? QString() : QStringLiteral("color: #b35c00;"));
}

} // namespace tipscope::gui
