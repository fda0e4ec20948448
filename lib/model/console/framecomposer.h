// FrameComposer: how the raw console builds a frame from a person's choices, without a widget.
//
// A person names a device, a header (R or W), a command and a data field. The composer lists the
// commands the device's family has for that header (from the catalog), addresses the frame as
// the device needs it (from the robot's address to the device's, or no addresses on a line
// without them), and checks it against the catalog. Because this is a raw console, the
// catalog's advice (value out of range, unknown command, a dangerous write) never blocks
// sending: it is a hint with `warning` set. Only what cannot be encoded at all is refused, with
// the reason in `problem`: no device, a command that is not 3 printable characters, data that is
// not printable ASCII, an address outside 00-99. Raw hex is read by readHex(): the bytes, or the
// first bad character, and whether they form one valid frame. Every text is in the user
// interface language; the data field is never "corrected", the frame carries it as typed.
#pragma once

#include "protocol/frame.h"

#include <QList>
#include <QString>
#include <optional>

namespace tipscope::model {

class DeviceModel;

// A device the console can address.
struct FrameTarget {
    QString label; // "01 DME-2C", or "DME-2C (no address)"
    std::optional<int> address;
    QString family; // catalog family; empty when unknown

    [[nodiscard]] static FrameTarget of(const DeviceModel &device);
};

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

// One entry of the command list: the wire code and "ST1 — Selected temperature".
struct CommandChoice {
    QString code;
    QString label;
};

// Hex typed by a person, read.
struct RawHex {
    std::optional<QByteArray> bytes;      // unset: nothing can be sent, `text` says why
    std::optional<protocol::Frame> frame; // set when the bytes are one valid frame
    QString text;                         // what the bytes are, or what is wrong with the text
    bool warning = false;                 // bytes that are not a valid frame: sent as typed
};

class FrameComposer {
public:
    void setTargets(const QList<FrameTarget> &targets) { m_targets = targets; }
    [[nodiscard]] const QList<FrameTarget> &targets() const { return m_targets; }
    void setRobotAddress(int address) { m_robotAddress = address; }
    [[nodiscard]] int robotAddress() const { return m_robotAddress; }

    // The catalog's commands of the target's family for `header`, in catalog order.
    [[nodiscard]] QList<CommandChoice> commands(int target, protocol::Header header) const;
    // The command to start from when none is chosen: the identity read every device answers,
    // else the first of the list; empty when the list is.
    [[nodiscard]] QString firstCommand(int target, protocol::Header header) const;
    // The data field a command picked from the list takes by construction: none for a read, the
    // fixed data of an action. Unset: whatever was typed stays.
    [[nodiscard]] std::optional<QString> dataOfPicked(int target, protocol::Header header,
                                                      const QString &code) const;
    // The frame to `target` (an index into targets()), with the robot's address as the source.
    [[nodiscard]] FrameDraft compose(int target, protocol::Header header, const QString &command,
                                     const QString &data) const;

    [[nodiscard]] static FrameDraft compose(const FrameInput &input);
    // The code in a command as typed or picked: "ST1 — Selected temperature" is ST1.
    [[nodiscard]] static QString codeOf(const QString &typed);
    [[nodiscard]] static RawHex readHex(const QString &text);
    // An example for the raw hex field: the model-name read of the device at 01, BCC included.
    [[nodiscard]] static QString exampleHex();

private:
    [[nodiscard]] QString familyOf(int target) const;

    QList<FrameTarget> m_targets;
    int m_robotAddress = 0;
};

} // namespace tipscope::model
