// FrameBuilder: the raw console's "compose and send" panel.
//
// A person picks a device, a header (R or W), a command from the catalog of that device's family
// (or types any 3-character code) and a data field; the panel shows live the exact bytes that
// would go on the wire, BCC included, and what the catalog thinks of them. Because this is a raw
// console, catalog advice (value out of range, unknown command) never blocks sending; only what
// cannot be encoded at all is refused (a command that is not 3 characters, non-printable data).
// A second field takes any bytes as hex. Both go through the console's ConsoleSender, which owns
// the monitor-only gate: what it would refuse (W frames, bytes that are not one valid R frame)
// disables the button, and the panel says why next to it; the outcome of the last send is shown
// under the fields. The rules (which commands, addressing, the catalog's checks, reading hex)
// are model::FrameComposer's; the panel shows its choices.
#pragma once

#include "model/console/consolesender.h"
#include "model/console/framecomposer.h"

#include <QGroupBox>
#include <QList>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace tipscope::gui {

class FrameBuilder : public QGroupBox {
    Q_OBJECT
public:
    // Sends through `sender`, which must outlive the panel.
    explicit FrameBuilder(model::ConsoleSender &sender, QWidget *parent = nullptr);

    void setTargets(const QList<model::FrameTarget> &targets);
    [[nodiscard]] model::FrameDraft draft() const;

private:
    void buildLayout();
    void onGateChanged();
    void showOutcome(const QString &text, bool failed);
    void fillCommands();
    void onCommandPicked();
    void updateDraft();
    void updateRawHex();
    void sendFrame();
    void sendRaw();
    [[nodiscard]] protocol::Header header() const;

    QComboBox *m_device = nullptr;
    QComboBox *m_header = nullptr;
    QComboBox *m_command = nullptr;
    QLineEdit *m_data = nullptr;
    QPushButton *m_sendFrame = nullptr;
    QLabel *m_preview = nullptr;
    QLabel *m_hint = nullptr;
    QLineEdit *m_rawHex = nullptr;
    QPushButton *m_sendRaw = nullptr;
    QLabel *m_rawStatus = nullptr;
    QLabel *m_outcome = nullptr;
    model::ConsoleSender &m_sender;
    model::FrameComposer m_composer;
};

} // namespace tipscope::gui
