// FeederPage: the SFR solder feeder: feeding settings (mode, speed, length, wire thickness,
// switch input) with Apply / Revert / save to memory; start forward or backward, stop, and
// loading; the live feeding status and fed length; the error code with its explanation and reset;
// and the total and partial counters with their (confirmed) partial resets. As on the Settings
// page, Apply is on only with something to write and nothing refused, and Revert discards what
// was typed, refused or not.
#pragma once

#include "page.h"

class QLabel;
class QPushButton;
class QGridLayout;
class QVBoxLayout;

namespace tipscope::gui {

class ParameterEditor;

class FeederPage : public Page {
    Q_OBJECT
public:
    explicit FeederPage(model::Session &session, QWidget *parent = nullptr);

    [[nodiscard]] QString title() const override { return tr("Feeder"); }
    [[nodiscard]] bool appliesTo(const model::DeviceModel *device) const override;
    void setSelection(model::DeviceModel *device, int port) override;

    // The buttons' actions, for keyboard users and tests; each returns an error or empty.
    QString start(bool forward);
    QString stop();
    QString setLoading(bool on);
    QString resetError();
    QString resetCounter(const QByteArray &code, bool confirmed);
    void applyEdits();
    // Discards what was typed, refused or not, and shows the feeder's values again.
    void revertEdits();
    // The settings' buttons, for tests: "apply" or "revert".
    [[nodiscard]] QPushButton *button(const QString &name) const;
    [[nodiscard]] ParameterEditor *editorFor(const QByteArray &code) const;
    [[nodiscard]] QString liveText() const;

private:
    void rebuild();
    void refreshLive();
    void updateEnabled();
    void report(const QString &error);
    [[nodiscard]] model::FeederModel *feeder() const;

    QWidget *m_body = nullptr;
    QVBoxLayout *m_layout;
    QLabel *m_live = nullptr;
    QLabel *m_error = nullptr;
    QLabel *m_feedback = nullptr;
    QList<ParameterEditor *> m_editors;
    QList<QPushButton *> m_writeButtons; // off in monitor-only mode
    QPushButton *m_apply = nullptr;      // on with an edit and no refusal
    QPushButton *m_revert = nullptr;     // on with an edit or a refusal
};

} // namespace tipscope::gui
