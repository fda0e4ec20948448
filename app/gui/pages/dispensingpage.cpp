#include "dispensingpage.h"

#include "widgets/parametereditor.h"

#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>

namespace tipscope::gui {

using namespace tipscope::model;
using protocol::Role;

DispensingPage::DispensingPage(Session &session, QWidget *parent)
    : Page(session, parent) {
    m_layout = new QVBoxLayout(this);
    connect(&session, &Session::devicesChanged, this, &DispensingPage::rebuild);
    connect(&session, &Session::monitorOnlyChanged, this, [this](bool on) {
        for (QPushButton *b : std::as_const(m_writeButtons))
            b->setEnabled(!on);
    });
    rebuild();
}

bool DispensingPage::appliesTo(const DeviceModel *device) const {
    const auto *station = qobject_cast<const StationModel *>(device);
    return station && !station->dispensingSettings().isEmpty();
}

StationModel *DispensingPage::ale() const {
    StationModel *st = m_session.station();
    return st && appliesTo(st) ? st : nullptr;
}

void DispensingPage::rebuild() {
    delete m_body;
    m_editors.clear();
    m_writeButtons.clear();
    m_body = new QWidget(this);
    m_layout->addWidget(m_body);
    auto *layout = new QVBoxLayout(m_body);
    StationModel *st = ale();
    if (!st) {
        layout->addWidget(new QLabel(tr("Only the ALE has a built-in wire feed."), m_body));
        layout->addStretch(1);
        return;
    }
    m_live = new QLabel(m_body);
    QFont big = m_live->font();
    big.setPointSizeF(big.pointSizeF() * 1.8);
    m_live->setFont(big);
    layout->addWidget(m_live);
    auto *controls = new QHBoxLayout;
    auto *start = new QPushButton(tr("&Start dispensing"), m_body);
    auto *stop = new QPushButton(tr("S&top dispensing"), m_body);
    auto *fuse = new QPushButton(tr("Ignore fuse error…"), m_body);
    connect(start, &QPushButton::clicked, this, &DispensingPage::startDispensing);
    connect(stop, &QPushButton::clicked, this, &DispensingPage::stopDispensing);
    connect(fuse, &QPushButton::clicked, this, [this] {
        StationModel *s = ale();
        Action *a = s ? s->action(Role::IgnoreFuseError) : nullptr;
        if (!a || QMessageBox::warning(this, a->name(), a->danger() + tr("\n\nContinue?"),
                                       QMessageBox::Yes | QMessageBox::Cancel,
                                       QMessageBox::Cancel) != QMessageBox::Yes)
            return;
        m_feedback->setText(s->ignoreFuseError(Confirmation::Confirmed));
    });
    m_writeButtons << start << stop << fuse;
    controls->addWidget(start);
    controls->addWidget(stop);
    controls->addStretch(1);
    controls->addWidget(fuse);
    layout->addLayout(controls);
    auto *settings = new QGroupBox(tr("Wire feed settings"), m_body);
    auto *form = new QFormLayout(settings);
    form->setFieldGrowthPolicy(QFormLayout::FieldsStayAtSizeHint);
    for (Parameter *p : st->dispensingSettings()) {
        if (!p->isWritable())
            continue;
        auto *e = new ParameterEditor(p, settings);
        m_editors.append(e);
        form->addRow(ParameterEditor::labelFor(*p), e);
    }
    auto *apply = new QPushButton(tr("&Apply"), settings);
    connect(apply, &QPushButton::clicked, this, [this] {
        for (ParameterEditor *e : std::as_const(m_editors))
            if (e->parameter() && e->parameter()->edit())
                e->parameter()->apply();
    });
    m_writeButtons.append(apply);
    form->addRow(apply);
    layout->addWidget(settings);
    m_feedback = new QLabel(m_body);
    layout->addWidget(m_feedback);
    layout->addStretch(1);
    for (Parameter *p : st->parameters())
        if (p->meta().group == protocol::Group::Dispensing || p->meta().role == Role::Fuse)
            connect(p, &Parameter::valueChanged, this, &DispensingPage::refreshLive);
    for (QPushButton *b : std::as_const(m_writeButtons))
        b->setEnabled(!m_session.monitorOnly());
    refreshLive();
}

void DispensingPage::refreshLive() {
    StationModel *st = ale();
    if (!st || !m_live)
        return;
    const auto fuse = st->fusePresent();
    m_live->setText(tr("%1 · dispensed %2 in %3 cycles · %4")
                        .arg(st->displayText(Role::Feeding),
                             st->displayText(Role::DispensedLength, 1), // its one port
                             st->displayText(Role::DispensedCycles, 1),
                             !fuse   ? tr("fuse unknown")
                             : *fuse ? tr("fuse present")
                                     : tr("fuse missing or blown")));
}

QString DispensingPage::startDispensing() {
    StationModel *st = ale();
    Action *a = st ? st->action(Role::Start) : nullptr;
    const QString e = a ? a->trigger() : tr("no ALE");
    m_feedback->setText(e);
    return e;
}

QString DispensingPage::stopDispensing() {
    StationModel *st = ale();
    Action *a = st ? st->action(Role::Stop) : nullptr;
    const QString e = a ? a->trigger() : tr("no ALE");
    m_feedback->setText(e);
    return e;
}

} // namespace tipscope::gui
