#include "clisession.h"

#include <QFileInfo>

#include "clicommands.h"

#include "base/elide.h"
#include "model/device/feedermodel.h"
#include "model/device/stationmodel.h"
#include "sim/simline.h"

#include <QEventLoop>
#include <QTimer>
#include <cstdio>

namespace tipscope::cli {

using namespace tipscope::link;
using namespace tipscope::protocol;

CliSession::CliSession(const CliOptions &options, QIODevice *out, QIODevice *err)
    : m_options(options)
    , m_out(stdout)
    , m_err(stderr) {
    if (out)
        m_out.setDevice(out);
    if (err)
        m_err.setDevice(err);
    LineSettings settings = options.line;
    if (options.demo) {
        m_demo = sim::SimLine::demo();
        m_demo->setDemoActivity(options.demoActivity);
        m_demo->setClockRunning(true);
    }
    auto transport = Line::makeTransport(settings, m_demo.get());
    m_line = std::make_unique<Line>(std::move(transport), settings);
    if (options.verbose) {
        QObject::connect(&m_line->queue().tap(), &FrameTap::event, &m_owner,
                         [this](const TapEvent &e) {
                             if (e.kind == TapEvent::Kind::Tx)
                                 m_err << "TX " << e.bytes.toHex(' ') << Qt::endl;
                             else if (e.kind == TapEvent::Kind::Rx)
                                 m_err << "RX " << e.bytes.toHex(' ') << Qt::endl;
                             else if (e.kind == TapEvent::Kind::Note)
                                 m_err << "-- " << e.note << Qt::endl;
                         });
    }
}

CliSession::~CliSession() {
    m_out.flush();
}

void CliSession::waitForLine() {
    QEventLoop loop;
    QObject::connect(m_line.get(), &Line::stateChanged, &loop, [&loop](Line::State s) {
        if (s != Line::State::Opening)
            loop.quit();
    });
    m_line->open();
    if (m_line->state() == Line::State::Opening)
        loop.exec();
}

// The link layer's messages quote the port as given; a name as long as a file can hold would
// make them unreadable, so it is shown the way every other echoed input is.
QString CliSession::withPortElided(QString message) const {
    const QString &port = m_options.line.serial.portName;
    if (m_options.line.kind == LineSettings::Kind::Serial && !port.isEmpty())
        message.replace(port, base::elidedPath(port));
    return message;
}

int CliSession::open() {
    waitForLine();
    if (m_line->state() == Line::State::Open)
        return kOk;
    m_err << withPortElided(tr("tipscope-cli: cannot open %1: %2")
                                .arg(m_line->transport().description(), m_line->lastError()))
          << Qt::endl;
    return kTransport;
}

Reply *CliSession::ask(const Request &request) {
    Reply *reply = m_line->queue().enqueue(request, &m_owner);
    if (!reply->isFinished()) {
        QEventLoop loop;
        QObject::connect(reply, &Reply::finished, &loop, &QEventLoop::quit);
        loop.exec();
    }
    return reply;
}

int CliSession::exitCodeFor(const Reply &reply) {
    return exitCodeFor(reply.error());
}

int CliSession::exitCodeFor(ReplyError error) {
    switch (error) {
    case ReplyError::None:
        return kOk;
    case ReplyError::Nak:
        return kNak;
    case ReplyError::Timeout:
    case ReplyError::Corrupted:
        return kNoAnswer;
    case ReplyError::Disconnected:
    case ReplyError::NotOpen:
    case ReplyError::Cancelled:
        return kTransport;
    }
    return kTransport;
}

void CliSession::waitFor(Discovery &discovery) {
    QEventLoop loop;
    QObject::connect(&discovery, &Discovery::finished, &loop, &QEventLoop::quit);
    if (discovery.isRunning())
        loop.exec();
}

int CliSession::identify(std::optional<int> address) {
    Discovery discovery(m_line->queue());
    discovery.identify(address);
    waitFor(discovery);
    const Identification &found = *discovery.identification();
    if (found.ok()) {
        m_devices = {found.value()};
        return kOk;
    }
    const IdentifyFailure &why = found.error();
    m_err << tr("tipscope-cli: %1").arg(why.text(address)) << Qt::endl;
    if (why.kind != IdentifyFailure::Kind::Unanswered)
        return kNoAnswer;
    const int code = exitCodeFor(why.replyError);
    return code == kOk ? kNoAnswer : code;
}

int CliSession::resolveDevices() {
    if (m_options.addressing == CliOptions::Addressing::With)
        return identify(m_options.targetAddress);
    if (m_options.addressing == CliOptions::Addressing::Without)
        return identify(std::nullopt);
    Discovery discovery(m_line->queue());
    discovery.setScanAllAddresses(m_options.flags.contains(QStringLiteral("scan")));
    discovery.start();
    waitFor(discovery);
    m_devices.clear();
    for (const DeviceInfo &d : discovery.devices())
        if (!d.family.isEmpty())
            m_devices.append(d);
    if (!m_devices.isEmpty())
        return kOk;
    if (m_line->state() != Line::State::Open) {
        m_err << withPortElided(tr("tipscope-cli: the line was lost: %1").arg(m_line->lastError()))
              << Qt::endl;
        return kTransport;
    }
    // Something that came back is not the cable's silence: say what it was.
    if (const QString heard = discovery.whatCameBack(); !heard.isEmpty()) {
        m_err << withPortElided(tr("tipscope-cli: no device could be identified on %1 (checked "
                                   "addresses 01, 10, 20 and frames without addresses); what "
                                   "came back: %2. Check the baud rate, the addressing, and "
                                   "that robot mode is on.")
                                    .arg(m_line->transport().description(), heard))
              << Qt::endl;
        return kNoAnswer;
    }
    m_err << withPortElided(
                 tr("tipscope-cli: no device answered on %1 (checked addresses 01, 10, 20 and "
                    "frames without addresses). Check the cable, the baud rate, and that robot "
                    "mode is on.")
                     .arg(m_line->transport().description()))
          << Qt::endl;
    return kNoAnswer;
}

const DeviceInfo *CliSession::deviceFor(const QByteArray &code, Direction direction) const {
    for (const DeviceInfo &d : m_devices)
        if (Catalog::builtin().resolve(d.family, code, direction))
            return &d;
    return nullptr;
}

const DeviceInfo *CliSession::firstStation() const {
    for (const DeviceInfo &d : m_devices)
        if (const FamilyInfo *f = Catalog::builtin().family(d.family); f && !f->isFeeder())
            return &d;
    return nullptr;
}

std::unique_ptr<model::DeviceModel> CliSession::model(const DeviceInfo &device) {
    if (Catalog::builtin().family(device.family)->isFeeder())
        return std::make_unique<model::FeederModel>(m_line->queue(), device);
    return std::make_unique<model::StationModel>(m_line->queue(), device);
}

model::Session::Settings sessionSettingsOf(const CliOptions &o) {
    model::Session::Settings s;
    s.line = o.line;
    s.addressing = o.addressing;
    s.targetAddress = o.targetAddress;
    s.scanAllAddresses = o.flags.contains(QStringLiteral("scan"));
    s.demoActivity = o.demoActivity;
    return s;
}

model::WorkspaceLine workspaceLineOf(const CliOptions &o) {
    model::WorkspaceLine line;
    line.session = sessionSettingsOf(o);
    switch (o.line.kind) {
    case link::LineSettings::Kind::Demo:
        line.name = QStringLiteral("demo");
        break;
    case link::LineSettings::Kind::Serial:
        line.name = QFileInfo(o.line.serial.portName).fileName();
        break;
    case link::LineSettings::Kind::Tcp:
        line.name = QStringLiteral("%1-%2").arg(o.line.tcpHost).arg(o.line.tcpPort);
        break;
    }
    return line;
}

} // namespace tipscope::cli
