#include "preferencesdialog.h"

#include "journal/journalsettings.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>

namespace tipscope::gui {

using namespace tipscope::model;

// Counters change slowly and are polled every minute or so: that interval reads in seconds
// ("60 s"), and is stored in milliseconds as before.
static int wholeSeconds(int ms) {
    return qMax(1, (ms + 500) / 1000);
}

static QSpinBox *spin(QWidget *parent, int lo, int hi, int value, const QString &suffix) {
    auto *s = new QSpinBox(parent);
    s->setRange(lo, hi);
    s->setValue(value);
    s->setSuffix(suffix);
    return s;
}

PreferencesDialog::PreferencesDialog(const AppSettings &settings, int journalRetentionDays,
                                     QWidget *parent)
    : QDialog(parent)
    , m_base(settings) {
    setWindowTitle(tr("Preferences"));
    m_unit = new QComboBox(this);
    m_unit->addItem(tr("Celsius (°C)"), int(TemperatureUnit::Celsius));
    m_unit->addItem(tr("Fahrenheit (°F)"), int(TemperatureUnit::Fahrenheit));
    m_unit->setCurrentIndex(m_unit->findData(int(settings.unit)));
    m_live = spin(this, 50, 60000, settings.liveMs, tr(" ms"));
    m_status = spin(this, 100, 600000, settings.statusMs, tr(" ms"));
    m_counters = spin(this, 1, 3600, wholeSeconds(settings.counterMs), tr(" s"));
    m_turnaround = spin(this, 5, 10000, settings.turnaroundMs, tr(" ms"));
    m_retries = spin(this, 0, 10, settings.retries, QString());
    m_fullRate = spin(this, 10, 24 * 60, settings.fullRateMinutes, tr(" min"));
    m_history = spin(this, 1, 7 * 24, settings.historyHours, tr(" h"));
    m_language = new QComboBox(this);
    m_language->addItem(tr("Follow the system"), QStringLiteral("system"));
    m_language->addItem(QStringLiteral("English"), QStringLiteral("en"));
    m_language->addItem(QStringLiteral("Español"), QStringLiteral("es"));
    m_language->addItem(QStringLiteral("Deutsch"), QStringLiteral("de"));
    m_language->setCurrentIndex(qMax(0, m_language->findData(settings.language)));
    m_retention = spin(this, 0, journal::kMaxRetentionDays, journalRetentionDays, tr(" days"));
    m_retention->setSpecialValueText(tr("Keep everything"));
    m_retention->setToolTip(
        tr("Joints and events older than this are deleted from the journal, a little at a time "
           "so polling never waits. Every TipScope program that keeps this journal uses the "
           "same retention."));
    auto *form = new QFormLayout(this);
    form->addRow(tr("Temperature unit:"), m_unit);
    form->addRow(tr("Live values (visible ports) every:"), m_live);
    form->addRow(tr("Errors, alarms and status every:"), m_status);
    form->addRow(tr("Counters every:"), m_counters);
    form->addRow(tr("Device turnaround (added to the wire time):"), m_turnaround);
    form->addRow(tr("Retries after a lost or corrupted answer:"), m_retries);
    form->addRow(tr("Chart history at full rate:"), m_fullRate);
    form->addRow(tr("Chart history in all:"), m_history);
    form->addRow(tr("Language (on the next start):"), m_language);
    form->addRow(tr("Keep journal records for:"), m_retention);
    auto *note =
        new QLabel(tr("The wire always carries °C; the unit only changes what you see and type. "
                      "The colours follow the desktop theme. Chart history older than the "
                      "full-rate part keeps min, max and mean per 5 s (about 1.4 MB a port for "
                      "a day); it applies to devices found from then on."),
                   this);
    note->setWordWrap(true);
    form->addRow(note);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

AppSettings PreferencesDialog::result() const {
    AppSettings a = m_base;
    a.unit = TemperatureUnit(m_unit->currentData().toInt());
    a.liveMs = m_live->value();
    a.statusMs = m_status->value();
    // A stored value that is not whole seconds stays as it is unless the field was changed.
    if (m_counters->value() != wholeSeconds(m_base.counterMs))
        a.counterMs = m_counters->value() * 1000;
    a.turnaroundMs = m_turnaround->value();
    a.retries = m_retries->value();
    a.fullRateMinutes = m_fullRate->value();
    a.historyHours = m_history->value();
    a.language = m_language->currentData().toString();
    return a;
}

int PreferencesDialog::journalRetentionDays() const {
    return m_retention->value();
}

} // namespace tipscope::gui
