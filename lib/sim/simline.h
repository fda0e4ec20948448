// SimLine: a serial line with simulated devices on it, plus the faults a real line has.
//
// Bytes written by the host go to receive(); answers leave through transmit(). The line decodes
// requests, routes each to the device it addresses (silence for other addresses), answers a
// request with a bad BCC with NAK 00001 and a malformed one with NAK 00002, and applies the
// configured faults to answers. With a baud rate set, the line paces both directions like a real
// wire (10 bits per byte): an answer starts no earlier than the request's last byte would have
// arrived, and leaves byte by byte at the line rate (or, with setChunkMs(), in the chunks a
// USB-serial adapter hands over once per latency period). Simulated time for the devices advances
// from a timer while the clock runs, or explicitly through advance(). A paced receiver holds at
// most a buffer's worth of bytes that came faster than the wire carries them; the rest is lost
// (an overrun, counted), so a flood of junk costs at most that buffer's wire time.
#pragma once

#include "demoactivity.h"
#include "randomjoints.h"
#include "simfeeder.h"
#include "simstation.h"

#include "protocol/framedecoder.h"

#include <QElapsedTimer>
#include <QObject>
#include <QRandomGenerator>
#include <QTimer>
#include <memory>
#include <vector>

namespace tipscope::sim {

enum class NakScope { All, Writes, Command };

struct SimFaults {
    int latencyMs = 0;              // device turnaround added to every answer
    double dropShare = 0;           // requests the device carries out but whose answer is lost
    double requestDropShare = 0;    // requests lost on their way: the device never sees them
    double requestCorruptShare = 0; // requests with a bit flipped on their way
    double corruptShare = 0;        // answers with a flipped bit, cut short, or a wrong BCC
    double garbageShare = 0;        // answers preceded by noise bytes
    double badDataShare = 0; // answers to reads whose data field no client can read ("?BAD?")
    double delayShare = 0;   // answers held back by delayMs (past a client's timeout)
    int delayMs = 0;
    int nakCode = 0; // when set, the requests nakFor names are answered with this NAK code
    NakScope nakFor = NakScope::All;
    QByteArray nakCommand; // with NakScope::Command: the command ("ST1"), reads and writes
    quint32 seed = 1;

    [[nodiscard]] bool naks(const protocol::Frame &request) const;
};

struct SimLineStats {
    qint64 bytesReceived = 0;
    qint64 bytesSent = 0;
    qint64 requests = 0;
    qint64 writeRequests = 0;
    qint64 answers = 0;
    qint64 dropped = 0;
    qint64 corrupted = 0;
    qint64 garbled = 0;
    qint64 delayed = 0;
    qint64 badData = 0;
    qint64 badRequests = 0;
    qint64 requestsLost = 0;    // requestDropShare
    qint64 requestsGarbled = 0; // requestCorruptShare
    qint64 overrunBytes = 0;    // came faster than the paced wire carries them, beyond the buffer
    qint64 unsentBytes = 0;     // answers a client did not take (not reading), dropped
};

class SimLine : public QObject {
    Q_OBJECT
public:
    explicit SimLine(QObject *parent = nullptr);
    ~SimLine() override;

    // The demo line: a DME station at 01 and an SFR feeder at 10, both addressed.
    static std::unique_ptr<SimLine> demo(QObject *parent = nullptr);

    SimDevice *addDevice(std::unique_ptr<SimDevice> device);
    [[nodiscard]] QList<SimDevice *> devices() const;
    [[nodiscard]] SimStation *station() const;
    [[nodiscard]] SimFeeder *feeder() const;

