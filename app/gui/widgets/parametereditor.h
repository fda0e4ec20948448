// ParameterEditor: the editor a Parameter builds for itself from its catalog metadata, so that
// a new command needs a catalog entry, not a widget.
//
// Numbers and delays get a spin box in display units with the parameter's range and step (and a
// "disabled" box where the catalog has that special value); enums get a combo box; read-only
// values a label. The editor shows the parameter's state: an edited value is highlighted, a
// write in progress says so, a failure shows the reason under the field. Edits go to
// Parameter::setEdit() as they are typed (an allowed value counts at once; one not allowed is
// refused when the typing ends); a number box never clamps what was typed (ValueSpinBox), so a
// value out of range is refused by the model, stays in the box in red, and the whole reason with
// what is allowed is written under it; nothing is written until the page applies, and
// discardRefusal() (Revert, Refresh) puts the parameter's value back. A value reported by the
// device updates the editor without being sent back. While the line is down the value is greyed and
// the state says when it was last read.
#pragma once

#include "model/device/parameter.h"

#include <QPointer>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;

namespace tipscope::gui {

class ValueSpinBox;

class ParameterEditor : public QWidget {
    Q_OBJECT
public:
    explicit ParameterEditor(model::Parameter *parameter, QWidget *parent = nullptr);

    [[nodiscard]] model::Parameter *parameter() const { return m_parameter; }
    // The label to put in front of the editor (name, with the tool or port when useful).
    [[nodiscard]] static QString labelFor(const model::Parameter &p);
    // For tests and keyboard users: set the editor's text as if typed, then commit it.
    QString enterText(const QString &text);
    // A value typed and refused: shown until another is typed or the refusal is discarded.
    [[nodiscard]] bool hasRefusal() const { return !m_refusal.isEmpty(); }
    void discardRefusal();
    // What the editor says beside and under the field, as shown (for tests).
    [[nodiscard]] QString stateText() const;
    [[nodiscard]] QString messageText() const;

Q_SIGNALS:
    void refusalChanged();

private:
    void build();
    void setRefusal(const QString &why);
    void refreshFromParameter();
    void refreshState();
    void commitSpin();
    void followTyping();
    void commitCombo();
    [[nodiscard]] QString editorStyle() const;

    QPointer<model::Parameter> m_parameter;
    ValueSpinBox *m_spin = nullptr;
    QCheckBox *m_disabled = nullptr;
    QComboBox *m_combo = nullptr;
    QLabel *m_value = nullptr;
    QLabel *m_state = nullptr;
    QLabel *m_message = nullptr;
    bool m_updating = false;
    bool m_typing = false; // from a keystroke in the number box to Enter or leaving the field
    QString m_refusal;
};

} // namespace tipscope::gui
