#include "simline.h"

#include <QDateTime>

namespace tipscope::sim {

using namespace tipscope::protocol;

namespace {
constexpr int kTickMs = 20;
constexpr qint64 kNsPerMs = 1'000'000;
// What a paced receiver holds of bytes that came faster than the wire (a tty's buffer).
constexpr qint64 kRxBufferBytes = 4096;
// Framed like any data field, but neither a number, a delay nor a hex counter.
constexpr char kUnreadableData[] = "?BAD?";

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}
} // namespace

SimLine::SimLine(QObject *parent)
    : QObject(parent)
    , m_rng(1) {
    m_clock.start();
    m_epochAtZeroMs = QDateTime::currentMSecsSinceEpoch();
    m_pumpTimer.setSingleShot(true);
    m_pumpTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_pumpTimer, &QTimer::timeout, this, &SimLine::pump);
    m_tickTimer.setInterval(kTickMs);
    connect(&m_tickTimer, &QTimer::timeout, this, &SimLine::tick);
}

SimLine::~SimLine() = default;

std::unique_ptr<SimLine> SimLine::demo(QObject *parent) {
    auto line = std::make_unique<SimLine>(parent);
    line->addDevice(std::make_unique<SimStation>(QStringLiteral("DME"), 1));
    line->addDevice(std::make_unique<SimFeeder>(10));
    return line;
}

SimDevice *SimLine::addDevice(std::unique_ptr<SimDevice> device) {
    m_devices.push_back(std::move(device));
    return m_devices.back().get();
}

QList<SimDevice *> SimLine::devices() const {
    QList<SimDevice *> out;
    for (const auto &d : m_devices)
        out.append(d.get());
    return out;
}

SimStation *SimLine::station() const {
    for (const auto &d : m_devices)
        if (auto *s = dynamic_cast<SimStation *>(d.get()))
            return s;
    return nullptr;
}

SimFeeder *SimLine::feeder() const {
    for (const auto &d : m_devices)
        if (auto *f = dynamic_cast<SimFeeder *>(d.get()))
            return f;
    return nullptr;
}

bool SimFaults::naks(const Frame &request) const {
    switch (nakFor) {
    case NakScope::All:
        return nakCode != 0;
    case NakScope::Writes:
        return nakCode != 0 && request.header == Header::Write;
    case NakScope::Command:
        return nakCode != 0 && request.command == nakCommand;
    }
    return false;
}

void SimLine::setFaults(const SimFaults &faults) {
    // Reseeding on every change would restart the fault sequence each time a knob is turned.
    if (faults.seed != m_faults.seed)
        m_rng.seed(faults.seed);
    m_faults = faults;
}

void SimLine::setClockRunning(bool running) {
    m_lastTickNs = m_clock.nsecsElapsed();
    // From here the simulated time keeps pace with the wall clock.
    if (running && station())
        m_epochAtZeroMs = QDateTime::currentMSecsSinceEpoch() - station()->nowMs();
    if (running)
        m_tickTimer.start();
    else
        m_tickTimer.stop();
}

void SimLine::tick() {
    catchUpTo(m_clock.nsecsElapsed());
}

// A device answers with what it is at the instant the request reached it: the joints' truth is
// logged on this clock, and a tip read as it stood at the last tick (up to a tick earlier) made
// every reading older than the instant it was answered at, which the benchmark then counted as
// the detector's error (every start about 20 ms late).
void SimLine::catchUpTo(qint64 ns) {
    if (!m_tickTimer.isActive())
        return;
    const int ms = int((ns - m_lastTickNs) / kNsPerMs);
    if (ms <= 0)
        return;
    m_lastTickNs += ms * kNsPerMs;
    advance(ms);
}

void SimLine::advance(int ms) {
    for (const auto &d : m_devices)
        d->advance(ms);
    if (m_activity)
        m_activity->advance(ms);
    if (m_randomJoints)
        m_randomJoints->advance(ms);
    reportJoints();
}

void SimLine::setRandomJoints(double perMinute, quint32 seed, const JointShapeSet &shapes) {
    SimStation *st = station();
    m_randomJoints =
        st && perMinute > 0 ? std::make_unique<RandomJoints>(st, perMinute, seed, shapes) : nullptr;
}

std::optional<SimJoint> SimLine::startJoint(int port, int depthK, qint64 recoveryMs) {
    SimStation *st = station();
    if (!st || port < 1 || port > st->portCount())
        return std::nullopt;
    catchUpTo(m_clock.nsecsElapsed()); // the joint starts now, not at the last tick
    const auto made = st->startJoint(port, depthK, recoveryMs);
    reportJoints();
    if (!made)
        return std::nullopt;
    SimJoint j = *made;
    j.startMs += m_epochAtZeroMs;
    return j;
}

