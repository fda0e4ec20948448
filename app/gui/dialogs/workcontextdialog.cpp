#include "workcontextdialog.h"

#include "model/context/workcontextjson.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

namespace tipscope::gui {

namespace {
QLineEdit *field(const QString &value, const QString &name, QWidget *parent) {
    auto *edit = new QLineEdit(value, parent);
    edit->setObjectName(name);
    edit->setMaxLength(model::kMaxWorkContextChars); // the bound every program reads it with
    edit->setClearButtonEnabled(true);
    edit->setMinimumWidth(260);
    return edit;
}
} // namespace

WorkContextDialog::WorkContextDialog(journal::WorkContextFollower &context, QWidget *parent)
    : QDialog(parent)
    , m_context(context) {
    setWindowTitle(tr("Work context"));
    const auto current = journal::readWorkContext(context.path());
    const model::WorkContext now = current ? current.value() : model::WorkContext{};
    m_workOrder = field(now.workOrder, QStringLiteral("workOrder"), this);
    m_serial = field(now.boardSerial, QStringLiteral("boardSerial"), this);
    m_operator = field(now.operatorName, QStringLiteral("operator"), this);
    m_problem = new QLabel(current ? QString() : current.error(), this);
    m_problem->setObjectName(QStringLiteral("problem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #c62828;"));
    auto *note = new QLabel(tr("Stamped on every joint and event from now on, by every TipScope "
                               "program on this computer, until it is changed."),
                            this);
    note->setWordWrap(true);
    auto *form = new QFormLayout(this);
    form->addRow(note);
    form->addRow(tr("Work order:"), m_workOrder);
    form->addRow(tr("Board serial:"), m_serial);
    form->addRow(tr("Operator:"), m_operator);
    form->addRow(m_problem);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    auto *clear = buttons->addButton(tr("Clear"), QDialogButtonBox::ResetRole);
    connect(clear, &QPushButton::clicked, this, [this] {
        for (QLineEdit *e : {m_workOrder, m_serial, m_operator})
            e->clear();
    });
    connect(buttons, &QDialogButtonBox::accepted, this, &WorkContextDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

void WorkContextDialog::accept() {
    const model::WorkContext context{m_workOrder->text().trimmed(), m_serial->text().trimmed(),
                                     m_operator->text().trimmed()};
    if (const auto saved = m_context.set(context); !saved) {
        m_problem->setText(saved.error());
        return;
    }
    QDialog::accept();
}

} // namespace tipscope::gui
