// DispensingPage: the ALE's built-in wire feed: mode, length, speed, wire diameter, backward
// length, clogging detection (Apply / Revert), start and stop dispensing, the dispensing status,
// dispensed length and cycles, and the fuse status with "ignore fuse error" behind a confirmation.
#pragma once

#include "page.h"

class QLabel;
class QPushButton;
class QVBoxLayout;

namespace tipscope::gui {

class ParameterEditor;

class DispensingPage : public Page {
    Q_OBJECT
public:
    explicit DispensingPage(model::Session &session, QWidget *parent = nullptr);

    [[nodiscard]] QString title() const override { return tr("Dispensing"); }
    [[nodiscard]] bool appliesTo(const model::DeviceModel *device) const override;
    QString startDispensing();
    QString stopDispensing();

private:
    void rebuild();
    void refreshLive();
    [[nodiscard]] model::StationModel *ale() const;

    QWidget *m_body = nullptr;
    QVBoxLayout *m_layout;
    QLabel *m_live = nullptr;
    QLabel *m_feedback = nullptr;
    QList<ParameterEditor *> m_editors;
    QList<QPushButton *> m_writeButtons;
};

} // namespace tipscope::gui
