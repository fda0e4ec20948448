// SettingsPage: every setting of the selected device, generated from the parameters'
// metadata and grouped (station, port, alarms, each tool with the connected one first, ALE
// dispensing, feeder), with Apply / Revert, save to station memory, the dangerous actions behind
// confirmations that say what will happen, and profiles (save, compare, dry run, apply).
//
// Whatever is off says why under the buttons, not only in a tooltip: monitor-only mode turns off
// Apply, Save to station memory and Station actions; a line that is down turns off Profiles too,
// and the values are shown greyed with the time they were last read. Revert and Refresh also
// discard values that were typed and refused. A saved profile asks for an optional comment and
// says where it went, until the next action (an edit, Apply, Revert, Refresh, another port).
#pragma once

#include "page.h"

#include "base/outcome.h"

class QComboBox;
class QLabel;
class QPushButton;
class QScrollArea;
class QVBoxLayout;
class QToolButton;

namespace tipscope::gui {

class DeferredRefresh;
class ParameterEditor;

class SettingsPage : public Page {
    Q_OBJECT
public:
    explicit SettingsPage(model::Session &session, QWidget *parent = nullptr);

    [[nodiscard]] QString title() const override { return tr("Settings"); }
    void setSelection(model::DeviceModel *device, int port) override;
    void setActive(bool active) override;
    [[nodiscard]] QSet<int> visiblePorts() const override { return {m_port > 0 ? m_port : 1}; }

    // Writes every edited value (each is read back); for the Apply button and tests.
    void applyEdits();
    void revertEdits();
    void refreshValues();
    [[nodiscard]] ParameterEditor *editorFor(const QByteArray &code) const;
    [[nodiscard]] int editedCount() const;
    // Saves the device's settings as a profile with `comment`; the confirmation shown (where it
    // went, how many settings), or why it was not saved.
    base::Outcome<QString> saveProfileTo(const QString &path, const QString &comment);
    // What the page says under its buttons (why some are off, the last profile saved).
    [[nodiscard]] QString noticeText() const;
    // The buttons, for tests: "apply", "revert", "refresh", "save", "actions", "profiles".
    [[nodiscard]] QWidget *button(const QString &name) const;

private:
    void rebuild();
    void addGroup(const QString &title, const QList<model::Parameter *> &params);
    void updateButtons();
    void forgetSavedProfile();
    void saveToMemory();
    void runDangerous(const QByteArray &code);
    void saveProfile();
    void openProfile();
    [[nodiscard]] QList<model::Parameter *> shownParameters() const;
    [[nodiscard]] bool anyRefusal() const;

    QComboBox *m_portBox;
    QPushButton *m_apply;
    QPushButton *m_revert;
    QPushButton *m_refresh;
    QPushButton *m_save;
    QToolButton *m_actions;
    QToolButton *m_profiles;
    QLabel *m_notice;
    QString m_saved;       // the last profile saved, said until the next action
    int m_editsAtSave = 0; // the edits and refusal shown when it was saved: a change is an action
    bool m_refusedAtSave = false;
    QScrollArea *m_scroll;
    QWidget *m_form = nullptr;
    QVBoxLayout *m_groups = nullptr;
    DeferredRefresh *m_buttonsRefresh = nullptr; // in m_form
    QList<ParameterEditor *> m_editors;
};

} // namespace tipscope::gui
