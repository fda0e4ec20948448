#include "consolemodel.h"

#include "model/session.h"

#include "base/atomicsave.h"
#include "protocol/catalog.h"
#include "protocol/datafield.h"
#include "protocol/hexbytes.h"

#include <QBrush>
#include <QColor>
#include <QCoreApplication>
#include <QDateTime>

namespace tipscope::model {

using namespace tipscope::protocol;

namespace {
struct ConsoleModelTr {
    Q_DECLARE_TR_FUNCTIONS(ConsoleModel)
};

// The command's name for the device's family; for a device not known (yet), in any family that
// has it.
QString commandName(const Frame &f, const QString &family) {
    const Catalog &cat = Catalog::builtin();
    const Direction dir = f.header == Header::Write ? Direction::Write : Direction::Read;
    if (!family.isEmpty())
        if (auto r = cat.resolve(family, f.command, dir))
            return catalogText(r->spec->name);
    for (const QString &fam : cat.familyNames())
        if (auto r = cat.resolve(fam, f.command, dir))
            return catalogText(r->spec->name);
    return {};
}
} // namespace

ConsoleModel::ConsoleModel(QObject *parent, int capacity)
    : QAbstractTableModel(parent)
    , m_batch(this)
    , m_capacity(qMax(10, capacity)) {
    m_batch.setSingleShot(true);
    m_batch.setInterval(kBatchMs);
    connect(&m_batch, &QTimer::timeout, this, &ConsoleModel::flush);
}

void ConsoleModel::attach(link::FrameTap *tap) {
    disconnect(m_connection);
    m_tap = tap;
    if (tap)
        m_connection = connect(tap, &link::FrameTap::event, this,
                               [this](const link::TapEvent &e) { add(fromTap(e)); });
}

void ConsoleModel::follow(Session *session) {
    for (const QMetaObject::Connection &c : std::as_const(m_sessionConnections))
        disconnect(c);
    m_sessionConnections.clear();
    m_session = session;
    if (session)
        m_sessionConnections = {
            connect(session, &Session::stateChanged, this, &ConsoleModel::followLine),
            connect(session, &Session::devicesChanged, this, &ConsoleModel::followDevices),
            connect(session, &Session::monitorOnlyChanged, &m_sender,
                    &ConsoleSender::setMonitorOnly)};
    m_sender.setMonitorOnly(session && session->monitorOnly());
    followLine();
    followDevices();
}

void ConsoleModel::followLine() {
    link::Line *line = m_session ? m_session->line() : nullptr;
    link::RequestQueue *queue = line ? &line->queue() : nullptr;
    // The tap is gone with its line, so a new line (a new connectTo()) is never taken for the
    // old one, even when it reuses the old one's address.
    if (queue && &queue->tap() == m_tap)
        return;
    attach(queue ? &queue->tap() : nullptr);
    m_sender.attach(queue);
}

void ConsoleModel::followDevices() {
    QMap<int, QString> families;
    if (m_session)
        for (const DeviceModel *d : m_session->devices())
            families.insert(d->address().value_or(-1), d->family());
    setDeviceFamilies(families);
}

ConsoleEntry ConsoleModel::fromTap(const link::TapEvent &e) {
    ConsoleEntry c;
    c.wallMs = e.wallMs;
    c.monotonicUs = e.monotonicUs;
    switch (e.kind) {
    case link::TapEvent::Kind::Tx:
        c.direction = ConsoleEntry::Direction::Tx;
        c.bytes = e.bytes;
        if (auto f = parseFrame(e.bytes))
            c.frame = std::move(f).value();
        else
            c.remark = ConsoleModelTr::tr("sent as typed (not a valid frame)");
        break;
    case link::TapEvent::Kind::Rx:
        c.direction = ConsoleEntry::Direction::Rx;
        c.bytes = e.bytes;
        break;
    case link::TapEvent::Kind::Decoded:
        c.bytes = e.decoded.raw;
        if (e.decoded.kind == DecodeEvent::Kind::Frame) {
            c.direction = ConsoleEntry::Direction::Decoded;
            c.frame = e.decoded.frame;
            c.stray = e.stray;
            if (e.decoded.frame.header == Header::Nak)
                c.remark = Catalog::builtin().nakText(
                    parseNumber(e.decoded.frame.data).value_or(-1), Wording::Translated);
            if (e.stray)
                c.remark = ConsoleModelTr::tr("stray: answers no pending request");
        } else {
            c.direction = ConsoleEntry::Direction::Error;
            c.bccOk = e.decoded.kind != DecodeEvent::Kind::BccError;
            c.remark =
                decodeEventKindName(e.decoded.kind) + QStringLiteral(": ") + e.decoded.detail;
        }
        break;
    case link::TapEvent::Kind::Note:
        c.direction = ConsoleEntry::Direction::Note;
        c.remark = e.note;
        break;
    }
    return c;
}

void ConsoleModel::setDeviceFamilies(const QMap<int, QString> &byAddress) {
    if (byAddress == m_families)
        return;
    m_families = byAddress;
    // Rows from before the devices were known (discovery's probes) get their names now.
    int first = -1, last = -1;
    for (int row = 0; row < int(m_entries.size()); ++row) {
        ConsoleEntry &e = m_entries[size_t(row)];
        if (!e.family.isEmpty() || !e.frame)
            continue;
        e.family = familyOf(e);
        if (e.family.isEmpty())
            continue;
        first = first < 0 ? row : first;
        last = row;
    }
    for (QList<ConsoleEntry> *queue : {&m_pending, &m_held})
        for (ConsoleEntry &e : *queue)
            if (e.family.isEmpty())
                e.family = familyOf(e);
    if (first >= 0)
        Q_EMIT dataChanged(index(first, Name), index(last, Name));
}

QString ConsoleModel::familyOf(const ConsoleEntry &e) const {
    if (!e.frame || m_families.isEmpty())
        return {};
    // A request names the device it goes to, an answer the device it comes from.
    const std::optional<int> device =
        e.direction == ConsoleEntry::Direction::Tx ? e.frame->target : e.frame->source;
    return m_families.value(device.value_or(-1));
}

void ConsoleModel::add(const ConsoleEntry &e) {
    QList<ConsoleEntry> &queue = m_paused ? m_held : m_pending;
    queue.append(e);
    queue.last().family = familyOf(e);
    if (queue.size() > m_capacity) // older than anything the table could still show
        queue.removeFirst();
    if (m_paused)
        Q_EMIT heldCountChanged(heldCount());
    else if (!m_batch.isActive())
        m_batch.start();
}

void ConsoleModel::flush() {
    m_batch.stop();
    if (m_pending.isEmpty())
        return;
    const QList<ConsoleEntry> batch = std::exchange(m_pending, {});
    if (m_originUs < 0)
        m_originUs = batch.constFirst().monotonicUs;
    const int overflow =
        qMin(int(m_entries.size()), int(m_entries.size() + batch.size()) - m_capacity);
    if (overflow > 0) {
        beginRemoveRows({}, 0, overflow - 1);
        m_entries.erase(m_entries.begin(), m_entries.begin() + overflow);
        endRemoveRows();
    }
    const int row = int(m_entries.size());
    beginInsertRows({}, row, row + int(batch.size()) - 1);
    m_entries.insert(m_entries.end(), batch.begin(), batch.end());
    endInsertRows();
}

void ConsoleModel::setPaused(bool paused) {
    if (paused)
        flush(); // what arrived before the pause is shown, not held
    m_paused = paused;
    if (paused)
        return;
    const bool held = !m_held.isEmpty();
    m_pending.append(std::exchange(m_held, {}));
    while (m_pending.size() > m_capacity)
        m_pending.removeFirst();
    flush();
    if (held)
        Q_EMIT heldCountChanged(0);
}

void ConsoleModel::setRelativeTime(bool relative) {
    m_relative = relative;
    if (!m_entries.empty())
        Q_EMIT dataChanged(index(0, Time), index(int(m_entries.size()) - 1, Time));
}

void ConsoleModel::clear() {
    beginResetModel();
    m_entries.clear();
    m_pending.clear();
    const bool held = !m_held.isEmpty();
    m_held.clear();
    m_batch.stop();
    m_originUs = -1;
    endResetModel();
    if (held)
        Q_EMIT heldCountChanged(0);
}

int ConsoleModel::rowCount(const QModelIndex &parent) const {
    return parent.isValid() ? 0 : int(m_entries.size());
}

int ConsoleModel::columnCount(const QModelIndex &parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QString ConsoleModel::timeText(const ConsoleEntry &e) const {
    if (m_relative)
        return QStringLiteral("+%1 s").arg((e.monotonicUs - m_originUs) / 1e6, 0, 'f', 4);
    return QDateTime::fromMSecsSinceEpoch(e.wallMs).toString(QStringLiteral("HH:mm:ss.zzz"));
}

QString ConsoleModel::directionText(ConsoleEntry::Direction d) {
    switch (d) {
    case ConsoleEntry::Direction::Tx:
        return ConsoleModelTr::tr("TX");
    case ConsoleEntry::Direction::Rx:
        return ConsoleModelTr::tr("RX chunk");
    case ConsoleEntry::Direction::Decoded:
        return ConsoleModelTr::tr("RX");
    case ConsoleEntry::Direction::Error:
        return ConsoleModelTr::tr("error");
    case ConsoleEntry::Direction::Note:
        return ConsoleModelTr::tr("note");
    }
    return {};
}

QString ConsoleModel::headerText(protocol::Header h) {
    switch (h) {
    case protocol::Header::Read:
        return ConsoleModelTr::tr("Read");
    case protocol::Header::Write:
        return ConsoleModelTr::tr("Write");
    case protocol::Header::Answer:
        return ConsoleModelTr::tr("Answer");
    case protocol::Header::Nak:
        break;
    }
    return headerName(h); // the protocol's word for a refusal, the same in every language
}

QVariant ConsoleModel::data(const QModelIndex &index, int role) const {
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const ConsoleEntry &e = m_entries.at(size_t(index.row()));
    if (role == Qt::ForegroundRole) {
        if (e.direction == ConsoleEntry::Direction::Error || !e.bccOk)
            return QBrush(QColor(0xc0, 0x1c, 0x28));
        if (e.frame && e.frame->header == Header::Nak)
            return QBrush(QColor(0xc0, 0x1c, 0x28));
        if (e.stray)
            return QBrush(QColor(0xb5, 0x83, 0x5a));
        return {};
    }
    if (role != Qt::DisplayRole && role != Qt::ToolTipRole)
        return {};
    const std::optional<Frame> &f = e.frame;
    switch (index.column()) {
    case Time:
        return timeText(e);
    case Direction:
        return directionText(e.direction);
    case Device:
        return f && f->isAddressed() ? QStringLiteral("%1→%2")
                                           .arg(*f->source, 2, 10, QLatin1Char('0'))
                                           .arg(*f->target, 2, 10, QLatin1Char('0'))
                                     : QString();
    case Header:
        return f ? headerText(f->header) : QString();
    case Command:
        return f ? QString::fromLatin1(f->command) : QString();
    case Name:
        return f ? commandName(*f, e.family) : QString();
    case Data:
        return f ? QString::fromLatin1(f->data) : QString();
    case Bcc:
        if (e.direction == ConsoleEntry::Direction::Rx ||
            e.direction == ConsoleEntry::Direction::Note)
            return QString();
        return e.bccOk ? ConsoleModelTr::tr("ok") : ConsoleModelTr::tr("bad");
    case Hex:
        return toHexText(e.bytes);
    case Ascii:
        return toAsciiText(e.bytes);
    case Remark:
        return e.remark;
    default:
        return {};
    }
}

QVariant ConsoleModel::headerData(int section, Qt::Orientation o, int role) const {
    if (o != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    static const char *names[] = {
        QT_TRANSLATE_NOOP("ConsoleModel", "Time"),  QT_TRANSLATE_NOOP("ConsoleModel", "Dir"),
        QT_TRANSLATE_NOOP("ConsoleModel", "Addr"),  QT_TRANSLATE_NOOP("ConsoleModel", "Header"),
        QT_TRANSLATE_NOOP("ConsoleModel", "Cmd"),   QT_TRANSLATE_NOOP("ConsoleModel", "Name"),
        QT_TRANSLATE_NOOP("ConsoleModel", "Data"),  QT_TRANSLATE_NOOP("ConsoleModel", "BCC"),
        QT_TRANSLATE_NOOP("ConsoleModel", "Hex"),   QT_TRANSLATE_NOOP("ConsoleModel", "ASCII"),
        QT_TRANSLATE_NOOP("ConsoleModel", "Remark")};
    return section >= 0 && section < ColumnCount
               ? QCoreApplication::translate("ConsoleModel", names[section])
               : QVariant();
}

QString ConsoleModel::lineText(int row) const {
    QStringList cells;
    for (int c = 0; c < ColumnCount; ++c)
        cells.append(data(index(row, c), Qt::DisplayRole).toString());
    return cells.join(QLatin1Char('\t'));
}

base::Outcome<void> ConsoleModel::saveText(const QString &path) const {
    QStringList header;
    for (int c = 0; c < ColumnCount; ++c)
        header.append(headerData(c, Qt::Horizontal, Qt::DisplayRole).toString());
    QByteArray text = header.join(QLatin1Char('\t')).toUtf8() + '\n';
    for (int r = 0; r < rowCount(); ++r)
        text += lineText(r).toUtf8() + '\n';
    return base::io::saveAtomically(path, text);
}

bool ConsoleModel::filterAccepts(int row, const Filter &filter) const {
    const ConsoleEntry &e = m_entries.at(size_t(row));
    switch (e.direction) {
    case ConsoleEntry::Direction::Tx:
        if (!filter.tx)
            return false;
        break;
    case ConsoleEntry::Direction::Rx:
        if (!filter.rx)
            return false;
        break;
    case ConsoleEntry::Direction::Decoded:
        if (!filter.decoded)
            return false;
        break;
    case ConsoleEntry::Direction::Error:
        if (!filter.errors)
            return false;
        break;
    case ConsoleEntry::Direction::Note:
        if (!filter.notes)
            return false;
        break;
    }
    if (filter.address &&
        (!e.frame || (e.frame->source != filter.address && e.frame->target != filter.address)))
        return false;
    if (!filter.command.isEmpty() &&
        (!e.frame ||
         !QString::fromLatin1(e.frame->command).contains(filter.command, Qt::CaseInsensitive)))
        return false;
    return true;
}

} // namespace tipscope::model
