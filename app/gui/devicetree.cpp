#include "devicetree.h"

#include <QHeaderView>

namespace tipscope::gui {

using namespace tipscope::model;

namespace {
constexpr int kDeviceRole = Qt::UserRole + 1;
constexpr int kPortRole = Qt::UserRole + 2;
} // namespace

DeviceTree::DeviceTree(Session &session, QWidget *parent)
    : QTreeWidget(parent)
    , m_session(session) {
    setHeaderHidden(true);
    setAccessibleName(tr("Devices"));
    setMinimumWidth(200);
    connect(&session, &Session::devicesChanged, this, &DeviceTree::rebuild);
    connect(&session, &Session::stateChanged, this, &DeviceTree::relabel);
    // A port's model changes with every live value; its label (tool, error) far more rarely.
    m_relabel.setSingleShot(true);
    m_relabel.setInterval(kRelabelMs);
    connect(&m_relabel, &QTimer::timeout, this, &DeviceTree::relabel);
    connect(this, &QTreeWidget::currentItemChanged, this,
            [this] { Q_EMIT selectionChangedTo(selectedDevice(), selectedPort()); });
    rebuild();
}

DeviceModel *DeviceTree::selectedDevice() const {
    const QTreeWidgetItem *item = currentItem();
    if (!item)
        return nullptr;
    const int index = item->data(0, kDeviceRole).toInt();
    return index > 0 ? m_session.devices().value(index - 1) : nullptr;
}

int DeviceTree::selectedPort() const {
    const QTreeWidgetItem *item = currentItem();
    return item ? item->data(0, kPortRole).toInt() : 0;
}

void DeviceTree::rebuild() {
    blockSignals(true);
    clear();
    auto *line = new QTreeWidgetItem(this);
    line->setData(0, kDeviceRole, 0);
    for (int i = 0; i < m_session.devices().size(); ++i) {
        DeviceModel *d = m_session.devices().at(i);
        auto *item = new QTreeWidgetItem(line);
        item->setData(0, kDeviceRole, i + 1);
        if (auto *st = qobject_cast<StationModel *>(d)) {
            for (PortModel *port : st->ports()) {
                auto *p = new QTreeWidgetItem(item);
                p->setData(0, kDeviceRole, i + 1);
                p->setData(0, kPortRole, port->number());
                connect(port, &PortModel::changed, this, [this] {
                    if (!m_relabel.isActive()) // not restarted: a busy port still gets a label
                        m_relabel.start();
                });
            }
        }
    }
    expandAll();
    relabel();
    blockSignals(false);
    if (line->childCount() > 0)
        setCurrentItem(line->child(0));
    else
        Q_EMIT selectionChangedTo(nullptr, 0);
}

void DeviceTree::relabel() {
    QTreeWidgetItem *line = topLevelItem(0);
    if (!line)
        return;
    line->setText(0,
                  m_session.line() ? m_session.line()->transport().description() : tr("No line"));
    for (int i = 0; i < line->childCount(); ++i) {
        QTreeWidgetItem *item = line->child(i);
        DeviceModel *d = m_session.devices().value(item->data(0, kDeviceRole).toInt() - 1);
        if (!d)
            continue;
        const QString kind = qobject_cast<FeederModel *>(d) ? tr("feeder") : tr("station");
        item->setText(0, QStringLiteral("%1 (%2)").arg(d->displayName(), kind));
        auto *st = qobject_cast<StationModel *>(d);
        for (int c = 0; st && c < item->childCount(); ++c) {
            PortModel *port = st->port(item->child(c)->data(0, kPortRole).toInt());
            QString text = tr("Port %1: %2").arg(port->number()).arg(port->toolName());
            if (const auto e = port->error(); e && *e != 0)
                text += QStringLiteral(" ⚠");
            item->child(c)->setText(0, text);
        }
    }
}

} // namespace tipscope::gui
