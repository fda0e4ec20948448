#include "parametereditor.h"

#include "deferredrefresh.h"

#include "model/devicemodel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>

namespace tipscope::gui {

using namespace tipscope::model;
using namespace tipscope::protocol;

namespace {
constexpr int kDisabledKey = 99999;

// Setting a style sheet restyles the widget even when the sheet is the same one.
void setStyleSheetIfChanged(QWidget *w, const QString &sheet) {
    if (w->styleSheet() != sheet)
        w->setStyleSheet(sheet);
}

bool isNumeric(const Parameter &p) {
    return p.meta().kind == ValueKind::Number || p.meta().kind == ValueKind::Delay;
}
} // namespace

ParameterEditor::ParameterEditor(Parameter *parameter, QWidget *parent)
    : QWidget(parent)
    , m_parameter(parameter) {
    build();
    // Live values change with every poll: an editor on a hidden page catches up when shown.
    auto *valueRefresh = new DeferredRefresh(*this, [this] { refreshFromParameter(); });
    connect(parameter, &Parameter::valueChanged, valueRefresh, &DeferredRefresh::request);
    connect(parameter, &Parameter::editChanged, valueRefresh, &DeferredRefresh::request);
    auto *stateRefresh = new DeferredRefresh(*this, [this] { refreshState(); });
    connect(parameter, &Parameter::stateChanged, stateRefresh, &DeferredRefresh::request);
    connect(&parameter->device(), &DeviceModel::temperatureUnitChanged, this, [this] {
        delete layout();
        qDeleteAll(findChildren<QWidget *>(QString(), Qt::FindDirectChildrenOnly));
        m_spin = nullptr;
        m_disabled = nullptr;
        m_combo = nullptr;
        m_value = nullptr;
        build();
    });
}

QString ParameterEditor::labelFor(const Parameter &p) {
    return p.label();
}

void ParameterEditor::build() {
    auto *row = new QHBoxLayout(this);
    row->setContentsMargins(0, 0, 0, 0);
    const Parameter &p = *m_parameter;
    const QString tip = p.description() + QStringLiteral("\n") +
                        tr("Allowed: %1").arg(p.allowedText()) + QStringLiteral("\n") +
                        tr("Command: %1").arg(QString::fromLatin1(p.code()));
    setToolTip(tip);
    if (!p.isWritable()) {
        m_value = new QLabel(this);
        m_value->setTextInteractionFlags(Qt::TextSelectableByMouse);
        m_value->setAccessibleName(p.label());
        row->addWidget(m_value, 1);
    } else if (isNumeric(p)) {
        const DisplayFormat f = displayFormat(p.spec(), p.device().temperatureUnit());
        m_spin = new QDoubleSpinBox(this);
        m_spin->setAccessibleName(p.label());
        m_spin->setDecimals(f.decimals);
        m_spin->setSuffix(f.unit.isEmpty() ? QString() : QLatin1Char(' ') + f.unit);
        m_spin->setSingleStep(p.meta().step * f.scale);
        m_spin->setRange(toDisplay(p.spec(), p.spec().min, p.device().temperatureUnit()),
                         toDisplay(p.spec(), p.spec().max, p.device().temperatureUnit()));
        m_spin->setKeyboardTracking(false);
        m_spin->setMinimumWidth(120);
        connect(m_spin, &QDoubleSpinBox::valueChanged, this, &ParameterEditor::commitSpin);
        row->addWidget(m_spin, 1);
        if (p.meta().special.contains(kDisabledKey)) {
            m_disabled =
                new QCheckBox(protocol::catalogText(p.meta().special.value(kDisabledKey)), this);
            m_disabled->setAccessibleName(tr("%1 disabled").arg(p.label()));
            connect(m_disabled, &QCheckBox::toggled, this, &ParameterEditor::commitSpin);
            row->addWidget(m_disabled);
        }
    } else {
        m_combo = new QComboBox(this);
        m_combo->setAccessibleName(p.label());
        for (auto it = p.spec().values.begin(); it != p.spec().values.end(); ++it)
            m_combo->addItem(protocol::catalogText(it.value()), it.key());
        connect(m_combo, &QComboBox::activated, this, &ParameterEditor::commitCombo);
        row->addWidget(m_combo, 1);
    }
    m_state = new QLabel(this);
    m_state->setMinimumWidth(90);
    row->addWidget(m_state);
    refreshFromParameter();
}

void ParameterEditor::refreshFromParameter() {
    if (!m_parameter)
        return;
    m_updating = true;
    const Parameter &p = *m_parameter;
    const TemperatureUnit t = p.device().temperatureUnit();
    const std::optional<qint64> shown = p.edit() ? p.edit() : p.number();
    if (m_value)
        m_value->setText(p.displayText());
    if (m_spin && shown) {
        const bool special = p.meta().special.contains(int(*shown));
        if (m_disabled)
            m_disabled->setChecked(special);
        m_spin->setEnabled(!special);
        if (!special)
            m_spin->setValue(toDisplay(p.spec(), *shown, t));
    }
    // Not read yet, a box shows a dash: its minimum there would read as the device's value.
    if (m_spin) {
        m_spin->setSpecialValueText(shown ? QString() : QStringLiteral("—"));
        if (!shown)
            m_spin->setValue(m_spin->minimum());
    }
    if (m_combo)
        m_combo->setCurrentIndex(shown ? m_combo->findData(int(*shown)) : -1);
    m_updating = false;
    refreshState();
}

void ParameterEditor::refreshState() {
    if (!m_parameter || !m_state)
        return;
    const Parameter &p = *m_parameter;
    QString text, style;
    switch (p.state()) {
    case Parameter::State::Unknown:
        text = tr("not read");
        break;
    case Parameter::State::Reading:
        text = tr("reading…");
        break;
    case Parameter::State::InSync:
        text = p.meta().isVolatile && !p.isSavedToMemory() ? tr("not saved") : tr("✓ in sync");
        style = QStringLiteral("color: palette(mid);");
        break;
    case Parameter::State::Edited:
        text = tr("edited");
        style = QStringLiteral("color: #8a5a00; font-weight: bold;");
        break;
    case Parameter::State::Writing:
        text = tr("writing…");
        break;
    case Parameter::State::Failed:
        text = tr("✗ failed");
        style = QStringLiteral("color: #c01c28; font-weight: bold;");
        break;
    }
    if (!m_refusal.isEmpty()) {
        text = tr("✗ refused");
        style = QStringLiteral("color: #c01c28; font-weight: bold;");
    }
    m_state->setText(text);
    setStyleSheetIfChanged(m_state, style);
    m_state->setToolTip(!m_refusal.isEmpty() ? m_refusal : p.failure());
    const bool edited = p.state() == Parameter::State::Edited;
    const QString editorStyle = !m_refusal.isEmpty() ? QStringLiteral("background: #fbe3e4;")
                                : edited             ? QStringLiteral("background: #fff4c2;")
                                                     : QString();
    if (m_spin)
        setStyleSheetIfChanged(m_spin, editorStyle);
    if (m_combo)
        setStyleSheetIfChanged(m_combo, editorStyle);
}

void ParameterEditor::commitSpin() {
    if (m_updating || !m_parameter)
        return;
    qint64 wire = 0;
    if (m_disabled && m_disabled->isChecked())
        wire = kDisabledKey;
    else
        wire = fromDisplay(m_parameter->spec(), m_spin->value(),
                           m_parameter->device().temperatureUnit());
    m_spin->setEnabled(!(m_disabled && m_disabled->isChecked()));
    m_refusal = m_parameter->setEdit(wire);
    refreshState();
}

void ParameterEditor::commitCombo() {
    if (m_updating || !m_parameter)
        return;
    m_refusal = m_parameter->setEdit(m_combo->currentData().toInt());
    refreshState();
}

QString ParameterEditor::enterText(const QString &text) {
    m_refusal = m_parameter->setEditText(text);
    refreshFromParameter();
    refreshState();
    return m_refusal;
}

} // namespace tipscope::gui
