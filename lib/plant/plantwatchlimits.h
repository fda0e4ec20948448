// PlantWatchLimits: what one publisher on the plant's broker may declare to a watching window
// (PlantWatch), so that whatever the broker holds, the window keeps a bounded amount of it
// (docs/mqtt.md, "The plant view").
//
// An agent publishes a few hundred bytes a message, four ports a station, a few devices a line.
// A message beyond the bounds below (too large, a string or a list too long, too deep, a port
// number out of range) is refused whole before anything of it is kept; a device, line or site
// beyond the counts is not added. Each refusal is logged once per publisher (device root), line
// or site, however often it comes again.
#pragma once

#include <QByteArray>
#include <QJsonObject>
#include <QString>

namespace tipscope::plant {

struct PlantWatchLimits {
    static constexpr qsizetype kMaxMessageBytes = 16 * 1024; // info, status, alarms, counters
    static constexpr qsizetype kMaxJointBytes = 2 * 1024;    // each of the 200 kept
    static constexpr qsizetype kMaxLiveBytes = 1024 * 1024;  // a batch of live samples
    static constexpr int kMaxSamples = 6000;     // a 10-minute batch at 10 samples a second
    static constexpr int kMaxItems = 256;        // a list's items, an object's members
    static constexpr int kMaxSampleMembers = 32; // a live sample, the one a watcher keeps
    static constexpr int kMaxStringChars = 256;
    static constexpr int kMaxDepth = 8;
    static constexpr int kMaxPorts = 8;       // port numbers 1 to 8; the largest station has 4
    static constexpr int kMaxLevelChars = 64; // site, line and device in the topic
    static constexpr int kMaxDevicesPerLine = 64;
    static constexpr int kMaxLinesPerSite = 64;
    static constexpr int kMaxDevices = 256;
};

// Empty when a message on `leaf` (what follows the device's root) may be kept, and `json` is
// then its object; otherwise why not, without the message's content.
[[nodiscard]] QString watchedMessageProblem(const QString &leaf, const QByteArray &payload,
                                            QJsonObject *json);

} // namespace tipscope::plant