void SimLine::reportJoints() {
    SimStation *st = station();
    if (!st)
        return;
    for (SimJoint j : st->takeMadeJoints()) {
        j.startMs += m_epochAtZeroMs;
        Q_EMIT jointMade(j);
    }
    for (SimJoint j : st->takeEndedJoints()) {
        j.startMs += m_epochAtZeroMs;
        Q_EMIT jointEnded(j);
    }
}

void SimLine::setDemoActivity(bool on) {
    if (on == hasDemoActivity())
        return;
    m_activity = on ? std::make_unique<DemoActivity>(station(), feeder()) : nullptr;
}

bool SimLine::chance(double share) {
    return share > 0 && m_rng.generateDouble() < share;
}

void SimLine::receive(const QByteArray &bytes) {
    // A request catches the devices up when a tick is due and restarts the timer, so a line
    // that is polled steadily never wakes the process for the clock.
    if (m_tickTimer.isActive() &&
        m_clock.nsecsElapsed() - m_lastTickNs >= m_tickTimer.interval() * kNsPerMs) {
        tick();
        m_tickTimer.start();
    }
    m_stats.bytesReceived += bytes.size();
    const qint64 now = m_clock.nsecsElapsed();
    // On a real wire the chunk starts arriving when it was written (about now) and takes its
    // bytes' time; a chunk cannot start before the previous one has finished.
    const qint64 chunkStart = qMax(now, m_rxFreeNs);
    qsizetype kept = bytes.size();
    if (byteNs() > 0) {
        const qint64 room = (now + kRxBufferBytes * byteNs() - chunkStart) / byteNs();
        kept = qsizetype(qBound<qint64>(0, room, bytes.size()));
        m_stats.overrunBytes += bytes.size() - kept;
    }
    m_rxFreeNs = chunkStart + kept * byteNs();
    qint64 offset = 0;
    for (const DecodeEvent &e : m_decoder.feed(QByteArrayView(bytes).first(kept))) {
        offset += e.raw.size();
        handleEvent(e, chunkStart + qMin<qint64>(offset, kept) * byteNs());
    }
}

void SimLine::clearWire() {
    m_decoder.reset();
    m_out.clear();
    m_pumpTimer.stop();
    m_rxFreeNs = m_txFreeNs = m_clock.nsecsElapsed();
}

void SimLine::handleEvent(const DecodeEvent &e, qint64 arrivedNs) {
    if (e.kind == DecodeEvent::Kind::Frame && spoilRequest(e, arrivedNs))
        return;
    deliver(e, arrivedNs);
}

bool SimLine::spoilRequest(const DecodeEvent &e, qint64 arrivedNs) {
    if (chance(m_faults.requestDropShare)) {
        ++m_stats.requestsLost;
        return true;
    }
    if (!chance(m_faults.requestCorruptShare))
        return false;
    ++m_stats.requestsGarbled;
    // One bit flipped anywhere: the device's own decoder makes of it what it can (mostly a BCC
    // error, answered NAK 00001; a flipped STX or ETX leaves it nothing to answer).
    QByteArray raw = e.raw;
    raw[m_rng.bounded(int(raw.size()))] ^= char(1 << m_rng.bounded(8));
    FrameDecoder decoder;
    for (const DecodeEvent &spoiled : decoder.feed(raw))
        deliver(spoiled, arrivedNs);
    return true;
}

void SimLine::deliver(const DecodeEvent &e, qint64 arrivedNs) {
    if (e.kind == DecodeEvent::Kind::Garbage || e.kind == DecodeEvent::Kind::Overflow)
        return;
    if (e.kind != DecodeEvent::Kind::Frame) {
        ++m_stats.badRequests;
        answerMalformed(e, arrivedNs);
        return;
    }
    ++m_stats.requests;
    if (e.frame.header == Header::Write)
        ++m_stats.writeRequests;
    catchUpTo(arrivedNs);
    Q_EMIT requestReceived(e.frame);
    SimDevice *device = route(e.frame.target);
    if (!device || e.frame.source.has_value() != device->isAddressed())
        return;
    const int address = device->address(); // a W-SAD answers from the old address
    Frame answer = m_faults.naks(e.frame) ? device->nak(e.frame.command, m_faults.nakCode)
                                          : device->handle(e.frame);
    if (spoilData(*device, e.frame, answer)) {
        ++m_stats.badData;
        answer.data = kUnreadableData;
    }
    sendAnswer(device, address, e.frame, std::move(answer), arrivedNs);
}

bool SimLine::spoilData(const SimDevice &device, const Frame &request, const Frame &answer) {
    if (request.header != Header::Read || answer.header != Header::Answer)
        return false;
    // Any printable text is a valid model name, so only values can be spoiled.
    const auto cmd =
        Catalog::builtin().resolve(device.family().name, request.command, Direction::Read);
    return cmd && cmd->spec->kind != ValueKind::Text && chance(m_faults.badDataShare);
}

