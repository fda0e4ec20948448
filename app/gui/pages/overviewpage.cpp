#include "overviewpage.h"

#include "portcard.h"

#include "model/events/eventtext.h"
#include "model/live/telemetryrecorder.h"

#include <QGridLayout>
#include <QLabel>
#include <QLocale>
#include <QScrollArea>
#include <QVBoxLayout>

namespace tipscope::gui {

using namespace tipscope::model;
using protocol::Role;

namespace {
// Only the last reading of the fastest value says how old the page is.
QString lastReadText(const StationModel &st) {
    QDateTime last;
    for (PortModel *port : st.ports()) {
        const Parameter *tip = port->parameter(Role::TipTemperature);
        const QDateTime t = tip ? tip->lastUpdate() : QDateTime();
        if (t.isValid() && (!last.isValid() || t > last))
            last = t;
    }
    return last.isValid() ? QLocale().toString(last.time(), QStringLiteral("HH:mm:ss")) : QString();
}
} // namespace

OverviewPage::OverviewPage(Session &session, QWidget *parent)
    : Page(session, parent) {
    m_notice = new QLabel(this);
    m_notice->setWordWrap(true);
    m_notice->setObjectName(QStringLiteral("overviewNotice"));
    m_notice->setStyleSheet(QStringLiteral("QLabel { background: #fdf3d8; border: 1px solid "
                                           "#e5a50a; padding: 6px; font-weight: bold; }"));
    m_notice->setVisible(false);
    m_station = new QLabel(this);
    m_station->setTextFormat(Qt::RichText);
    m_stationProblem = new QLabel(this);
    m_stationProblem->setWordWrap(true);
    m_feeder = new QLabel(this);
    m_feeder->setTextFormat(Qt::RichText);
    m_cardsHost = new QWidget(this);
    m_grid = new QGridLayout(m_cardsHost);
    auto *scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(m_cardsHost);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_notice);
    layout->addWidget(m_station);
    layout->addWidget(m_stationProblem);
    layout->addWidget(scroll, 1);
    layout->addWidget(m_feeder);
    connect(&session, &Session::devicesChanged, this, &OverviewPage::rebuild);
    connect(&session, &Session::stateChanged, this, [this] {
        if (!m_session.station())
            refreshStation();
    });
    connect(&session.joints(), &JointWatcher::jointEnded, this, &OverviewPage::showJoint);
    connect(&session, &Session::monitorOnlyChanged, this, &OverviewPage::updateWritesAllowed);
    rebuild();
}

QSet<int> OverviewPage::visiblePorts() const {
    QSet<int> ports;
    for (int i = 1; i <= m_cards.size(); ++i)
        ports.insert(i);
    return ports;
}

void OverviewPage::rebuild() {
    qDeleteAll(m_cards);
    m_cards.clear();
    for (int row = 0; row < m_grid->rowCount(); ++row)
        m_grid->setRowStretch(row, 0);
    if (StationModel *st = m_session.station()) {
        const int columns = qMax(1, st->ports().size() > 2 ? 2 : int(st->ports().size()));
        for (PortModel *port : st->ports()) {
            auto *card = new PortCard(*port, m_session.telemetry(),
                                      TelemetryRecorder::keyOf(*st, port->number()), m_cardsHost);
            const int i = int(m_cards.size());
            m_grid->addWidget(card, i / columns, i % columns);
            m_grid->setRowStretch(i / columns, 1);
            m_cards.append(card);
            const auto last = m_lastJoints.constFind(
                QStringLiteral("%1|%2").arg(st->identity().key()).arg(port->number()));
            if (last != m_lastJoints.cend())
                card->showJoint(*last);
        }
        for (Role role : {Role::Error, Role::TransformerTemperature, Role::Fuse})
            if (Parameter *p = st->parameter(role))
                connect(p, &Parameter::valueChanged, this, &OverviewPage::refreshStation);
        // A steady transformer temperature sends no new value: the unit's change redraws it.
        connect(st, &DeviceModel::temperatureUnitChanged, this, &OverviewPage::refreshStation);
    }
    for (DeviceModel *d : m_session.devices()) {
        connect(d, &DeviceModel::lineUpChanged, this, &OverviewPage::updateWritesAllowed,
                Qt::UniqueConnection);
        connect(d, &DeviceModel::lineUpChanged, this, &OverviewPage::refreshStation,
                Qt::UniqueConnection);
        connect(d, &DeviceModel::lineUpChanged, this, &OverviewPage::refreshFeeder,
                Qt::UniqueConnection);
    }
    if (FeederModel *f = m_session.feeder())
        for (Parameter *p : f->parameters())
            connect(p, &Parameter::valueChanged, this, &OverviewPage::refreshFeeder);
    refreshStation();
    refreshFeeder();
    updateWritesAllowed();
}

