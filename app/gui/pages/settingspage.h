// SettingsPage: every setting of the selected device, generated from the parameters'
// metadata and grouped (station, port, alarms, each tool with the connected one first, ALE
// dispensing, feeder), with Apply / Revert, save to station memory, the dangerous actions behind
// confirmations that say what will happen, and profiles (save, compare, dry run, apply).
#pragma once

#include "page.h"

class QComboBox;
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
    [[nodiscard]] ParameterEditor *editorFor(const QByteArray &code) const;
    [[nodiscard]] int editedCount() const;

private:
    void rebuild();
    void addGroup(const QString &title, const QList<model::Parameter *> &params);
    void updateButtons();
    void saveToMemory();
    void runDangerous(const QByteArray &code);
    void saveProfile();
    void openProfile();
    [[nodiscard]] QList<model::Parameter *> shownParameters() const;

    QComboBox *m_portBox;
    QPushButton *m_apply;
    QPushButton *m_revert;
    QPushButton *m_refresh;
    QPushButton *m_save;
    QToolButton *m_actions;
    QToolButton *m_profiles;
    QScrollArea *m_scroll;
    QWidget *m_form = nullptr;
    QVBoxLayout *m_groups = nullptr;
    DeferredRefresh *m_buttonsRefresh = nullptr; // in m_form
    QList<ParameterEditor *> m_editors;
};

} // namespace tipscope::gui
