// ParameterEditor: the editor a Parameter builds for itself from its catalog metadata, so that
// a new command needs a catalog entry, not a widget.
//
// Numbers and delays get a spin box in display units with the parameter's range and step (and a
// "disabled" box where the catalog has that special value); enums get a combo box; read-only
// values a label. The editor shows the parameter's state: an edited value is highlighted, a
// write in progress says so, a failure shows the reason. Edits go to Parameter::setEdit(); a
// refused value is shown in red with what is allowed, and nothing is written until the page
// applies. A value reported by the device updates the editor without being sent back.
#pragma once

#include "model/parameter.h"

#include <QPointer>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace tipscope::gui {

class ParameterEditor : public QWidget {
    Q_OBJECT
public:
    explicit ParameterEditor(model::Parameter *parameter, QWidget *parent = nullptr);

    [[nodiscard]] model::Parameter *parameter() const { return m_parameter; }
    // The label to put in front of the editor (name, with the tool or port when useful).
    [[nodiscard]] static QString labelFor(const model::Parameter &p);
    // For tests and keyboard users: set the editor's text as if typed, then commit it.
    QString enterText(const QString &text);

private:
    void build();
    void refreshFromParameter();
    void refreshState();
    void commitSpin();
    void commitCombo();

    QPointer<model::Parameter> m_parameter;
    QDoubleSpinBox *m_spin = nullptr;
    QCheckBox *m_disabled = nullptr;
    QComboBox *m_combo = nullptr;
    QLabel *m_value = nullptr;
    QLabel *m_state = nullptr;
    bool m_updating = false;
    QString m_refusal;
};

} // namespace tipscope::gui
