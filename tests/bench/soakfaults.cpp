#include "soakfaults.h"

namespace tipscope::bench {

namespace {
constexpr int kTickMs = 1000;
// A NAK window is long enough to catch a request or two at 19200 baud (a request and its answer
// take about 15 ms); a delay window stalls the wire past the answer budget of about 125 ms.
constexpr int kWindowMs[2] = {20, 200};
constexpr int kStallBaud = 300;
} // namespace

std::optional<SimStats> SimStats::parse(const QString &line) {
    // "requests 12 writes 3 answers 11 ...": names and counts in turn.
    const QStringList words = line.split(QLatin1Char(' '), Qt::SkipEmptyParts);
    QMap<QString, qint64> counts;
    for (qsizetype i = 0; i + 1 < words.size(); i += 2) {
        bool ok = false;
        counts.insert(words.at(i), words.at(i + 1).toLongLong(&ok));
        if (!ok)
            return std::nullopt;
    }
    if (!counts.contains(QStringLiteral("requests")))
        return std::nullopt;
    const auto n = [&counts](const char *name) { return counts.value(QLatin1String(name)); };
    SimStats s;
    s.requests = n("requests");
    s.writes = n("writes");
    s.answers = n("answers");
    s.dropped = n("dropped");
    s.corrupted = n("corrupted");
    s.garbled = n("garbled");
    s.badRequests = n("bad-requests");
    s.lostRequests = n("lost-requests");
    s.garbledRequests = n("garbled-requests");
    return s;
}

std::optional<QMap<QByteArray, qint64>> parseSettings(const QString &reply) {
    if (reply.isEmpty() || reply.startsWith(QLatin1String("error:")))
        return std::nullopt;
    QMap<QByteArray, qint64> settings;
    for (const QString &pair : reply.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        bool ok = false;
        const qint64 value = pair.section(QLatin1Char('='), 1).toLongLong(&ok);
        if (!ok || !pair.contains(QLatin1Char('=')))
            return std::nullopt;
        settings.insert(pair.section(QLatin1Char('='), 0, 0).toLatin1(), value);
    }
    return settings;
}

SimConsole::SimConsole(QProcess &process, QObject *parent)
    : QObject(parent)
    , m_process(process) {
    connect(&m_process, &QProcess::readyReadStandardOutput, this, &SimConsole::onReadyRead);
}

void SimConsole::send(const QStringList &commands, const QList<Handler> &handlers) {
    QByteArray batch;
    for (qsizetype i = 0; i < commands.size(); ++i) {
        batch += commands.at(i).toLocal8Bit() + '\n';
        m_waiting.push_back(handlers.value(i));
    }
    m_process.write(batch);
}

void SimConsole::onReadyRead() {
    while (m_process.canReadLine()) {
        const QString line = QString::fromLocal8Bit(m_process.readLine()).trimmed();
        if (m_waiting.empty())
            continue; // not an answer to us (the simulator prints nothing else, but be safe)
        Handler h = std::move(m_waiting.front());
        m_waiting.pop_front();
        if (h)
            h(line);
    }
}

FaultWindows::FaultWindows(SimConsole &console, double nakShare, double delayShare, int normalBaud,
                           QObject *parent)
    : QObject(parent)
    , m_console(console)
    , m_share{nakShare, delayShare}
    , m_normalBaud(normalBaud) {
    m_tick.setInterval(kTickMs);
    connect(&m_tick, &QTimer::timeout, this, &FaultWindows::tick);
}

void FaultWindows::tick() {
    if (m_windowOpen || m_paused)
        return;
    m_console.send(QStringLiteral("stats"), [this](const QString &reply) {
        if (const auto s = SimStats::parse(reply))
            m_requests = s->requests;
        // Alternate the kinds, and open a window only for a kind behind its share.
        for (int i = 0; i < 2; ++i) {
            const Kind k = Kind((m_next + i) % 2);
            if (m_share[k] > 0 && m_injected[k] < m_share[k] * double(m_requests)) {
                m_next = (k + 1) % 2;
                open(k);
                return;
            }
        }
    });
}

void FaultWindows::open(Kind kind) {
    if (m_windowOpen || m_paused)
        return;
    m_windowOpen = true;
    ++m_windows[kind];
    const QString on =
        kind == Nak ? QStringLiteral("robot-mode off") : QStringLiteral("pace %1").arg(kStallBaud);
    const QString off =
        kind == Nak ? QStringLiteral("robot-mode on") : QStringLiteral("pace %1").arg(m_normalBaud);
    auto before = std::make_shared<qint64>(-1);
    m_console.send({QStringLiteral("stats"), on}, {[before](const QString &reply) {
                       if (const auto s = SimStats::parse(reply))
                           *before = s->requests;
                   }});
    QTimer::singleShot(kWindowMs[kind], this, [this, kind, off, before] {
        m_console.send({off, QStringLiteral("stats")},
                       {{}, [this, kind, before](const QString &reply) {
                            const auto s = SimStats::parse(reply);
                            if (s && *before >= 0)
                                m_injected[kind] += s->requests - *before;
                            if (kind == Delay) // the answer that was on the wire
                                ++m_injected[kind];
                            m_windowOpen = false;
                        }});
    });
}

} // namespace tipscope::bench
