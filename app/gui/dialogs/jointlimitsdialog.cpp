#include "jointlimitsdialog.h"

#include "model/joints/jointlimitsfile.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace tipscope::gui {

using namespace tipscope::model;

namespace {
enum Column { kPort, kTool, kRecovery, kDip, kWear, kColumns };
constexpr int kMaxPorts = 4;

QString cellText(const QTableWidget *table, int row, int column) {
    const QTableWidgetItem *item = table->item(row, column);
    return item ? item->text().trimmed() : QString();
}

// A number as people type it here (this locale's decimal mark), in the C locale for parseRule.
QString cNumber(const QString &typed) {
    bool ok = false;
    const double v = QLocale().toDouble(typed, &ok);
    return ok ? QString::number(v, 'g', 10) : typed;
}
} // namespace

JointLimitsDialog::JointLimitsDialog(const JointLimitRules &rules, const QString &path,
                                     QWidget *parent)
    : QDialog(parent)
    , m_path(path) {
    setWindowTitle(tr("Joint limits"));
    const JointLimits &d = rules.defaults();
    m_recovery = new QDoubleSpinBox(this);
    m_recovery->setObjectName(QStringLiteral("defaultRecovery"));
    m_recovery->setRange(0.1, 600);
    m_recovery->setDecimals(1);
    m_recovery->setSuffix(tr(" s"));
    m_recovery->setValue(double(d.maxRecoveryMs) / 1000);
    m_dip = new QSpinBox(this);
    m_dip->setObjectName(QStringLiteral("defaultDip"));
    m_dip->setRange(1, 500);
    m_dip->setSuffix(tr(" K"));
    m_dip->setValue(d.maxDipK);
    m_wear = new QSpinBox(this);
    m_wear->setObjectName(QStringLiteral("defaultWear"));
    m_wear->setRange(1, 1000);
    m_wear->setSuffix(tr(" %"));
    m_wear->setValue(qRound(d.wearShare * 100));

    m_rules = new QTableWidget(0, kColumns, this);
    m_rules->setObjectName(QStringLiteral("rules"));
    m_rules->setHorizontalHeaderLabels({tr("Port"), tr("Tool"), tr("Longest recovery (s)"),
                                        tr("Deepest dip (K)"), tr("Tip wear (%)")});
    m_rules->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_rules->horizontalHeader()->setStretchLastSection(true);
    m_rules->verticalHeader()->hide();

    auto *add = new QPushButton(tr("Add rule"), this);
    auto *remove = new QPushButton(tr("Remove rule"), this);
    connect(add, &QPushButton::clicked, this, [this] { addRule({}); });
    connect(remove, &QPushButton::clicked, this, [this] {
        m_rules->removeRow(m_rules->currentRow());
        check();
    });
    m_problem = new QLabel(this);
    m_problem->setObjectName(QStringLiteral("problem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #c62828;"));

    auto *form = new QFormLayout;
    form->addRow(tr("Longest recovery (back within 5 K of the setpoint):"), m_recovery);
    form->addRow(tr("Deepest dip below the setpoint:"), m_dip);
    form->addRow(tr("Tip wearing when recoveries are slower than when new by:"), m_wear);
    auto *note = new QLabel(tr("Rules for a port, a tool or both override these; the most "
                               "specific rule wins. An empty cell keeps the default."),
                            this);
    note->setWordWrap(true);
    auto *ruleButtons = new QHBoxLayout;
    ruleButtons->addWidget(add);
    ruleButtons->addWidget(remove);
    ruleButtons->addStretch();
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_ok = buttons->button(QDialogButtonBox::Ok);
    connect(buttons, &QDialogButtonBox::accepted, this, &JointLimitsDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(note);
    layout->addWidget(m_rules, 1);
    layout->addLayout(ruleButtons);
    layout->addWidget(m_problem);
    layout->addWidget(buttons);
    for (const JointLimitRule &rule : rules.rules())
        addRule(rule);
    connect(m_rules, &QTableWidget::itemChanged, this, &JointLimitsDialog::check);
    resize(720, 460);
    check();
}

void JointLimitsDialog::addRule(const JointLimitRule &rule) {
    const QSignalBlocker block(m_rules);
    const int row = m_rules->rowCount();
    m_rules->insertRow(row);
    auto *port = new QComboBox(m_rules);
    port->addItem(tr("Any port"));
    for (int p = 1; p <= kMaxPorts; ++p)
        port->addItem(tr("Port %1").arg(p), p);
    port->setCurrentIndex(rule.port ? *rule.port : 0);
    connect(port, &QComboBox::currentIndexChanged, this, &JointLimitsDialog::check);
    m_rules->setCellWidget(row, kPort, port);
    const QLocale locale;
    const auto number = [&](auto value, double scale) {
        return value ? locale.toString(double(*value) / scale, 'g', 6) : QString();
    };
    m_rules->setItem(row, kTool, new QTableWidgetItem(rule.tool));
    m_rules->setItem(row, kRecovery, new QTableWidgetItem(number(rule.maxRecoveryMs, 1000)));
    m_rules->setItem(row, kDip, new QTableWidgetItem(number(rule.maxDipK, 1)));
    m_rules->setItem(
        row, kWear,
        new QTableWidgetItem(rule.wearShare ? locale.toString(*rule.wearShare * 100) : QString()));
    check();
}

base::Outcome<JointLimitRules> JointLimitsDialog::limits() const {
    JointLimits defaults;
    defaults.maxRecoveryMs = qRound64(m_recovery->value() * 1000);
    defaults.maxDipK = m_dip->value();
    defaults.wearShare = m_wear->value() / 100.0;
    JointLimitRules rules(defaults);
    for (int row = 0; row < m_rules->rowCount(); ++row) {
        QStringList parts;
        const auto *port = qobject_cast<QComboBox *>(m_rules->cellWidget(row, kPort));
        if (port && port->currentData().isValid())
            parts << QStringLiteral("port=%1").arg(port->currentData().toInt());
        if (const QString tool = cellText(m_rules, row, kTool); !tool.isEmpty())
            parts << QStringLiteral("tool=") + tool;
        if (const QString s = cellText(m_rules, row, kRecovery); !s.isEmpty())
            parts << QStringLiteral("recovery=") + cNumber(s);
        if (const QString k = cellText(m_rules, row, kDip); !k.isEmpty())
            parts << QStringLiteral("dip=") + cNumber(k);
        if (const QString w = cellText(m_rules, row, kWear); !w.isEmpty()) {
            bool ok = false;
            const double percent = QLocale().toDouble(w, &ok);
            parts << QStringLiteral("wear=") + (ok ? QString::number(percent / 100) : w);
        }
        const auto rule = JointLimitRules::parseRule(parts.join(QLatin1Char(',')));
        if (!rule)
            return base::failure(tr("Rule %1: %2").arg(row + 1).arg(rule.error()));
        rules.add(rule.value());
    }
    return rules;
}

void JointLimitsDialog::check() {
    const auto rules = limits();
    m_problem->setText(rules ? QString() : rules.error());
    m_ok->setEnabled(bool(rules));
}

void JointLimitsDialog::accept() {
    const auto rules = limits();
    if (!rules)
        return;
    if (const auto saved = saveJointLimits(m_path, rules.value()); !saved) {
        m_problem->setText(saved.error());
        return;
    }
    QDialog::accept();
}

} // namespace tipscope::gui
