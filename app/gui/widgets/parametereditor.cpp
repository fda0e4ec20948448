#include "parametereditor.h"

#include "deferredrefresh.h"
#include "valuespinbox.h"

#include "model/device/devicemodel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QVBoxLayout>

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

const QString kRefusedStyle = QStringLiteral("color: #c01c28; font-weight: bold;");
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
    connect(&parameter->device(), &DeviceModel::lineUpChanged, stateRefresh,
            &DeferredRefresh::request);
    connect(&parameter->device(), &DeviceModel::temperatureUnitChanged, this, [this] {
        delete layout();
        qDeleteAll(findChildren<QWidget *>(QString(), Qt::FindDirectChildrenOnly));
        m_spin = nullptr;
        m_disabled = nullptr;
        m_combo = nullptr;
        m_value = nullptr;
        m_refusal.clear();
        build();
    });
}

QString ParameterEditor::labelFor(const Parameter &p) {
    return p.label();
}

void ParameterEditor::build() {
    auto *column = new QVBoxLayout(this);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(2);
    auto *row = new QHBoxLayout;
    column->addLayout(row);
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
        m_spin = new ValueSpinBox(this);
        m_spin->setAccessibleName(p.label());
        m_spin->setDecimals(f.decimals);
        m_spin->setSuffix(f.unit.isEmpty() ? QString() : QLatin1Char(' ') + f.unit);
        m_spin->setSingleStep(p.meta().step * f.scale);
        m_spin->setKeyboardTracking(false);
        m_spin->setMinimumWidth(120);
        connect(m_spin, &QDoubleSpinBox::valueChanged, this, &ParameterEditor::commitSpin);
        if (auto *line = m_spin->findChild<QLineEdit *>())
            connect(line, &QLineEdit::textEdited, this, &ParameterEditor::followTyping);
        connect(m_spin, &QAbstractSpinBox::editingFinished, this, [this] { m_typing = false; });
        row->addWidget(m_spin);
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
        row->addWidget(m_combo);
    }
    m_state = new QLabel(this);
    m_state->setMinimumWidth(90);
    row->addWidget(m_state);
    // The field keeps its size; the editor takes the form's width so that the reason under it
    // is laid out at the width it is shown at (a form sizing the field to its hint measured
    // the wrapped reason at another width, and cut it to its first line).
    row->addStretch(1);
    // Why a value was refused or a write failed, where the eye is: not only in a tooltip.
    m_message = new QLabel(this);
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_message->setStyleSheet(kRefusedStyle);
    m_message->setVisible(false);
    column->addWidget(m_message);
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
    if (m_spin)
        m_spin->setAllowedRange(toDisplay(p.spec(), p.minimum(), t),
                                toDisplay(p.spec(), p.maximum(), t));
    // A refused value stays in the box beside its reason until it is replaced or discarded;
    // what is being typed stays as typed.
    const bool keepTyped = !m_refusal.isEmpty() || m_typing;
    const bool special = shown && p.meta().special.contains(int(*shown));
    if (m_spin && shown && !keepTyped) {
        if (m_disabled)
            m_disabled->setChecked(special);
        m_spin->setEnabled(!special);
        if (!special)
            m_spin->setValue(toDisplay(p.spec(), *shown, t));
    }
    // Not read yet or disabled, a box shows a dash: any number there would read as the
    // device's value.
    if (m_spin && !keepTyped) {
        const bool number = shown && !special;
        m_spin->setSpecialValueText(number ? QString() : QStringLiteral("—"));
        if (!number)
            m_spin->setValue(m_spin->minimum());
    }
    if (m_combo && !keepTyped)
        m_combo->setCurrentIndex(shown ? m_combo->findData(int(*shown)) : -1);
    m_updating = false;
    refreshState();
}

QString ParameterEditor::editorStyle() const {
    const Parameter &p = *m_parameter;
    QString style;
    if (!m_refusal.isEmpty())
        style = QStringLiteral("background: #fbe3e4;");
    else if (p.state() == Parameter::State::Edited)
        style = QStringLiteral("background: #fff4c2;");
    // Read before the line went down: the value is only what it was then.
    if (p.value() && !p.isCurrent())
        style += QStringLiteral("color: palette(mid);");
    return style;
}