QString OverviewPage::stationText() const {
    return m_station->text() + m_stationProblem->text();
}

QString OverviewPage::noticeText() const {
    return m_notice->isHidden() ? QString() : m_notice->text();
}

void OverviewPage::refreshStation() {
    StationModel *st = m_session.station();
    if (!st) {
        // A line in use says what it is doing about it: a fleet tile's click lands here.
        const bool idle = m_session.state() == Session::State::Disconnected;
        const bool none = m_session.devices().isEmpty();
        m_station->setText(!none  ? QString()
                           : idle ? tr("<i>No station. Connect to a line, or start the demo.</i>")
                                  : tr("<i>No station on this line.</i>"));
        m_stationProblem->setText(none && !idle ? model::asSentence(m_session.stateText())
                                                : QString());
        return;
    }
    QStringList facts{
        QStringLiteral("<b>%1</b>").arg(st->displayName().toHtmlEscaped()),
        tr("family %1").arg(st->family()),
        tr("software %1")
            .arg(st->info().softwareVersion.isEmpty() ? tr("—") : st->info().softwareVersion)};
    if (Parameter *tt = st->parameter(Role::TransformerTemperature); tt && tt->value())
        facts.append(tr("transformer %1").arg(tt->displayText()));
    if (const auto fuse = st->fusePresent())
        facts.append(*fuse ? tr("fuse present")
                           : tr("<span style='color:#c01c28'>fuse missing or blown</span>"));
    m_station->setText(facts.join(QStringLiteral(" · ")));
    m_station->setEnabled(st->isLineUp());
    m_stationProblem->setEnabled(st->isLineUp());
    const auto error = st->stationError();
    m_stationProblem->setText(
        error && *error != 0 ? tr("⚠ Station error: %1").arg(st->stationErrorText()) : QString());
    m_stationProblem->setStyleSheet(QStringLiteral("color: #c01c28; font-weight: bold;"));
}

void OverviewPage::refreshFeeder() {
    FeederModel *f = m_session.feeder();
    if (!f) {
        m_feeder->clear();
        return;
    }
    QStringList facts{QStringLiteral("<b>%1</b>").arg(f->displayName().toHtmlEscaped())};
    facts.append(f->isFeeding().value_or(false) ? tr("feeding") : tr("idle"));
    if (Parameter *fdl = f->parameter(Role::FedLength); fdl && fdl->value())
        facts.append(tr("fed %1").arg(fdl->displayText()));
    if (Parameter *spd = f->parameter(Role::FeedSpeed); spd && spd->value())
        facts.append(tr("speed %1").arg(spd->displayText()));
    if (const auto e = f->errorCode(); e && *e != 0)
        facts.append(QStringLiteral("<span style='color:#c01c28'>⚠ %1</span>")
                         .arg(f->errorText().toHtmlEscaped()));
    if (!f->isLineUp())
        facts.append(tr("not connected, as last read"));
    m_feeder->setText(facts.join(QStringLiteral(" · ")));
    m_feeder->setEnabled(f->isLineUp());
}

void OverviewPage::showJoint(const JointRecord &joint) {
    m_lastJoints.insert(QStringLiteral("%1|%2").arg(joint.device.key()).arg(joint.port), joint);
    StationModel *st = m_session.station();
    if (st && st->identity() == joint.device && joint.port >= 1 && joint.port <= m_cards.size())
        m_cards.at(joint.port - 1)->showJoint(joint);
}

void OverviewPage::updateWritesAllowed() {
    StationModel *st = m_session.station();
    const QString why = st ? st->writesUnavailableReason() : QString();
    for (PortCard *c : std::as_const(m_cards))
        c->setWritesAllowed(why.isEmpty());
    QString notice;
    if (st && !st->isLineUp()) {
        const QString last = lastReadText(*st);
        notice = last.isEmpty()
                     ? tr("⚠ Not connected: nothing has been read yet. The robot controls are "
                          "off until the line is back.")
                     : tr("⚠ Not connected: the greyed values are as last read at %1. The robot "
                          "controls are off until the line is back.")
                           .arg(last);
    } else if (st && !why.isEmpty()) {
        notice = tr("Monitor-only mode is on: the robot controls are off.");
    }
    m_notice->setText(notice);
    m_notice->setVisible(!notice.isEmpty());
}

} // namespace tipscope::gui
