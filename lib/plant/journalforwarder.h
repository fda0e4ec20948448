// JournalForwarder: store and forward. Publishes the journal's joints and events that are not yet
// sent, oldest first, with QoS 1, and marks each sent only when the broker acknowledged it
// (PUBACK). A broker outage, a network cut or an agent restart loses none: what was not
// acknowledged is still unsent in the journal and goes out, in order, once the client is
// connected again. Duplicates are possible (QoS 1 is at least once) and carry the record's id.
// Each payload names the workspace line as `line` and how the device is reached as `connection`,
// as `info` does (the journal's own export calls the connection `line`).
//
// Only records the journal has made durable are read, so nothing is published that a crash could
// take back. At most kWindow messages wait for their acknowledgement at a time; the rest wait in
// the journal. A message handed over when the connection drops stays with the client, which sends
// it again after reconnecting; one not acknowledged for a minute while connected is given up and
// everything after the last acknowledged record is read again.
//
// Both the journal and the client must outlive the forwarder, and live on its thread.
#pragma once

#include "planttopics.h"

#include "journal/journalreader.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QTimer>
#include <functional>

namespace tipscope::journal {
class Journal;
}
namespace tipscope::mqtt {
class MqttClient;
}

namespace tipscope::plant {

class JournalForwarder : public QObject {
    Q_OBJECT
public:
    // Where a record of `device` goes: its root topic (an agent's root for an empty identity)
    // and the name of the workspace line it is on (empty when none).
    using PlaceOf = std::function<DevicePlace(const model::DeviceIdentity &device)>;
    static constexpr int kWindow = 200;

    JournalForwarder(journal::Journal &journal, mqtt::MqttClient &client, PlaceOf placeOf,
                     QObject *parent = nullptr);

    // Forgets what is waiting for an acknowledgement and reads again from the oldest unsent
    // record: after the client was stopped (its messages forgotten) and started again.
    void restart();

    [[nodiscard]] qint64 acknowledgedCount() const { return m_acknowledged; }
    [[nodiscard]] int waitingCount() const { return int(m_inFlight.size()); }
    // Why the journal could not be read, empty when it could.
    [[nodiscard]] QString problem() const { return m_problem; }

Q_SIGNALS:
    // After records were acknowledged and marked sent.
    void forwarded(int joints, int events);
    void problemChanged(const QString &problem);

private:
    struct InFlight {
        bool joint = false;
        qint64 row = 0;
    };

    void pumpSoon();
    void pump();
    bool publish(const QString &topic, const QJsonObject &payload, InFlight item);
    void onPublished(int messageId);
    void flushMarks();
    void checkStalled();
    void setProblem(const QString &problem);

    journal::Journal &m_journal;
    mqtt::MqttClient &m_client;
    PlaceOf m_placeOf;
    journal::JournalReader m_reader;
    qint64 m_jointCursor = 0;
    qint64 m_eventCursor = 0;
    QHash<int, InFlight> m_inFlight;
    QList<qint64> m_sentJoints;
    QList<qint64> m_sentEvents;
    QTimer m_pumpTimer;
    QTimer m_markTimer;
    QTimer m_stallTimer;
    QElapsedTimer m_sinceAck;
    qint64 m_acknowledged = 0;
    QString m_problem;
};

} // namespace tipscope::plant
