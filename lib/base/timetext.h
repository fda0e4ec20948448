// Times as TipScope writes them for people and for files. A file another program or another
// time zone reads carries the UTC offset (isoTimeWithOffset), as the chart CSV's UTC times do; a
// table read on the spot gives the date only when it is not today (clockText).
#pragma once

#include <QDate>
#include <QDateTime>
#include <QString>

namespace tipscope::base {

// "2024-05-01T10:02:03.123+02:00": the local time with its offset; empty for an invalid time.
[[nodiscard]] QString isoTimeWithOffset(const QDateTime &time);
// "10:02:03" on `today`, "2024-04-30 10:02:03" on any other day.
[[nodiscard]] QString clockText(const QDateTime &time, const QDate &today = QDate::currentDate());
// "4.2": a duration in seconds with one decimal, in the user's locale (people read it).
[[nodiscard]] QString secondsText(qint64 ms);

} // namespace tipscope::base
