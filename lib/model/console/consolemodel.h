// ConsoleModel: the raw frame console's data, apart from its widget.
//
// It keeps the last `capacity` entries of the line's FrameTap (TX and RX chunks, decoded frames
// and decode errors, line notes) and presents them as a table: time, direction, device, header,
// command and its catalog name, data, BCC, hex, ASCII, and a remark (error or NAK meaning). While
// paused, new entries wait in a buffer and appear on resume, so pausing loses nothing. Entries
// reach the table in batches, at most every kBatchMs (or at flush()): a busy line taps a few
// hundred events a second, and a row inserted at a time kept the filter proxy and the view busy
// even with the console hidden. Filters (direction, device address, command text) act on the
// view through filterAccepts(). Received frames are labelled RX, the chunks they arrived in
// "RX chunk", and headers are named in the user interface language. Sending goes through
// sender(), which owns the monitor-only gate;
// follow() keeps the table, the sender and the commands' names with a Session's current line.
#pragma once

#include "consolesender.h"

#include "base/outcome.h"
#include "link/frametap.h"

#include <QAbstractTableModel>
#include <QMap>
#include <QPointer>
#include <QTimer>
#include <deque>

namespace tipscope::model {

class Session;

struct ConsoleEntry {
    enum class Direction { Tx, Rx, Decoded, Error, Note };
    qint64 wallMs = 0;
    qint64 monotonicUs = 0;
    Direction direction = Direction::Tx;
    QByteArray bytes;
    std::optional<protocol::Frame> frame;
    QString remark;
    bool bccOk = true;
    bool stray = false;
    // The family of the device in the frame, as known when the entry arrived (or when the
    // devices were found, for the frames that found them); empty when not known.
    QString family;
};

class ConsoleModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        Time,
        Direction,
        Device,
        Header,
        Command,
        Name,
        Data,
        Bcc,
        Hex,
        Ascii,
        Remark,
        ColumnCount
    };

    static constexpr int kBatchMs = 100;

    explicit ConsoleModel(QObject *parent = nullptr, int capacity = 20000);

    void attach(link::FrameTap *tap);
    // Shows the tap of the session's line and sends on it, from now on and after every
    // reconnection, names commands by its devices' families and takes its monitor-only setting.
    // Null: none of it (the rows stay).
    void follow(Session *session);
    [[nodiscard]] ConsoleSender &sender() { return m_sender; }
    void setPaused(bool paused);
    [[nodiscard]] bool isPaused() const { return m_paused; }
    // Rows that arrived while paused and appear on resume; heldCountChanged() says each change.
    [[nodiscard]] int heldCount() const { return int(m_held.size()); }
    // How many rows are kept: older ones go as new ones come (a busy line fills it in minutes).
    [[nodiscard]] int capacity() const { return m_capacity; }
    void setRelativeTime(bool relative);
    // The families of the devices on the line by address (-1: the device of a line without
    // addresses), so a code that families share is named as the device in the frame knows it:
    // SPD is the feeder's feeding speed and the ALE's dispensing speed. Each entry keeps the
    // family it got, so rows stay named after a disconnect or when other devices are found.
    void setDeviceFamilies(const QMap<int, QString> &byAddress);
    void clear();
    // Shows the entries that arrived since the last batch now.
    void flush();
    // How long new entries wait to reach the table (kBatchMs unless set). Nothing is lost to a
    // longer wait; a console nobody looks at takes them in fewer, larger batches.
    void setBatchMs(int ms) { m_batch.setInterval(qMax(1, ms)); }

    [[nodiscard]] int rowCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] int columnCount(const QModelIndex &parent = {}) const override;
    [[nodiscard]] QVariant data(const QModelIndex &index, int role) const override;
    [[nodiscard]] QVariant headerData(int section, Qt::Orientation o, int role) const override;

    [[nodiscard]] const ConsoleEntry &entry(int row) const { return m_entries.at(size_t(row)); }
    [[nodiscard]] static ConsoleEntry fromTap(const link::TapEvent &e);
    // What the Dir column says for a kind of row ("TX", "RX", "RX chunk", ...).
    [[nodiscard]] static QString directionText(ConsoleEntry::Direction d);
    // What the Header column says, in the user interface language ("Read", "Answer", ...).
    [[nodiscard]] static QString headerText(protocol::Header h);
    // One line per entry, as shown; for "save to file".
    [[nodiscard]] QString lineText(int row) const;
    // Every entry, with a header line, tab-separated; saved atomically.
    [[nodiscard]] base::Outcome<void> saveText(const QString &path) const;

    struct Filter {
        bool tx = true, rx = true, decoded = true, errors = true, notes = true;
        std::optional<int> address;
        QString command;
    };
    [[nodiscard]] bool filterAccepts(int row, const Filter &filter) const;

Q_SIGNALS:
    void heldCountChanged(int held);

private:
    void add(const ConsoleEntry &e);
    void followLine();
    void followDevices();
    [[nodiscard]] QString timeText(const ConsoleEntry &e) const;
    [[nodiscard]] QString familyOf(const ConsoleEntry &e) const;

    std::deque<ConsoleEntry> m_entries;
    QList<ConsoleEntry> m_pending; // arrived, not yet in the table
    QList<ConsoleEntry> m_held;    // arrived while paused
    QTimer m_batch;
    int m_capacity;
    bool m_paused = false;
    bool m_relative = false;
    qint64 m_originUs = -1;
    QMap<int, QString> m_families;
    QPointer<link::FrameTap> m_tap;
    QMetaObject::Connection m_connection;
    QPointer<Session> m_session;
    QList<QMetaObject::Connection> m_sessionConnections;
    ConsoleSender m_sender;
};

} // namespace tipscope::model
