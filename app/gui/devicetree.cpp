#include "devicetree.h"

#include <QHeaderView>
#include <QStyle>
#include <QTreeWidgetItemIterator>

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
    // German labels are long ("SFR-A, Adresse 10 (Lotdrahtvorschub)") and so are some tools'
    // names ("T245/T470 (TR245/TR470)"); the pages leave the tree no more width at 1280 px, so a
    // label wraps at its spaces instead of being cut.
    setWordWrap(true);
    setTextElideMode(Qt::ElideNone);
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
    fitLabels();
}

// QTreeView wraps a long label but keeps one line's height for its row, which hides the rest:
// each row is given the height of its label wrapped to the width the tree has.
void DeviceTree::fitLabels() {
    const QFontMetrics metrics(font());
    // The delegate's text margins, and two pixels more: a row a line too high beats a line cut.
    const int margins =
        2 * (style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, this) + 1) + 2;
    for (QTreeWidgetItemIterator it(this); *it; ++it) {
        QTreeWidgetItem *item = *it;
        item->setToolTip(0, item->text(0)); // whole, wherever a single word is wider than the tree
        int depth = 1;
        for (const QTreeWidgetItem *p = item->parent(); p; p = p->parent())
            ++depth;
        const int width = qMax(1, viewport()->width() - indentation() * depth - margins);
        const QRect text =
            metrics.boundingRect(QRect(0, 0, width, 0), Qt::TextWordWrap, item->text(0));
        const int lines = qMax(1, text.height() / metrics.lineSpacing());
        const QSize hint =
            lines > 1 ? QSize(text.width(), text.height() + metrics.height() / 2) : QSize();
        if (item->sizeHint(0) != hint)
            item->setSizeHint(0, hint);
    }
}

void DeviceTree::resizeEvent(QResizeEvent *event) {
    QTreeWidget::resizeEvent(event);
    fitLabels(); // wider or narrower, a label takes fewer or more lines
}

} // namespace tipscope::gui
