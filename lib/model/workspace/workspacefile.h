// WorkspaceFile: the lines TipScope opens at once, with the names people give them, kept in a
// versioned JSON file (docs/workspace.md describes every field, with an example):
//     {"format": "tipscope-workspace", "version": 1, "lines": [{"name": "cell-3", ...}]}
//
// Each line has a name (unique in the file, used as the prefix of everything said about the
// line), a cell and a location, its connection (a serial port with its frame format, a TCP serial
// server as host:port, or the built-in demo), its link timing, addressing, the names of its
// stations by address, its own joint limits (JointLimitRules' JSON; none: the shared limits) and
// its work context (the context file's JSON). load() refuses a file that is not a workspace, one
// of a later version (with the version it knows), duplicate line names, and any field of the
// wrong kind or out of range, naming the line and the field; save() replaces the file atomically.
// A file written by toJson() reads back equal.
#pragma once

#include "model/context/workcontext.h"
#include "model/joints/jointlimitrules.h"
#include "model/session.h"

#include "base/outcome.h"

#include <QJsonObject>
#include <QList>
#include <QMap>
#include <optional>

namespace tipscope::model {

struct WorkspaceLine {
    QString name;
    QString cell;
    QString location;
    Session::Settings session;
    // Station names by bus address; -1 names the device that answers without addresses.
    QMap<int, QString> deviceNames;
    std::optional<JointLimitRules> jointLimits; // none: the shared limits apply
    WorkContext context;                        // empty: the shared one applies

    // The line's own work context, when it has one.
    [[nodiscard]] std::optional<WorkContext> ownContext() const {
        return context.isEmpty() ? std::nullopt : std::optional<WorkContext>(context);
    }

    // The name given to the device at `address` (none: without addresses), or empty.
    [[nodiscard]] QString deviceName(std::optional<int> address) const {
        return deviceNames.value(address.value_or(-1));
    }
};

struct WorkspaceFile {
    static constexpr int kVersion = 1;

    QList<WorkspaceLine> lines;

    [[nodiscard]] const WorkspaceLine *line(const QString &name) const;
    [[nodiscard]] QJsonObject toJson() const;
    [[nodiscard]] static base::Outcome<WorkspaceFile> fromJson(const QJsonObject &json);
    [[nodiscard]] static base::Outcome<WorkspaceFile> load(const QString &path);
    [[nodiscard]] base::Outcome<void> save(const QString &path) const;
};

// One line of a workspace as JSON, and back (workspacelinejson.cpp). A failure names the field.
[[nodiscard]] QJsonObject workspaceLineToJson(const WorkspaceLine &line);
[[nodiscard]] base::Outcome<WorkspaceLine> workspaceLineFromJson(const QJsonObject &json);

} // namespace tipscope::model
