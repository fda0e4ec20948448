// ValueSpinBox: a number box that never changes what a person typed. QDoubleSpinBox clamps a
// typed 600 to its maximum of 500, or refuses the keystroke, without a word; this box takes any
// number of a wide range, so the model (Parameter::validate) can refuse it and say what is
// allowed. Only the arrows and the wheel stop at the allowed limits (setAllowedRange()).
#pragma once

#include <QDoubleSpinBox>

namespace tipscope::gui {

class ValueSpinBox : public QDoubleSpinBox {
    Q_OBJECT
public:
    // What the box itself takes: far beyond any limit of the catalog, in display units.
    static constexpr double kWideLimit = 999999;

    explicit ValueSpinBox(QWidget *parent = nullptr);

    void setAllowedRange(double minimum, double maximum);
    [[nodiscard]] double allowedMinimum() const { return m_allowedMin; }
    [[nodiscard]] double allowedMaximum() const { return m_allowedMax; }
    void stepBy(int steps) override;

protected:
    [[nodiscard]] StepEnabled stepEnabled() const override;

private:
    double m_allowedMin = -kWideLimit;
    double m_allowedMax = kWideLimit;
};

} // namespace tipscope::gui