void SimLine::answerMalformed(const DecodeEvent &e, qint64 arrivedNs) {
    const QByteArray &raw = e.raw;
    if (raw.size() < 7 || raw.at(raw.size() - 2) != kEtx)
        return; // cut short: a device would not know it was meant for it
    std::optional<int> target, source;
    qsizetype pos = 1;
    if (isDigit(raw.at(1))) {
        if (raw.size() < 11 || !isDigit(raw.at(2)) || !isDigit(raw.at(3)) || !isDigit(raw.at(4)))
            return;
        source = raw.mid(1, 2).toInt();
        target = raw.mid(3, 2).toInt();
        pos = 5;
    }
    SimDevice *device = route(target);
    if (!device || device->isAddressed() != target.has_value())
        return;
    QByteArray command = raw.mid(pos + 1, 3);
    for (char c : command)
        if (!isDigit(c) && (c < 'A' || c > 'Z'))
            return;
    const int code = e.kind == DecodeEvent::Kind::BccError ? 1 : 2;
    Frame request;
    request.source = source;
    request.target = target;
    request.command = command;
    sendAnswer(device, device->address(), request, device->nak(command, code), arrivedNs);
}

SimDevice *SimLine::route(std::optional<int> target) const {
    for (const auto &d : m_devices) {
        if (target && d->isAddressed() && d->address() == *target)
            return d.get();
        if (!target && !d->isAddressed())
            return d.get();
    }
    return nullptr;
}

void SimLine::sendAnswer(SimDevice *, int deviceAddress, const Frame &request, Frame answer,
                         qint64 arrivedNs) {
    if (chance(m_faults.dropShare)) {
        ++m_stats.dropped;
        return;
    }
    if (request.source) {
        answer.source = deviceAddress;
        answer.target = *request.source;
    }
    QByteArray bytes = answer.encode();
    if (chance(m_faults.corruptShare)) {
        ++m_stats.corrupted;
        bytes = applyCorruption(bytes);
    }
    if (chance(m_faults.garbageShare)) {
        ++m_stats.garbled;
        QByteArray noise;
        for (int i = 0, n = 1 + int(m_rng.bounded(6)); i < n; ++i)
            noise.append(char(0x20 + m_rng.bounded(0x60)));
        bytes.prepend(noise);
    }
    qint64 delayNs = m_faults.latencyMs * kNsPerMs;
    if (chance(m_faults.delayShare)) {
        ++m_stats.delayed;
        delayNs += m_faults.delayMs * kNsPerMs;
    }
    ++m_stats.answers;
    schedule(bytes, arrivedNs + delayNs);
}

QByteArray SimLine::applyCorruption(QByteArray bytes) {
    switch (m_rng.bounded(3)) {
    case 0: // a bit flipped inside the frame: the BCC no longer matches
        bytes[1 + m_rng.bounded(int(bytes.size()) - 3)] ^= char(1 << m_rng.bounded(7));
        break;
    case 1: // the wrong BCC
        bytes.back() = char(bytes.back() ^ 0x5A);
        break;
    default: // cut short
        bytes.chop(1 + m_rng.bounded(int(bytes.size()) - 1));
        break;
    }
    return bytes;
}

void SimLine::schedule(const QByteArray &bytes, qint64 earliestNs) {
    const qint64 start = qMax(earliestNs, m_txFreeNs);
    m_txFreeNs = start + bytes.size() * byteNs();
    m_out.push_back({start, bytes, 0});
    pump();
}

void SimLine::pump() {
    const qint64 now = m_clock.nsecsElapsed();
    while (!m_out.empty()) {
        Outgoing &o = m_out.front();
        if (now < o.startNs)
            break;
        qsizetype due = o.bytes.size();
        if (byteNs() > 0)
            due = qMin<qsizetype>(o.bytes.size(), (now - o.startNs) / byteNs() + 1);
        if (m_chunkNs > 0 && due < o.bytes.size() && now < o.startNs + m_chunkNs)
            due = o.sent; // the adapter has not handed anything over yet
        const QByteArray part = due > o.sent ? o.bytes.mid(o.sent, due - o.sent) : QByteArray();
        o.sent = qMax(o.sent, due);
        const bool whole = o.sent == o.bytes.size();
        // Done with the answer before it is handed on: a receiver may clear the wire from there.
        if (whole)
            m_out.erase(m_out.begin());
        if (!part.isEmpty()) {
            m_stats.bytesSent += part.size();
            Q_EMIT transmit(part);
        }
        if (!whole)
            break;
    }
    if (m_out.empty())
        return;
    const Outgoing &next = m_out.front();
    qint64 waitNs = next.sent > 0 ? qMax(byteNs(), m_chunkNs) : next.startNs - now;
    if (m_chunkNs > 0 && next.sent == 0) // the first hand-over, or the whole answer if shorter
        waitNs = qMax<qint64>(0, next.startNs - now) +
                 qMin(m_chunkNs, (next.bytes.size() - 1) * byteNs());
    m_pumpTimer.start(int(qMax<qint64>(0, (waitNs + kNsPerMs - 1) / kNsPerMs)));
}

} // namespace tipscope::sim
