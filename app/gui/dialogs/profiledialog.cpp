#include "profiledialog.h"

#include "model/devicemodel.h"

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
    resize(760, 560);
    m_summary = new QLabel(this);
    m_summary->setWordWrap(true);
    m_table = new QTableWidget(0, 3, this);
    m_table->setHorizontalHeaderLabels({tr("Setting"), tr("Device now"), tr("Profile")});
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
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

void ProfileDialog::setBusy(bool busy) {
    m_progress->setVisible(busy);
    m_compare->setEnabled(!busy);
    m_dryRun->setEnabled(!busy);
    m_apply->setEnabled(!busy && !m_device.writesBlocked() && !m_conflicts);
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
    m_apply->setToolTip(m_conflicts ? tr("The profile would break the device's limits; see above")
                        : m_device.writesBlocked()
                            ? tr("Monitor-only mode is on: nothing is written")
                            : QString());
    setBusy(false);
    m_table->setRowCount(0);
    for (const ProfileDifference &d : report.differences) {
        const int row = m_table->rowCount();
        m_table->insertRow(row);
        m_table->setItem(row, 0,
                         new QTableWidgetItem(
                             QStringLiteral("%1 (%2)").arg(d.name, QString::fromLatin1(d.code))));
        m_table->setItem(row, 1, new QTableWidgetItem(d.deviceText));
        m_table->setItem(row, 2, new QTableWidgetItem(d.profileText));
    }
    if (report.refused)
        m_summary->setText(tr("<b>Refused:</b> %1").arg(asHtml(report.reason)));
    else if (m_conflicts)
        m_summary->setText(tr("<b>This profile cannot be applied to this device:</b> %1")
                               .arg(asHtml(report.conflictReason())));
    else if (report.diffOnly)
        m_summary->setText(tr("Profile from %1 (%2, software %3), created %4: %n setting(s) differ "
                              "from the device.",
                              nullptr, int(report.differences.size()))
                               .arg(m_profile.model, m_profile.family, m_profile.softwareVersion,
                                    QLocale().toString(m_profile.created, QLocale::ShortFormat)));
    else if (report.dryRun)
        m_summary->setText(tr("Dry run: %n frame(s) would be sent; nothing was written.", nullptr,
                              int(report.frames.size())));
    else
        m_summary->setText(
            report.ok() ? tr("<b>Applied.</b> Every written value was read back and matches.")
                        : tr("<b>Not everything was applied.</b> See the report below."));
    if (!report.diffOnly || report.refused)
        m_report->setPlainText(report.text());
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

} // namespace tipscope::gui