    void setFaults(const SimFaults &faults);
    [[nodiscard]] const SimFaults &faults() const { return m_faults; }
    void setBaud(int baud) { m_baud = baud; }
    [[nodiscard]] int baud() const { return m_baud; }
    // What has arrived of an answer is delivered every `ms` after its first byte, or when its
    // last byte is in, whichever is first (0, the default: as each byte arrives). A USB-serial
    // adapter works this way (its latency timer), and it spares the receiver a wake-up a byte.
    void setChunkMs(int ms) { m_chunkNs = qMax(0, ms) * 1'000'000LL; }
    // What the paced demo is: a real station on a 19200-baud wire, reached through a USB adapter
    // with a short latency timer (8 ms).
    void paceLikeARealWire() {
        setBaud(19200);
        setChunkMs(8);
    }
    void setClockRunning(bool running);
    // How often the running clock moves the devices' simulated time (default 20 ms). The
    // physics steps by the time elapsed, so a coarser tick only makes changes show in steps
    // between requests: a request catches the devices up to the instant it arrives.
    void setTickMs(int ms) { m_tickTimer.setInterval(qMax(1, ms)); }
    void advance(int ms);
    // The demo's station and feeder at work (DemoActivity); off by default, so tests see
    // devices that change only when told to.
    void setDemoActivity(bool on);
    [[nodiscard]] bool hasDemoActivity() const { return m_activity != nullptr; }
    // Joints drawn from `shapes` on every port of the station, about `perMinute` a minute on
    // each (RandomJoints), seeded; 0 stops them.
    void
    setRandomJoints(double perMinute, quint32 seed,
                    const JointShapeSet &shapes = *JointShapeSet::named(QStringLiteral("demo")));
    // A joint on the station's port now (the clock caught up first): nullopt when there is no
    // such port or it cannot make one (SimStation::canMakeJoint()).
    std::optional<SimJoint> startJoint(int port, int depthK, qint64 recoveryMs);
    [[nodiscard]] const SimLineStats &stats() const { return m_stats; }
    // A new client on the line: what the old one left half sent, the answers not yet on the
    // wire and the wire's backlog are forgotten.
    void clearWire();
    // An endpoint dropped `bytes` of answers its client did not take.
    void countUnsent(qint64 bytes) { m_stats.unsentBytes += bytes; }

public Q_SLOTS:
    void receive(const QByteArray &bytes);

Q_SIGNALS:
    void transmit(const QByteArray &bytes);
    void requestReceived(const tipscope::protocol::Frame &request);
    // Every joint the station made (a command, the demo, the random joints), with its true
    // values; startMs is in milliseconds since the epoch: the wall clock while the line's clock
    // runs, and the time the line was made plus the simulated time when advance() drives it.
    void jointMade(const tipscope::sim::SimJoint &joint);
    // The same joint once it is over, with how its tip was read (SimJoint::reads).
    void jointEnded(const tipscope::sim::SimJoint &joint);

private:
    struct Outgoing {
        qint64 startNs = 0;
        QByteArray bytes;
        qsizetype sent = 0;
    };

    void handleEvent(const protocol::DecodeEvent &event, qint64 arrivedNs);
    // A request frame that a fault on the way spoiled or lost; true when it did.
    bool spoilRequest(const protocol::DecodeEvent &event, qint64 arrivedNs);
    void deliver(const protocol::DecodeEvent &event, qint64 arrivedNs);
    [[nodiscard]] bool spoilData(const SimDevice &device, const protocol::Frame &request,
                                 const protocol::Frame &answer);
    void answerMalformed(const protocol::DecodeEvent &event, qint64 arrivedNs);
    SimDevice *route(std::optional<int> target) const;
    void sendAnswer(SimDevice *device, int deviceAddress, const protocol::Frame &request,
                    protocol::Frame answer, qint64 arrivedNs);
    QByteArray applyCorruption(QByteArray bytes);
    void schedule(const QByteArray &bytes, qint64 earliestNs);
    void pump();
    [[nodiscard]] qint64 byteNs() const { return m_baud > 0 ? 10'000'000'000LL / m_baud : 0; }
    [[nodiscard]] bool chance(double share);
    void tick();
    void catchUpTo(qint64 ns);
    void reportJoints();

    std::vector<std::unique_ptr<SimDevice>> m_devices;
    protocol::FrameDecoder m_decoder;
    SimFaults m_faults;
    QRandomGenerator m_rng;
    int m_baud = 0;
    qint64 m_chunkNs = 0;
    QElapsedTimer m_clock;
    qint64 m_rxFreeNs = 0;
    qint64 m_txFreeNs = 0;
    std::vector<Outgoing> m_out;
    QTimer m_pumpTimer;
    QTimer m_tickTimer;
    qint64 m_lastTickNs = 0;
    SimLineStats m_stats;
    std::unique_ptr<DemoActivity> m_activity;
    std::unique_ptr<RandomJoints> m_randomJoints;
    qint64 m_epochAtZeroMs = 0; // the epoch time of the station's simulated time 0
};

} // namespace tipscope::sim
