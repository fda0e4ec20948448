#include "devicetree.h"

#include <QFileInfo>
#include <QHeaderView>
#include <QPointer>
#include <QStyle>
#include <QTreeWidgetItemIterator>

namespace tipscope::gui {

using namespace tipscope::model;

namespace {
constexpr int kLineRole = Qt::UserRole;
constexpr int kDeviceRole = Qt::UserRole + 1;
constexpr int kPortRole = Qt::UserRole + 2;
} // namespace

DeviceTree::DeviceTree(Session &session, Workspace &workspace, QWidget *parent)
    : QTreeWidget(parent)
    , m_session(session)
    , m_workspace(workspace) {
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
    connect(&workspace, &Workspace::linesChanged, this, &DeviceTree::rebuild);
    connect(&workspace, &Workspace::lineDevicesChanged, this, &DeviceTree::rebuild);
    connect(&workspace, &Workspace::lineStateChanged, this, &DeviceTree::scheduleRelabel);
    // A port's model changes with every live value; its label (tool, error) far more rarely.
    m_relabel.setSingleShot(true);
    m_relabel.setInterval(kRelabelMs);
    connect(&m_relabel, &QTimer::timeout, this, &DeviceTree::relabel);
    connect(this, &QTreeWidget::currentItemChanged, this, [this] {
        Q_EMIT selectionChangedTo(selectedLine(), selectedDevice(), selectedPort());
    });
    rebuild();
}

Session *DeviceTree::sessionOf(int line) const {
    if (line == kBarLine)
        return &m_session;
    return line >= 0 && line < m_workspace.count() ? m_workspace.session(line) : nullptr;
}

QTreeWidgetItem *DeviceTree::lineItem(int line) const {
    for (int i = 0; i < topLevelItemCount(); ++i)
        if (topLevelItem(i)->data(0, kLineRole).toInt() == line)
            return topLevelItem(i);
    return nullptr;
}

int DeviceTree::selectedLine() const {
    const QTreeWidgetItem *item = currentItem();
    return item ? item->data(0, kLineRole).toInt() : kBarLine;
}

DeviceModel *DeviceTree::selectedDevice() const {
    const QTreeWidgetItem *item = currentItem();
    const Session *session = item ? sessionOf(item->data(0, kLineRole).toInt()) : nullptr;
    if (!session)
        return nullptr;
    const int index = item->data(0, kDeviceRole).toInt();
    return index > 0 ? session->devices().value(index - 1) : nullptr;
}

int DeviceTree::selectedPort() const {
    const QTreeWidgetItem *item = currentItem();
    return item ? item->data(0, kPortRole).toInt() : 0;
}

bool DeviceTree::select(int line, const DeviceModel *device, int port) {
    const Session *session = sessionOf(line);
    QTreeWidgetItem *top = lineItem(line);
    if (!device && top && line != kFleet) {
        setCurrentItem(top);
        return true;
    }
    const int index = session ? int(session->devices().indexOf(device)) : -1;
    if (!top || index < 0 || index >= top->childCount())
        return false;
    QTreeWidgetItem *item = top->child(index);
    for (int c = 0; port > 0 && c < item->childCount(); ++c)
        if (item->child(c)->data(0, kPortRole).toInt() == port)
            item = item->child(c);
    setCurrentItem(item);
    return true;
}

bool DeviceTree::selectFleet() {
    QTreeWidgetItem *fleet = lineItem(kFleet);
    if (!fleet)
        return false;
    setCurrentItem(fleet);
    return true;
}

void DeviceTree::setPlantWatched(bool watched) {
    if (watched == m_plantWatched)
        return;
    m_plantWatched = watched;
    rebuild();
}

void DeviceTree::rebuild() {
    const int line = selectedLine();
    const QPointer<DeviceModel> device = selectedDevice();
    const int port = selectedPort();
    blockSignals(true);
    clear();
    if (m_workspace.count() > 0 || m_plantWatched) {
        auto *fleet = new QTreeWidgetItem(this);
        fleet->setData(0, kLineRole, kFleet);
        fleet->setData(0, kDeviceRole, 0);
        fleet->setText(0, tr("Fleet overview"));
    }
    addLine(kBarLine);
    for (int i = 0; i < m_workspace.count(); ++i)
        addLine(i);
    // The connection bar's line is in the way of a workspace or a plant while it is not used.
    lineItem(kBarLine)->setHidden((m_workspace.count() > 0 || m_plantWatched) &&
                                  m_session.devices().isEmpty() &&
                                  m_session.state() == Session::State::Disconnected);
    expandAll();
    relabel();
    blockSignals(false);
    if (device && select(line, device, port))
        return;
    if (line == kFleet && selectFleet())
        return;
    for (int i = 0; i < topLevelItemCount(); ++i) {
        if (topLevelItem(i)->childCount() > 0) {
            setCurrentItem(topLevelItem(i)->child(0));
            return;
        }
    }
    setCurrentItem(nullptr);
    Q_EMIT selectionChangedTo(kBarLine, nullptr, 0);
}

void DeviceTree::addLine(int lineIndex) {
    auto *line = new QTreeWidgetItem(this);
    line->setData(0, kLineRole, lineIndex);
    line->setData(0, kDeviceRole, 0);
    Session *session = sessionOf(lineIndex);
    for (int i = 0; i < session->devices().size(); ++i) {
        DeviceModel *d = session->devices().at(i);
        auto *item = new QTreeWidgetItem(line);
        item->setData(0, kLineRole, lineIndex);
        item->setData(0, kDeviceRole, i + 1);
        if (auto *st = qobject_cast<StationModel *>(d)) {
            for (PortModel *port : st->ports()) {
                auto *p = new QTreeWidgetItem(item);
                p->setData(0, kLineRole, lineIndex);
                p->setData(0, kDeviceRole, i + 1);
                p->setData(0, kPortRole, port->number());
                connect(port, &PortModel::changed, this, &DeviceTree::scheduleRelabel);
            }
        }
    }
}

void DeviceTree::scheduleRelabel() {
    if (!m_relabel.isActive()) // not restarted: a busy port still gets a label
        m_relabel.start();
}

void DeviceTree::relabel() {
    for (int i = 0; i < topLevelItemCount(); ++i)
        if (topLevelItem(i)->data(0, kLineRole).toInt() != kFleet)
            relabelLine(topLevelItem(i));
    fitLabels();
}

void DeviceTree::relabelLine(QTreeWidgetItem *line) {
    const int lineIndex = line->data(0, kLineRole).toInt();
    Session *session = sessionOf(lineIndex);
    const QString where =
        session->line() ? session->line()->transport().description()
        : session->isPlayback()
            ? tr("recording %1").arg(QFileInfo(session->settings().recordingPath).fileName())
            : tr("No line");
    if (lineIndex == kBarLine) {
        line->setText(0, where);
    } else {
        const bool up = session->state() == Session::State::Connected;
        line->setText(0,
                      up ? tr("%1: %2").arg(m_workspace.line(lineIndex).name, where)
                         : tr("%1: %2 (%3)")
                               .arg(m_workspace.line(lineIndex).name, where, session->stateText()));
    }
    for (int i = 0; i < line->childCount(); ++i) {
        QTreeWidgetItem *item = line->child(i);
        DeviceModel *d = session->devices().value(item->data(0, kDeviceRole).toInt() - 1);
        if (!d)
            continue;
        const QString kind = qobject_cast<FeederModel *>(d) ? tr("feeder") : tr("station");
        // The name the workspace gives the device comes first, its model and address after.
        const QString given = lineIndex == kBarLine
                                  ? QString()
                                  : m_workspace.line(lineIndex).deviceName(d->address());
        const QString name =
            given.isEmpty() ? d->displayName() : tr("%1, %2").arg(given, d->displayName());
        item->setText(0, QStringLiteral("%1 (%2)").arg(name, kind));
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
