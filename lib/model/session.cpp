#include "session.h"

#include "sim/simline.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QFileInfo>

namespace tipscope::model {

using namespace tipscope::link;

namespace {
struct SessionTr {
    Q_DECLARE_TR_FUNCTIONS(Session)
};
} // namespace

Session::Session(QObject *parent)
    : Session(protocol::Catalog::builtin(), parent) {}

Session::Session(const protocol::Catalog &catalog, QObject *parent)
    : QObject(parent)
    , m_catalog(catalog)
    , m_recorder(m_telemetry, [this] { return sampleTimeMs(); })
    , m_joints(m_telemetry) {
    m_log.setClock([this] { return sampleTimeMs(); });
    connect(&m_joints, &JointWatcher::jointEnded, this, &Session::warnOfJoint);
    connect(&m_joints, &JointWatcher::tipWearing, this, &Session::noticeWear);
    m_stateText = SessionTr::tr("disconnected");
}

Session::~Session() {
    m_scheduler.stop();
    clearDevices();
}

StationModel *Session::station() const {
    for (DeviceModel *d : m_devices)
        if (auto *s = qobject_cast<StationModel *>(d))
            return s;
    return nullptr;
}

FeederModel *Session::feeder() const {
    for (DeviceModel *d : m_devices)
        if (auto *f = qobject_cast<FeederModel *>(d))
            return f;
    return nullptr;
}

void Session::setState(State s, const QString &text) {
    m_state = s;
    m_stateText = text;
    Q_EMIT stateChanged(s, text);
}

void Session::warnOfJoint(const JointRecord &joint) {
    logJointWarning(
        joint.device, joint.port,
        JointWatcher::warningText(joint, m_joints.rules().limitsFor(joint.port, joint.tool)));
}

void Session::noticeWear(const TipWear::Notice &notice) {
    logJointWarning(notice.device, notice.port, TipWear::noticeText(notice));
}

void Session::logJointWarning(const DeviceIdentity &device, int port, const QString &text) {
    if (text.isEmpty())
        return;
    for (DeviceModel *d : std::as_const(m_devices))
        if (d->identity() == device)
            d->logEvent(Event::Kind::JointWarning, Event::Severity::Warning, port, text);
}

void Session::clearDevices() {
    for (DeviceModel *d : std::as_const(m_devices)) {
        m_recorder.unwatch(d, TelemetryGap::Cause::Disconnected);
        m_joints.unwatch(d);
        m_scheduler.removeDevice(d);
        delete d;
    }
    m_devices.clear();
}

void Session::connectTo(const Settings &settings) {
    disconnectFromLine();
    m_settings = settings;
    if (isPlayback()) {
        setState(State::Connecting, SessionTr::tr("reading the recording %1")
                                        .arg(QFileInfo(settings.recordingPath).fileName()));
        return;
    }
    if (settings.line.kind == LineSettings::Kind::Demo) {
        m_demo = sim::SimLine::demo();
        if (settings.demoPaced)
            m_demo->paceLikeARealWire();
        m_demo->setTickMs(100); // the tip's physics, as often as the chart's fastest poll
        m_demo->setDemoActivity(settings.demoActivity);
        m_demo->setClockRunning(true);
    }
    LineSettings ls = settings.line;
    ls.retryInitialOpen = true; // the application keeps trying; the state says why it cannot
    m_line = std::make_unique<Line>(Line::makeTransport(ls, m_demo.get()), ls);
    connect(m_line.get(), &Line::stateChanged, this, &Session::onLineState);
    setState(State::Connecting, m_line->stateText());
    m_line->open();
}

QString Session::playbackLine() const {
    return QStringLiteral("recording ") + QFileInfo(m_settings.recordingPath).absoluteFilePath();
}

void Session::setPlaybackState(State state, const QString &text) {
    if (isPlayback())
        setState(state, text);
}

void Session::disconnectFromLine() {
    m_scheduler.stop();
    m_discovery.reset();
    clearDevices();
    Q_EMIT devicesChanged();
    if (m_line) {
        m_line->disconnect(this);
        m_line->close();
        m_line.reset();
        m_log.add(Event::Kind::Connection, Event::Severity::Info, SessionTr::tr("line"),
                  SessionTr::tr("disconnected"));
    }
    m_demo.reset();
    setState(State::Disconnected, SessionTr::tr("disconnected"));
}

void Session::onLineState(Line::State s, const QString &) {
    const QString text = m_line->stateText();
    for (DeviceModel *d : std::as_const(m_devices))
        d->setLineUp(s == Line::State::Open);
    switch (s) {
    case Line::State::Open:
        m_log.add(Event::Kind::Connection, Event::Severity::Info, SessionTr::tr("line"), text);
        if (m_devices.isEmpty())
            detect();
        else
            setState(State::Connected, connectedText());
        break;
    case Line::State::Retrying:
        m_recorder.markGaps(TelemetryGap::Cause::LineDown);
        m_log.add(Event::Kind::Connection, Event::Severity::Error, SessionTr::tr("line"), text);
        setState(State::Retrying, text);
        break;
    case Line::State::Failed:
        setState(State::Failed, text);
        break;
    case Line::State::Opening:
        setState(State::Connecting, text);
        break;
    case Line::State::Closed:
        break;
    }
}

void Session::detect() {
    setState(State::Detecting,
             SessionTr::tr("looking for devices on %1").arg(m_line->transport().description()));
    if (m_settings.addressing == Addressing::With) {
        identify(m_settings.targetAddress);
        return;
    }
    if (m_settings.addressing == Addressing::Without) {
        identify(std::nullopt);
        return;
    }
    m_discovery = std::make_unique<Discovery>(m_line->queue());
    m_discovery->setScanAllAddresses(m_settings.scanAllAddresses);
    connect(m_discovery.get(), &Discovery::finished, this,
            [this] { adoptDevices(m_discovery->devices()); });
    m_discovery->start();
}

void Session::identify(std::optional<int> address) {
    // The one device the settings name, at any address: Discovery asks it as the CLI does.
    m_discovery = std::make_unique<Discovery>(m_line->queue());
    connect(m_discovery.get(), &Discovery::finished, this, [this, address] {
        const auto &found = m_discovery->identification();
        adoptDevices(m_discovery->devices(),
                     found && !found->ok() ? found->error().text(address) : QString());
    });
    m_discovery->identify(address);
}

void Session::adoptDevices(const QList<DeviceInfo> &found, const QString &unidentified) {
    clearDevices();
    for (const DeviceInfo &info : found) {
        if (info.family.isEmpty())
            continue;
        DeviceModel *d = nullptr;
        const protocol::FamilyInfo *family = m_catalog.family(info.family);
        if (!family)
            continue;
        if (family->isFeeder())
            d = new FeederModel(m_line->queue(), info, m_catalog, this);
        else
            d = new StationModel(m_line->queue(), info, m_catalog, this);
        d->setLineName(lineIdentityName(m_settings.line));
        m_recorder.watch(d);
        if (auto *station = qobject_cast<StationModel *>(d))
            m_joints.watch(
                station, [station](int port) { return TelemetryRecorder::keyOf(*station, port); });
        d->setEventLog(&m_log);
        d->setTemperatureUnit(m_unit);
        d->setWritesBlocked(m_monitorOnly);
        m_devices.append(d);
        m_scheduler.addDevice(d);
        d->logEvent(Event::Kind::Connection, Event::Severity::Info, 0,
                    SessionTr::tr("found %1, software %2")
                        .arg(info.family, info.softwareVersion.isEmpty() ? SessionTr::tr("unknown")
                                                                         : info.softwareVersion));
    }
    m_scheduler.start();
    Q_EMIT devicesChanged();
    if (m_devices.isEmpty() && !unidentified.isEmpty())
        setState(State::Connected, SessionTr::tr("connected to %1, but %2")
                                       .arg(m_line->transport().description(), unidentified));
    else if (const QString heard = m_discovery ? m_discovery->whatCameBack() : QString();
             m_devices.isEmpty() && !heard.isEmpty())
        setState(State::Connected,
                 SessionTr::tr("connected to %1, but no device could be identified; what came "
                               "back: %2 (robot mode off? wrong addressing or baud rate?)")
                     .arg(m_line->transport().description(), heard));
    else if (m_devices.isEmpty())
        setState(State::Connected,
                 SessionTr::tr("connected to %1, but no device answered (robot mode "
                               "off? wrong addressing or baud rate?)")
                     .arg(m_line->transport().description()));
    else
        setState(State::Connected, connectedText());
}

QString Session::connectedText() const {
    return SessionTr::tr("%1, %n device(s)", nullptr, int(m_devices.size()))
        .arg(m_line->transport().description());
}

qint64 Session::sampleTimeMs() const {
    return m_clock.nowMs();
}

void Session::setTemperatureUnit(TemperatureUnit unit) {
    m_unit = unit;
    for (DeviceModel *d : std::as_const(m_devices))
        d->setTemperatureUnit(unit);
    Q_EMIT temperatureUnitChanged();
}

void Session::setMonitorOnly(bool on) {
    m_monitorOnly = on;
    for (DeviceModel *d : std::as_const(m_devices))
        d->setWritesBlocked(on);
    Q_EMIT monitorOnlyChanged(on);
}

} // namespace tipscope::model
