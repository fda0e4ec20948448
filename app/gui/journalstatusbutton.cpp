#include "journalstatusbutton.h"

#include "dialogs/workcontextdialog.h"

#include <QStringList>

namespace tipscope::gui {

QString workContextText(const model::WorkContext &context) {
    if (context.isEmpty())
        return JournalStatusButton::tr("No work order");
    QStringList parts;
    for (const QString &part : {context.workOrder, context.boardSerial, context.operatorName})
        if (!part.isEmpty())
            parts.append(part);
    return parts.join(QStringLiteral(" · "));
}

JournalStatusButton::JournalStatusButton(journal::Journal &journal,
                                         journal::WorkContextFollower &context, QWidget *parent)
    : QToolButton(parent)
    , m_journal(journal)
    , m_context(context) {
    setObjectName(QStringLiteral("journalStatus"));
    setAutoRaise(true);
    setAccessibleName(tr("Work context and journal"));
    connect(this, &QToolButton::clicked, this, [this] {
        WorkContextDialog dialog(m_context, window());
        dialog.exec();
    });
    connect(&m_journal, &journal::Journal::stateChanged, this, &JournalStatusButton::refresh);
    connect(&m_journal, &journal::Journal::recordsLost, this, &JournalStatusButton::refresh);
    connect(&m_context, &journal::WorkContextFollower::contextChanged, this, [this] {
        m_contextProblem.clear();
        refresh();
    });
    connect(&m_context, &journal::WorkContextFollower::unreadable, this,
            [this](const QString &why) {
                m_contextProblem = why;
                refresh();
            });
    refresh();
}

void JournalStatusButton::refresh() {
    const QString context = workContextText(m_journal.context());
    QStringList tip{tr("Stamped on every joint and event: %1. Click to change it.").arg(context),
                    tr("Journal: %1").arg(m_journal.path())};
    QString problem;
    if (m_journal.state() == journal::JournalState::Failed) {
        problem = tr("Journal not written");
        tip.append(m_journal.errorText());
        tip.append(
            tr("%1 records wait to be written; polling goes on.").arg(m_journal.pendingCount()));
    }
    if (m_journal.lostCount() > 0) {
        problem = tr("%1 records lost").arg(m_journal.lostCount());
        tip.append(m_journal.lossReason());
    }
    if (!m_contextProblem.isEmpty()) {
        problem = problem.isEmpty() ? tr("Work context unreadable") : problem;
        tip.append(m_contextProblem);
    }
    setText(problem.isEmpty() ? context : tr("%1 — %2").arg(context, problem));
    setToolTip(tip.join(QLatin1Char('\n')));
    setStyleSheet(problem.isEmpty() ? QString()
                                    : QStringLiteral("QToolButton { color: #c62828; }"));
}

} // namespace tipscope::gui
