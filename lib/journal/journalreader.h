// JournalReader: queries over a journal file, through a connection of its own. Synchronous: for
// the CLI, reports and pages that query off the poll path. A reader may run beside a Journal
// writing the same file (WAL lets readers see every committed transaction without blocking
// the writer). Use one reader on one thread: Qt SQL connections belong to their thread.
//
// open() refuses a missing file (it never creates one), a damaged or foreign file and a newer
// schema; an older schema is migrated as the writer would. Every query returns nullopt on
// failure and says why in `error`, in the user's language.
#pragma once

#include "journaltypes.h"

#include <QMap>
#include <QString>
#include <optional>

namespace tipscope::journal {

class JournalReader {
public:
    JournalReader();
    ~JournalReader();
    JournalReader(const JournalReader &) = delete;
    JournalReader &operator=(const JournalReader &) = delete;

    [[nodiscard]] bool open(const QString &path, QString *error);
    [[nodiscard]] bool isOpen() const { return m_open; }
    [[nodiscard]] QString path() const { return m_path; }

    [[nodiscard]] std::optional<QList<StoredJoint>> joints(const JointFilter &filter,
                                                           QString *error) const;
    [[nodiscard]] std::optional<QList<StoredEvent>> events(const EventFilter &filter,
                                                           QString *error) const;
    // Ignores the filter's limit and order.
    [[nodiscard]] std::optional<qint64> countJoints(const JointFilter &filter,
                                                    QString *error) const;
    [[nodiscard]] std::optional<QMap<model::JointVerdict, qint64>>
    verdictCounts(const JointFilter &filter, QString *error) const;
    // Per device and port, in key and port order.
    [[nodiscard]] std::optional<QList<PortRecovery>> recoveryByPort(const JointFilter &filter,
                                                                    QString *error) const;

    // Store-and-forward: the oldest unsent records with a row id above `afterId`, in order.
    [[nodiscard]] std::optional<QList<StoredJoint>> unsentJoints(qint64 afterId, int limit,
                                                                 QString *error) const;
    [[nodiscard]] std::optional<QList<StoredEvent>> unsentEvents(qint64 afterId, int limit,
                                                                 QString *error) const;
    // Every device the journal has a record of, in key order.
    [[nodiscard]] std::optional<QList<model::DeviceIdentity>> devices(QString *error) const;

private:
    void close();

    QString m_connection;
    QString m_path;
    bool m_open = false;
};

} // namespace tipscope::journal