void ParameterEditor::refreshState() {
    if (!m_parameter || !m_state)
        return;
    const Parameter &p = *m_parameter;
    QString text, style, tip;
    switch (p.state()) {
    case Parameter::State::Unknown:
        text = tr("not read");
        break;
    case Parameter::State::Reading:
        text = tr("reading…");
        break;
    case Parameter::State::InSync:
        text = tr("✓ in sync");
        style = QStringLiteral("color: palette(mid);");
        // Written and proved, but volatile: a grey "not saved" alone read as a failed write.
        if (p.meta().isVolatile && !p.isSavedToMemory()) {
            text = tr("✓ in sync, not yet saved");
            style.clear();
            tip = tr("Written and read back. The station forgets it when it restarts, unless "
                     "it is saved to station memory.");
        }
        if (!p.isCurrent())
            text = tr("last read %1")
                       .arg(QLocale().toString(p.lastUpdate().time(), QStringLiteral("HH:mm:ss")));
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
        style = kRefusedStyle;
    }
    m_state->setText(text);
    setStyleSheetIfChanged(m_state, style);
    const QString why = !m_refusal.isEmpty()                    ? m_refusal
                        : p.state() == Parameter::State::Failed ? p.failure()
                                                                : QString();
    m_state->setToolTip(why.isEmpty() ? tip : why);
    m_message->setText(why);
    m_message->setVisible(!why.isEmpty());
    const QString sheet = editorStyle();
    // A number box's look goes on its text field: restyling the box itself puts its last value
    // back in the field, over what is being typed.
    QWidget *spinField = m_spin ? m_spin->findChild<QLineEdit *>() : nullptr;
    for (QWidget *w : {spinField, static_cast<QWidget *>(m_combo), static_cast<QWidget *>(m_value)})
        if (w)
            setStyleSheetIfChanged(w, sheet);
}

QString ParameterEditor::stateText() const {
    return m_state ? m_state->text() : QString();
}

QString ParameterEditor::messageText() const {
    return m_message && !m_message->isHidden() ? m_message->text() : QString();
}

void ParameterEditor::discardRefusal() {
    m_typing = false; // what was typed goes with the refusal (Revert, Refresh)
    if (m_refusal.isEmpty())
        return;
    m_refusal.clear();
    refreshFromParameter();
    Q_EMIT refusalChanged();
}

void ParameterEditor::commitSpin() {
    if (m_updating || !m_parameter)
        return;
    m_typing = false;
    qint64 wire = 0;
    if (m_disabled && m_disabled->isChecked()) {
        wire = kDisabledKey;
    } else {
        // Enabled again from the dash: start at the lowest allowed value.
        if (m_spin->value() == m_spin->minimum()) {
            const QSignalBlocker quiet(m_spin);
            m_spin->setValue(m_spin->allowedMinimum());
        }
        wire = fromDisplay(m_parameter->spec(), m_spin->value(),
                           m_parameter->device().temperatureUnit());
    }
    m_spin->setEnabled(!(m_disabled && m_disabled->isChecked()));
    setRefusal(m_parameter->setEdit(wire));
}

// An edit counts while it is typed: a keystroke that makes an allowed value makes it the edit
// (highlighted, Apply on). A value not allowed is said when the typing ends (Enter, or leaving
// the field), not at each keystroke of "350" on its way through "3" and "35"; meanwhile no
// earlier edit stays behind to be applied in its place.
void ParameterEditor::followTyping() {
    if (m_updating || !m_parameter || (m_disabled && m_disabled->isChecked()))
        return;
    m_typing = true;
    bool isNumber = false;
    const double typed = m_spin->locale().toDouble(m_spin->cleanText(), &isNumber);
    const qint64 wire =
        isNumber ? fromDisplay(m_parameter->spec(), typed, m_parameter->device().temperatureUnit())
                 : 0;
    const bool allowed =
        isNumber && !m_parameter->device().writesBlocked() && m_parameter->validate(wire).isEmpty();
    setRefusal({});
    if (allowed)
        (void)m_parameter->setEdit(wire);
    else
        m_parameter->revert();
}

void ParameterEditor::commitCombo() {
    if (m_updating || !m_parameter)
        return;
    setRefusal(m_parameter->setEdit(m_combo->currentData().toInt()));
}

QString ParameterEditor::enterText(const QString &text) {
    const QString why = m_parameter->setEditText(text);
    setRefusal(why);
    refreshFromParameter();
    return why;
}

void ParameterEditor::setRefusal(const QString &why) {
    const bool changed = why != m_refusal;
    m_refusal = why;
    refreshState();
    if (changed)
        Q_EMIT refusalChanged();
}

} // namespace tipscope::gui
