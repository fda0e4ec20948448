// DeviceModel: one device on a line, as the widgets see it: identity, every Parameter and Action
// its family has (built from the catalog), and the shared settings that shape them (temperature
// unit, monitor-only). StationModel and FeederModel add the structure of their families.
//
// Values and actions are found by what they are for (a catalog Role, per port) and lists by the
// catalog's Group, so nothing above the catalog spells a command code; the codes themselves are
// for the console, profiles and the CLI. The catalog is the built-in one unless another is given
// (tests add entries); it must outlive the model.
//
// Requests go through the line's RequestQueue with this model as the owner of every Reply, so
// deleting the model withdraws whatever it still had queued. Whoever owns the line (the Session)
// says whether it is up: while it is down every value is only what was last read (each
// Parameter's lastUpdate()), and pages show it as stale; when it is back, the failures the lost
// line caused are cleared (Parameter::lineRestored()). Communication failures of its
// requests and changes of errors, alarms and status are written to the EventLog if one is set.
#pragma once

#include "action.h"
#include "displayunits.h"
#include "model/events/eventlog.h"
#include "parameter.h"

#include "link/discovery.h"

#include <QMap>
#include <QObject>
#include <QPointer>
#include <vector>

namespace tipscope::model {

// A command's name with its tool and port when it has them ("Sleep delay, T245, port 1"), in
// `wording`; the tool's name comes from the family's tool table of `catalog`.
[[nodiscard]] QString qualifiedName(const protocol::Catalog &catalog,
                                    const protocol::ResolvedCommand &cmd,
                                    protocol::Wording wording = protocol::Wording::Translated);
// A tool's name from the family's tool table ("T245"), or "tool 9" for one it lacks.
[[nodiscard]] QString toolName(const protocol::Catalog &catalog, const QString &family, int tool,
                               protocol::Wording wording = protocol::Wording::Translated);

class DeviceModel : public QObject {
    Q_OBJECT
public:
    DeviceModel(link::RequestQueue &queue, const link::DeviceInfo &info, QObject *parent = nullptr);
    DeviceModel(link::RequestQueue &queue, const link::DeviceInfo &info,
                const protocol::Catalog &catalog, QObject *parent = nullptr);

    [[nodiscard]] const link::DeviceInfo &info() const { return m_info; }
    [[nodiscard]] QString family() const { return m_info.family; }
    [[nodiscard]] const protocol::FamilyInfo &familyInfo() const;
    [[nodiscard]] std::optional<int> address() const { return m_info.address; }
    [[nodiscard]] QString displayName() const; // "DME-2C at 01"
    // Which device this is: the line it is reached through, its address, model and software.
    // Histories (telemetry, events, measurements) are kept under it, never under the address.
    [[nodiscard]] DeviceIdentity identity() const;
    // The line's name in the identity (lineIdentityName()); set by whoever built the line.
    void setLineName(const QString &name) { m_lineName = name; }
    [[nodiscard]] link::RequestQueue &queue() const { return m_queue; }
    [[nodiscard]] const protocol::Catalog &catalog() const { return m_catalog; }

    [[nodiscard]] const QList<Parameter *> &parameters() const { return m_parameters; }
    [[nodiscard]] Parameter *parameter(const QByteArray &code) const;
    [[nodiscard]] const QList<Action *> &actions() const { return m_actions; }
    [[nodiscard]] Action *action(const QByteArray &code) const;

