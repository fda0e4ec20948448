#include "overviewpage.h"

#include "portcard.h"

#include <QGridLayout>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

namespace tipscope::gui {

using namespace tipscope::model;
using protocol::Role;

OverviewPage::OverviewPage(Session &session, QWidget *parent)
    : Page(session, parent) {
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
    layout->addWidget(m_station);
    layout->addWidget(m_stationProblem);
    layout->addWidget(scroll, 1);
    layout->addWidget(m_feeder);
    connect(&session, &Session::devicesChanged, this, &OverviewPage::rebuild);
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
    if (StationModel *st = m_session.station()) {
        const int columns = st->ports().size() > 2 ? 2 : int(st->ports().size());
        for (PortModel *port : st->ports()) {
            auto *card = new PortCard(*port, m_cardsHost);
            const int i = int(m_cards.size());
            m_grid->addWidget(card, i / qMax(1, columns), i % qMax(1, columns));
            m_cards.append(card);
        }
        m_grid->setRowStretch(int(st->ports().size() + 1) / qMax(1, columns) + 1, 1);
        for (Role role : {Role::Error, Role::TransformerTemperature, Role::Fuse})
            if (Parameter *p = st->parameter(role))
                connect(p, &Parameter::valueChanged, this, &OverviewPage::refreshStation);
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

void OverviewPage::refreshStation() {
    StationModel *st = m_session.station();
    if (!st) {
        m_station->setText(m_session.devices().isEmpty()
                               ? tr("<i>No station. Connect to a line, or start the demo.</i>")
                               : QString());
        m_stationProblem->clear();
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
    m_feeder->setText(facts.join(QStringLiteral(" · ")));
}

void OverviewPage::updateWritesAllowed() {
    for (PortCard *c : std::as_const(m_cards))
        c->setWritesAllowed(!m_session.monitorOnly());
}

} // namespace tipscope::gui
