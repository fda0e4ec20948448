// How an event that repeated reads for people: the first text, then how often and until when
// ("not sent: the line is not connected (75 times, until 10:02:13)"). The event history table and
// the support report both say it so, in one translatable wording.
#pragma once

#include <QString>

namespace tipscope::model {

// `text` unchanged when the event happened once (count 1 or less); otherwise `text` followed by
// the count and `lastTime`, already written in the form the caller shows times in.
[[nodiscard]] QString repeatedEventText(const QString &text, int count, const QString &lastTime);

// A state or error text written to follow a colon ("cannot connect to tcp …: Connection
// refused"), capitalised where it stands alone.
[[nodiscard]] QString asSentence(QString text);

} // namespace tipscope::model
