// AppSettings: what TipScope remembers between runs (QSettings), read with validation so that
// a value written by an older version, or edited by hand, falls back to its default instead of
// reaching the line: the last connection, line settings, units, poll rates, timeouts, language,
// and how much telemetry history is kept (TelemetryTiers: hours at full rate, hours in all).
#pragma once

#include "session.h"

#include "base/outcome.h"

#include <QByteArray>
#include <QString>

class QSettings;

namespace tipscope::model {

struct AppSettings {
    enum class Kind { Serial, Tcp, Demo };
    Kind kind = Kind::Demo;
    QString serialPort;
    QString tcpAddress = QStringLiteral("127.0.0.1:4001");
    int baud = 19200;
    QString parity = QStringLiteral("none");
    int stopBits = 1;
    Session::Addressing addressing = Session::Addressing::Auto;
    int robotAddress = 0;
    int targetAddress = 1;
    TemperatureUnit unit = TemperatureUnit::Celsius;
    int liveMs = 250;
    int statusMs = 2000;
    int counterMs = 60000;
    int turnaroundMs = 100;
    int retries = 2;
    QString language = QStringLiteral("system");
    int fullRateMinutes = int(TelemetryTiers::kDefaultFullRateMs / TelemetryTiers::kMinuteMs);
    int historyHours = int(TelemetryTiers::kDefaultHistoryMs / TelemetryTiers::kHourMs);

    [[nodiscard]] static AppSettings load(QSettings &s);
    void save(QSettings &s) const;
    // The tiers of the telemetry buffers made from now on; a history shorter than the full-rate
    // part is all at full rate.
    [[nodiscard]] TelemetryTiers telemetryTiers() const;
    // The session settings these describe, or why they cannot be used.
    [[nodiscard]] base::Outcome<Session::Settings> sessionSettings() const;
};

} // namespace tipscope::model
