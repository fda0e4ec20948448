#include "feederpage.h"

#include "widgets/parametereditor.h"

#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>

namespace tipscope::gui {

using namespace tipscope::model;

FeederPage::FeederPage(Session &session, QWidget *parent)
    : Page(session, parent) {
    m_layout = new QVBoxLayout(this);
    connect(&session, &Session::devicesChanged, this, &FeederPage::rebuild);
    connect(&session, &Session::monitorOnlyChanged, this, &FeederPage::updateEnabled);
    rebuild();
}

bool FeederPage::appliesTo(const DeviceModel *device) const {
    return qobject_cast<const FeederModel *>(device) != nullptr;
}

FeederModel *FeederPage::feeder() const {
    return m_session.feeder();
}

void FeederPage::setSelection(DeviceModel *device, int port) {
    Page::setSelection(device, port);
}

void FeederPage::rebuild() {
    delete m_body;
    m_editors.clear();
    m_writeButtons.clear();
    m_apply = nullptr;
    m_revert = nullptr;
    m_body = new QWidget(this);
    m_layout->addWidget(m_body);
    auto *layout = new QVBoxLayout(m_body);
    FeederModel *f = feeder();
    if (!f) {
        layout->addWidget(new QLabel(tr("No feeder on this line."), m_body));
        layout->addStretch(1);
        return;
    }
    m_live = new QLabel(m_body);
    QFont big = m_live->font();
    big.setPointSizeF(big.pointSizeF() * 2.2);
    big.setBold(true);
    m_live->setFont(big);
    m_error = new QLabel(m_body);
    m_error->setWordWrap(true);
    layout->addWidget(
        new QLabel(QStringLiteral("<b>%1</b>").arg(f->displayName().toHtmlEscaped()), m_body));
    layout->addWidget(m_live);

    auto *controls = new QHBoxLayout;
    auto addButton = [&](const QString &text, const QString &tip, auto slot) {
        auto *b = new QPushButton(text, m_body);
        b->setToolTip(tip);
        connect(b, &QPushButton::clicked, this, slot);
        controls->addWidget(b);
        m_writeButtons.append(b);
        return b;
    };
    addButton(tr("Feed &forward"), tr("W-SFD 00001"), [this] { start(true); });
    addButton(tr("Feed &backward"), tr("W-SFD 00000"), [this] { start(false); });
    addButton(tr("&Stop"), tr("W-SSD"), [this] { stop(); });
    addButton(tr("Start &loading"), tr("W-SLD 00001: feed ignoring errors, for a new spool"),
              [this] { setLoading(true); });
    addButton(tr("End loading"), tr("W-SLD 00000"), [this] { setLoading(false); });
    controls->addStretch(1);
    layout->addLayout(controls);

    auto *errorRow = new QHBoxLayout;
    errorRow->addWidget(m_error, 1);
    auto *reset = new QPushButton(tr("&Reset error"), m_body);
    connect(reset, &QPushButton::clicked, this, [this] { resetError(); });
    m_writeButtons.append(reset);
    errorRow->addWidget(reset);
    layout->addLayout(errorRow);

    auto *settings = new QGroupBox(tr("Feeding settings"), m_body);
    auto *form = new QFormLayout(settings);
    // The editors take the width: the reason under a refused value wraps at the width shown.
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    for (Parameter *p : f->settings()) {
        auto *e = new ParameterEditor(p, settings);
        m_editors.append(e);
        form->addRow(ParameterEditor::labelFor(*p), e);
        connect(p, &Parameter::stateChanged, this, &FeederPage::updateEnabled);
        connect(e, &ParameterEditor::refusalChanged, this, &FeederPage::updateEnabled);
    }
    m_apply = new QPushButton(tr("&Apply"), settings);
    m_revert = new QPushButton(tr("Re&vert"), settings);
    m_revert->setToolTip(tr("Discard the values typed here and show the feeder's own"));
    auto *save = new QPushButton(tr("Save to feeder memory"), settings);
    save->setToolTip(tr("W-NVS: mode, speed and length survive a restart"));
    connect(m_apply, &QPushButton::clicked, this, &FeederPage::applyEdits);
    connect(m_revert, &QPushButton::clicked, this, &FeederPage::revertEdits);
    connect(save, &QPushButton::clicked, this,
            [this] { report(feeder() ? feeder()->saveToMemory() : QString()); });
    m_writeButtons << save;
    auto *buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(m_revert);
    buttons->addWidget(m_apply);
    buttons->addWidget(save);
    form->addRow(buttons);
    layout->addWidget(settings);

    auto *counters = new QGroupBox(tr("Counters"), m_body);
    auto *grid = new QGridLayout(counters);
    int row = 0;
    for (Parameter *p : f->counters()) {
        auto *value = new ParameterEditor(p, counters);
        grid->addWidget(new QLabel(p->label(), counters), row, 0);
        grid->addWidget(value, row, 1);
        if (Action *a = f->action(p->code())) {
            auto *b = new QPushButton(tr("Reset"), counters);
            b->setToolTip(a->danger());
            connect(b, &QPushButton::clicked, this,
                    [this, code = p->code()] { resetCounter(code, false); });
            m_writeButtons.append(b);
            grid->addWidget(b, row, 2);
        }
        ++row;
    }
    layout->addWidget(counters);
    m_feedback = new QLabel(m_body);
    m_feedback->setWordWrap(true);
    layout->addWidget(m_feedback);
    layout->addStretch(1);
    for (Parameter *p : f->parameters())
        connect(p, &Parameter::valueChanged, this, &FeederPage::refreshLive);
    refreshLive();
    updateEnabled();
}

void FeederPage::refreshLive() {
    FeederModel *f = feeder();
    if (!f || !m_live)
        return;
    const QString state =
        f->isFeeding().has_value() ? (*f->isFeeding() ? tr("Feeding") : tr("Idle")) : tr("—");
    m_live->setText(tr("%1 · fed %2").arg(state, f->displayText(protocol::Role::FedLength)));
    const auto e = f->errorCode();
    m_error->setText(e && *e != 0 ? tr("⚠ %1").arg(f->errorText()) : tr("No feeder error"));
    m_error->setStyleSheet(e && *e != 0 ? QStringLiteral("color:#c01c28; font-weight:bold;")
                                        : QString());
}

void FeederPage::updateEnabled() {
    const bool allowed = !m_session.monitorOnly();
    for (QPushButton *b : std::as_const(m_writeButtons)) {
        b->setEnabled(allowed);
        if (!allowed)
            b->setToolTip(tr("Monitor-only mode is on: nothing is written"));
    }
    if (!m_apply)
        return;
    // As on the Settings page: Apply only when there is something to write and nothing typed
    // is refused (it would write the others and say nothing of the refused one).
    int edited = 0;
    bool refused = false;
    for (const ParameterEditor *e : std::as_const(m_editors)) {
        refused = refused || e->hasRefusal();
        if (e->parameter() && e->parameter()->edit())
            ++edited;
    }
    m_apply->setText(edited ? tr("&Apply (%1)").arg(edited) : tr("&Apply"));
    m_apply->setEnabled(allowed && edited > 0 && !refused);
    m_apply->setToolTip(!allowed  ? tr("Monitor-only mode is on: nothing is written")
                        : refused ? tr("A value typed is not allowed: correct it or Revert")
                                  : QString());
    m_revert->setEnabled(edited > 0 || refused);
}

void FeederPage::revertEdits() {
    for (ParameterEditor *e : std::as_const(m_editors)) {
        e->discardRefusal();
        if (e->parameter())
            e->parameter()->revert();
    }
    updateEnabled();
}

void FeederPage::report(const QString &error) {
    if (m_feedback)
        m_feedback->setText(error.isEmpty()
                                ? QString()
                                : QStringLiteral("<span style='color:#c01c28'>%1</span>")
                                      .arg(error.toHtmlEscaped()));
}

QString FeederPage::start(bool forward) {
    const QString e = feeder() ? feeder()->startFeeding(forward) : tr("no feeder");
    report(e);
    return e;
}

QString FeederPage::stop() {
    const QString e = feeder() ? feeder()->stopFeeding() : tr("no feeder");
    report(e);
    return e;
}

QString FeederPage::setLoading(bool on) {
    const QString e = feeder() ? feeder()->setLoading(on) : tr("no feeder");
    report(e);
    return e;
}

QString FeederPage::resetError() {
    const QString e = feeder() ? feeder()->resetError() : tr("no feeder");
    report(e);
    return e;
}

QString FeederPage::resetCounter(const QByteArray &code, bool confirmed) {
    FeederModel *f = feeder();
    Action *a = f ? f->action(code) : nullptr;
    if (!a)
        return tr("no such counter");
    if (!confirmed) {
        const auto answer =
            QMessageBox::warning(this, a->name(), a->danger() + tr("\n\nReset it?"),
                                 QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel);
        if (answer != QMessageBox::Yes)
            return tr("cancelled");
    }
    const QString e = f->resetPartialCounter(code, Confirmation::Confirmed);
    report(e);
    return e;
}

void FeederPage::applyEdits() {
    for (ParameterEditor *e : std::as_const(m_editors))
        if (e->parameter() && e->parameter()->edit())
            e->parameter()->apply();
}

QPushButton *FeederPage::button(const QString &name) const {
    return name == QLatin1String("apply")    ? m_apply
           : name == QLatin1String("revert") ? m_revert
                                             : nullptr;
}

ParameterEditor *FeederPage::editorFor(const QByteArray &code) const {
    for (ParameterEditor *e : m_editors)
        if (e->parameter() && e->parameter()->code() == code)
            return e;
    return nullptr;
}

QString FeederPage::liveText() const {
    return m_live ? m_live->text() : QString();
}

} // namespace tipscope::gui
