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
// queues them and reports back through showOutcome(). composeFrame() holds the rules without any
// widget, so they can be tested and reused.
#pragma once

#include "protocol/frame.h"

#include <QGroupBox>
#include <QList>
#include <optional>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace tipscope::gui {

struct FrameInput {
    int source = 0;            // the robot's address, used when `target` is set
    std::optional<int> target; // unset: a frame without addresses
    QString family;            // catalog family of the target; empty when unknown
    protocol::Header header = protocol::Header::Read;
    QString command;
    QString data;
};

struct FrameDraft {
    protocol::Frame frame;
    bool encodable = false; // false: `problem` says why nothing can be sent
    QString problem;
    QString hint;         // catalog advice or the command's description
    bool warning = false; // the hint is a warning (out of range, unknown, dangerous)
};

[[nodiscard]] FrameDraft composeFrame(const FrameInput &input);

class FrameBuilder : public QGroupBox {
    Q_OBJECT
public:
    struct Target {
        QString label; // "01 DME-2C"
        std::optional<int> address;
        QString family;
    };

    explicit FrameBuilder(QWidget *parent = nullptr);

    void setTargets(const QList<Target> &targets);
    void setRobotAddress(int address);
    void setMonitorOnly(bool on);
    // The result of the last send, as one line; `failed` shows it as an error.
    void showOutcome(const QString &text, bool failed);
    [[nodiscard]] FrameDraft draft() const;

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
    [[nodiscard]] QString commandCode() const;
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
    QList<Target> m_targets;
    int m_robotAddress = 0;
    bool m_monitorOnly = false;
};

} // namespace tipscope::gui
