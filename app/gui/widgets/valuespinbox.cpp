#include "valuespinbox.h"

namespace tipscope::gui {

ValueSpinBox::ValueSpinBox(QWidget *parent)
    : QDoubleSpinBox(parent) {
    setRange(-kWideLimit, kWideLimit);
}

void ValueSpinBox::setAllowedRange(double minimum, double maximum) {
    m_allowedMin = minimum;
    m_allowedMax = maximum;
}

void ValueSpinBox::stepBy(int steps) {
    // From a value outside the allowed range the arrows bring it back to the nearest limit.
    const double next = qBound(m_allowedMin, value() + steps * singleStep(), m_allowedMax);
    setValue(next);
    selectAll();
}

QAbstractSpinBox::StepEnabled ValueSpinBox::stepEnabled() const {
    if (isReadOnly())
        return StepNone;
    StepEnabled e = StepNone;
    if (value() < m_allowedMax)
        e |= StepUpEnabled;
    if (value() > m_allowedMin)
        e |= StepDownEnabled;
    return e;
}

} // namespace tipscope::gui
