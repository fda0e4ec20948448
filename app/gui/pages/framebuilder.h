// FrameBuilder: the raw console's "compose and send" panel.
//
// A person picks a device, a header (R or W), a command from the catalog of that device's family
// (or types any 3-character code) and a data field; the panel shows live the exact bytes that
// would go on the wire, BCC included, and what the catalog thinks of them. Because this is a raw
// console, catalog advice (value out of range, unknown command) never blocks sending; only what
// cannot be encoded at all is refused (a command that is not 3 characters, non-printable data).
// A second field takes any bytes as hex. In monitor-only mode writes and raw bytes (which may be
// writes) cannot be sent, and the disabled buttons say why in their tooltips.
//
// The panel does not talk to the line: it emits sendRequested() with the bytes, and its owner
// queues them and reports back through showOutcome(). The rules (which commands, addressing,
// the catalog's checks, reading hex) are model::FrameComposer's; the panel shows its choices.
#pragma once

#include "model/framecomposer.h"

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
    explicit FrameBuilder(QWidget *parent = nullptr);

    void setTargets(const QList<model::FrameTarget> &targets);
    void setRobotAddress(int address);
    void setMonitorOnly(bool on);
    // The result of the last send, as one line; `failed` shows it as an error.
    void showOutcome(const QString &text, bool failed);
    [[nodiscard]] model::FrameDraft draft() const;

Q_SIGNALS:
    // `write`: the bytes are (or may be) a write, so they belong to the writes' queue class.
    void sendRequested(const QByteArray &bytes, bool write);

private:
    void buildLayout();
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
    model::FrameComposer m_composer;
    bool m_monitorOnly = false;
};

} // namespace tipscope::gui