    // The value with this role on `port` (0: the device's own), or null when the family has none.
    [[nodiscard]] Parameter *parameter(protocol::Role role, int port = 0) const;
    [[nodiscard]] Action *action(protocol::Role role) const;
    // The value as last read, as a number: nullopt before the first reading, for a text, or
    // when the family has no such value.
    [[nodiscard]] std::optional<qint64> number(protocol::Role role, int port = 0) const;
    // What to check for the error the device (port 0) or a port last reported, from the
    // catalog's advice for its error table; empty while no error is known.
    [[nodiscard]] QString
    errorAdvice(int port = 0, protocol::Wording wording = protocol::Wording::Translated) const;
    // The value as people read it: "—" before the first reading or when the family has none.
    [[nodiscard]] QString displayText(protocol::Role role, int port = 0) const;
    // In catalog order: every parameter of the group, whatever its port or tool; or those of one
    // port (0: the device's own) and tool (-1: not a per-tool setting).
    [[nodiscard]] QList<Parameter *> parameters(protocol::Group group) const;
    [[nodiscard]] QList<Parameter *> parameters(protocol::Group group, int port,
                                                int tool = -1) const;
    // A tool's name from the family's tool table ("T245"), or "tool 9" for one it lacks.
    [[nodiscard]] QString toolName(int tool,
                                   protocol::Wording wording = protocol::Wording::Translated) const;
    // A parameter's name with its tool and port when it has them ("Sleep delay, T245, port 1"),
    // for wherever it appears out of its group (a profile, a report, a message).
    [[nodiscard]] QString
    qualifiedLabel(const Parameter &p,
                   protocol::Wording wording = protocol::Wording::Translated) const;
    // What a role's command is called, for messages about one the family lacks.
    [[nodiscard]] QString commandName(protocol::Role role) const;

    [[nodiscard]] TemperatureUnit temperatureUnit() const { return m_unit; }
    void setTemperatureUnit(TemperatureUnit unit);
    [[nodiscard]] bool writesBlocked() const { return m_writesBlocked; }
    void setWritesBlocked(bool blocked);
    // Whether the line to the device is open; true when the model was made on an open line.
    [[nodiscard]] bool isLineUp() const { return m_lineUp; }
    void setLineUp(bool up);
    // Why nothing can be written now (monitor-only, the line down), for the hint beside a
    // disabled button; empty when writes can go.
    [[nodiscard]] QString writesUnavailableReason() const;
    void setEventLog(EventLog *log) { m_log = log; }
    [[nodiscard]] EventLog *eventLog() const { return m_log; }

    // Reads every readable parameter once (settings pages, profiles, the support report).
    void refreshAll(link::Priority priority = link::Priority::Background);
    // Called by parameters and actions when a request of theirs failed or a write was done.
    // While the line is down every request fails alike, so the entry says the reason only and
    // a flood of them collapses into one (EventLog). A write names the port it was on (0: the
    // device's own), so that the history's Source column does.
    void logCommunication(const QString &what, const QString &reason);
    void logWrite(int port, const QString &what, const QJsonObject &details = {});
    // An event of this device (`port` 0: the device itself), with its identity and source name;
    // `ageMs`: how old the reading that showed it was (EventLog::append).
    void logEvent(Event::Kind kind, Event::Severity severity, int port, const QString &text,
                  const QJsonObject &details = {}, double ageMs = 0);

Q_SIGNALS:
    void temperatureUnitChanged();
    void writesBlockedChanged(bool blocked);
    void lineUpChanged(bool up);
    void parameterChanged(tipscope::model::Parameter *parameter);

protected:
    // Hook for subclasses: a parameter's value changed (errors, alarms, status to log).
    virtual void onParameterChanged(Parameter *) {}
    [[nodiscard]] QString sourceName(int port = 0) const;

private:
    void indexByRole();

    link::RequestQueue &m_queue;
    link::DeviceInfo m_info;
    const protocol::Catalog &m_catalog;
    QList<Parameter *> m_parameters;
    QMap<QByteArray, Parameter *> m_byCode;
    // [role][port], flat: every reading looks values up by role (the recorder, the tiles, the
    // scheduler), and a tree of pairs was a visible share of the fleet's CPU.
    std::vector<Parameter *> m_byRole;
    int m_rolePorts = 0;
    QList<Action *> m_actions;
    QMap<QByteArray, Action *> m_actionByCode;
    QMap<protocol::Role, Action *> m_actionByRole;
    TemperatureUnit m_unit = TemperatureUnit::Celsius;
    bool m_writesBlocked = false;
    bool m_lineUp = false;
    QString m_lineName;
    QPointer<EventLog> m_log;
};

} // namespace tipscope::model
