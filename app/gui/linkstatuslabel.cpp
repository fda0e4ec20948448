#include "linkstatuslabel.h"

#include "protocol/catalog.h"

namespace tipscope::gui {

LinkStatusLabel::LinkStatusLabel(model::Session &session, QWidget *parent)
    : QLabel(parent)
    , m_session(&session) {
    setAccessibleName(tr("Line statistics"));
    connect(&m_timer, &QTimer::timeout, this, &LinkStatusLabel::refresh);
    m_timer.start(500);
    refresh();
}

void LinkStatusLabel::setSession(model::Session *session) {
    m_session = session;
    setVisible(session != nullptr);
    refresh();
}

void LinkStatusLabel::refresh() {
    if (!m_session)
        return;
    link::Line *line = m_session->line();
    if (!line) {
        setText(tr("no line"));
        setToolTip({});
        return;
    }
    const link::LinkStats &s = line->queue().stats();
    const qint64 now = line->queue().nowMs();
    setText(tr("%L1 tx/s · %L2 ms · %3 timeouts · %4 BCC errors · %5 NAKs")
                .arg(s.transactionsPerSecond(now), 0, 'f', 1)
                .arg(s.medianLatencyUs() / 1000.0, 0, 'f', 1)
                .arg(s.timeouts)
                .arg(s.corrupted)
                .arg(s.nakTotal()));
    QStringList tip{s.summary(now)};
    for (auto it = s.naks.begin(); it != s.naks.end(); ++it)
        tip.append(tr("NAK %1 × %2: %3")
                       .arg(it.key())
                       .arg(it.value())
                       .arg(protocol::Catalog::builtin().nakText(it.key(),
                                                                 protocol::Wording::Translated)));
    tip.append(tr("Reconnects: %1").arg(line->reconnects()));
    setToolTip(tip.join(QLatin1Char('\n')));
}

} // namespace tipscope::gui
