// The independent CFX consumer (support/cfxconsumerprocess.h) run by `tipscope-bench cfx` on one
// source for as long as the bench lasts: each message it prints is
// kept as what the bench counts (name, endpoint, UniqueID, time stamp, arrival, transaction,
// board, and the joints a UnitsProcessed carries). The consumer checks every message against
// the CFX SDK's names as it does for the tests; its complaints are kept apart from the broker
// outages it rides out (it connects again at most --retry-max-s apart).
#pragma once

#include "cfxconsumerprocess.h"

#include <QHash>
#include <QList>
#include <QString>
#include <QStringList>

namespace tipscope::bench {

struct TappedMessage {
    QString name;   // "CFX.Production.WorkStarted"
    QString source; // the endpoint's handle
    QString uniqueId;
    qint64 stampMs = 0;   // the envelope's TimeStamp
    qint64 arrivedMs = 0; // when the consumer received it (the same machine's clock)
    QString transaction;  // TransactionID / TransactionId; empty for other messages
    QString board;        // WorkStarted's PrimaryIdentifier; empty for other messages
    QStringList jointIds; // the JointId of each stage of a UnitsProcessed
};

class CfxTap {
public:
    CfxTap();
    CfxTap(const CfxTap &) = delete;
    CfxTap &operator=(const CfxTap &) = delete;

    [[nodiscard]] static QString skipReason();
    // Starts the consumer on `source` and returns once its link is attached.
    [[nodiscard]] bool start(const QString &url, const QString &source, QString *error);
    // Reads what the consumer printed so far (the bench's event loop also does, as it arrives).
    void read() { m_consumer.read(); }

    [[nodiscard]] const QList<TappedMessage> &messages() const { return m_messages; }
    [[nodiscard]] const QStringList &complaints() const { return m_complaints; }
    [[nodiscard]] int transportErrors() const { return m_transportErrors; }
    [[nodiscard]] qint64 pid() { return m_consumer.process().processId(); }
    // The endpoints that said WorkStarted for `board`.
    [[nodiscard]] QStringList startedAt(const QString &board) const {
        return m_startedAt.value(board);
    }
    // The endpoints that said EndpointConnected at or after `sinceMs` (arrival).
    [[nodiscard]] int connectedSince(qint64 sinceMs) const;

private:
    void take(const QByteArray &line);

    QList<TappedMessage> m_messages;
    QHash<QString, QStringList> m_startedAt;
    QStringList m_complaints;
    int m_transportErrors = 0;
    testing::CfxConsumerProcess m_consumer;
};

} // namespace tipscope::bench
