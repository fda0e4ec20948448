#include "profiledialog.h"

#include "model/device/devicemodel.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace tipscope::gui {

using namespace tipscope::model;

ProfileDialog::ProfileDialog(DeviceModel &device, const Profile &profile, QWidget *parent)
    : QDialog(parent)
    , m_device(device)
    , m_profile(profile) {
    setWindowTitle(tr("Profile for %1").arg(device.displayName()));
    resize(900, 600);
    m_summary = new QLabel(this);
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_table = new QTableWidget(0, 4, this);
    m_table->setHorizontalHeaderLabels(
        {tr("Setting"), tr("Device now"), tr("Profile"), tr("Note")});
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(3, QHeaderView::Stretch);
    m_table->setWordWrap(false);
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_report = new QPlainTextEdit(this);
    m_report->setReadOnly(true);
    m_report->setPlaceholderText(tr("The dry run's frames and the apply report appear here."));
    m_progress = new QProgressBar(this);
    m_progress->setVisible(false);
    m_force =
        new QCheckBox(tr("Apply anyway: the profile is for a %1, this is a %2 (only the settings "
                         "both have are written)")
                          .arg(profile.family, device.family()),
                      this);
    m_force->setVisible(profile.family != device.family());
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    m_compare = buttons->addButton(tr("Compare again"), QDialogButtonBox::ActionRole);
    m_dryRun = buttons->addButton(tr("Dry run"), QDialogButtonBox::ActionRole);
    m_apply = buttons->addButton(tr("Apply to device"), QDialogButtonBox::AcceptRole);
    m_cancel = buttons->addButton(tr("Stop"), QDialogButtonBox::ActionRole);
    m_cancel->setEnabled(false);
    connect(m_compare, &QPushButton::clicked, this, [this] { run(ProfileApplier::Mode::Diff); });
    connect(m_force, &QCheckBox::toggled, this, [this] { run(ProfileApplier::Mode::Diff); });
    connect(m_dryRun, &QPushButton::clicked, this, [this] { run(ProfileApplier::Mode::DryRun); });
    connect(m_apply, &QPushButton::clicked, this, [this] { run(ProfileApplier::Mode::Apply); });
    connect(m_cancel, &QPushButton::clicked, this, [this] {
        if (m_applier)
            m_applier->cancel();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    layout->addWidget(m_table, 2);
    layout->addWidget(m_force);
    layout->addWidget(m_progress);
    layout->addWidget(m_report, 1);
    layout->addWidget(buttons);
    m_apply->setEnabled(!device.writesBlocked());
    if (device.writesBlocked())
        m_apply->setToolTip(tr("Monitor-only mode is on: nothing is written"));
    run(ProfileApplier::Mode::Diff);
}

void ProfileDialog::setForce(bool force) {
    m_force->setChecked(force);
}

void ProfileDialog::setBusy(bool busy) {
    m_progress->setVisible(busy);
    m_force->setEnabled(!busy);
    m_compare->setEnabled(!busy);
    m_dryRun->setEnabled(!busy);
    m_apply->setEnabled(!busy && !m_device.writesBlocked() && !m_conflicts && !m_greyed);
    m_cancel->setEnabled(busy);
}

void ProfileDialog::run(ProfileApplier::Mode mode) {
    if (m_applier)
        return;
    const bool force = m_force->isVisible() && m_force->isChecked();
    m_applier = new ProfileApplier(m_device, m_profile, mode, force, this);
    connect(m_applier, &ProfileApplier::progress, this,
            [this](int done, int total, const QString &what) {
                m_progress->setRange(0, total);
                m_progress->setValue(done);
                m_progress->setFormat(what + QStringLiteral(" %v/%m"));
            });
    connect(m_applier, &ProfileApplier::finished, this, &ProfileDialog::finished);
    setBusy(true);
    m_applier->start();
}

static QString asHtml(const QString &text) {
    return text.toHtmlEscaped().replace(QLatin1Char('\n'), QStringLiteral("<br>"));
}

void ProfileDialog::finished(const ApplyReport &report) {
    m_applier->deleteLater();
    m_applier = nullptr;
    m_conflicts = !report.conflicts.isEmpty();
    // Refused, the table is what the profile would do: greyed, but there to read.
    m_greyed = report.refused || m_conflicts;
    m_apply->setToolTip(m_conflicts ? tr("The profile would break the device's limits; see above")
                        : m_device.writesBlocked()
                            ? tr("Monitor-only mode is on: nothing is written")
                            : QString());
    setBusy(false);
    fillTable(report);
    m_summary->setText(summaryFor(report));
    if (!report.diffOnly || report.refused)
        m_report->setPlainText(report.text());
}

void ProfileDialog::addRow(const QStringList &cells, bool greyed) {
    const int row = m_table->rowCount();
    m_table->insertRow(row);
    for (int column = 0; column < cells.size(); ++column) {
        auto *item = new QTableWidgetItem(cells.at(column));
        item->setToolTip(cells.at(column));
        if (greyed)
            item->setForeground(m_table->palette().brush(QPalette::Disabled, QPalette::Text));
        m_table->setItem(row, column, item);
    }
}

void ProfileDialog::fillTable(const ApplyReport &report) {
    m_table->setRowCount(0);
    for (const ProfileDifference &d : report.differences) {
        const QString setting = QStringLiteral("%1 (%2)").arg(d.name, QString::fromLatin1(d.code));
        const auto done = std::find_if(report.written.begin(), report.written.end(),
                                       [&d](const ApplyItem &i) { return i.code == d.code; });
        if (done == report.written.end()) {
            addRow({setting, d.deviceText, d.profileText, QString()}, m_greyed);
            continue;
        }
        // Written: the device as it now is, proved by the read-back, and how it went.
        const Parameter *p = m_device.parameter(d.code);
        const QString now = done->after.isEmpty() && p ? p->displayText() : done->after;
        addRow({setting, now, d.profileText,
                done->ok ? tr("✓ changed from %1").arg(done->before)
                         : tr("✗ failed: %1").arg(done->reason)},
               false);
    }
    for (const SkippedSetting &s : report.skipped)
        addRow({QStringLiteral("%1 (%2)").arg(s.name, QString::fromLatin1(s.code)), tr("—"),
                tr("—"), tr("skipped: %1").arg(s.reason)},
               true);
}

QString ProfileDialog::summaryFor(const ApplyReport &report) const {
    QString skipped;
    if (!report.skipped.isEmpty())
        skipped = QLatin1Char(' ') +
                  tr("%n setting(s) of the profile skipped: this device does not take them.",
                     nullptr, int(report.skipped.size()));
    if (report.refused)
        return tr("<b>Refused, nothing was written:</b> %1").arg(asHtml(report.reason)) +
               asHtml(skipped) + QStringLiteral("<br>") +
               tr("The table shows what the profile would change.");
    if (m_conflicts)
        return tr("<b>This profile cannot be applied to this device:</b> %1")
                   .arg(asHtml(report.conflictReason())) +
               QStringLiteral("<br>") + tr("The table shows what the profile would change.");
    if (report.dryRun)
        return tr("Dry run: %n frame(s) would be sent; nothing was written.", nullptr,
                  int(report.frames.size())) +
               asHtml(skipped);
    if (!report.diffOnly)
        return (report.ok() ? tr("<b>Applied.</b> Every written value was read back and matches; "
                                 "the table shows the device as it now is.")
                            : tr("<b>Not everything was applied.</b> The table shows the device "
                                 "as it now is; see the report below.")) +
               asHtml(skipped);
    QString text = tr("Profile from %1 (%2, software %3), created %4: %n setting(s) differ "
                      "from the device.",
                      nullptr, int(report.differences.size()))
                       .arg(m_profile.model.toHtmlEscaped(), m_profile.family,
                            m_profile.softwareVersion.toHtmlEscaped(),
                            QLocale().toString(m_profile.created, QLocale::ShortFormat)) +
                   asHtml(skipped);
    if (!m_profile.comment.isEmpty())
        text += QStringLiteral("<br>") + tr("Comment: %1").arg(asHtml(m_profile.comment));
    return text;
}

QString ProfileDialog::reportText() const {
    return m_report->toPlainText();
}

QString ProfileDialog::summaryText() const {
    return m_summary->text();
}

bool ProfileDialog::canApply() const {
    return m_apply->isEnabled();
}

int ProfileDialog::differenceRows() const {
    return m_table->rowCount();
}

QString ProfileDialog::cellText(int row, int column) const {
    const QTableWidgetItem *item = m_table->item(row, column);
    return item ? item->text() : QString();
}

} // namespace tipscope::gui
