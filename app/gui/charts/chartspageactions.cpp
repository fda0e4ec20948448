// ChartsPage's toolbar and continuous recording (exports: chartspageexport.cpp, replay:
// chartspagereplay.cpp).
#include "chartspage.h"

#include "chartwidget.h"
#include "model/analysis/measurementreport.h"
#include "model/recording/chartcsv.h"
#include "model/recording/chartcsvreader.h"
#include "model/recording/chartrecorder.h"
#include "widgets/elidedlabel.h"
#include "widgets/flowlayout.h"

#include "widgets/startfolder.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDateTime>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QToolButton>
#include <QVBoxLayout>

namespace tipscope::gui {

using namespace tipscope::model;

QString ChartsPage::softwareVersion() {
    const QString v = QCoreApplication::applicationVersion();
    return v.isEmpty() ? QStringLiteral("unknown") : v;
}

QString ChartsPage::suggestedPath(const QString &suffix) {
    const QString folder = startFolder();
    return folder + QStringLiteral("/tipscope-") +
           QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")) + suffix;
}

namespace {
// Marks the Window box's entry that shows a zoomed span rather than a preset.
constexpr int kZoomedSpan = 1;

QToolButton *toolButton(const QString &text, const QString &name, QWidget *parent) {
    auto *b = new QToolButton(parent);
    b->setText(text);
    b->setObjectName(name);
    b->setAccessibleName(QString(text).remove(QLatin1Char('&')).remove(QStringLiteral("…")));
    b->setToolButtonStyle(Qt::ToolButtonTextOnly);
    return b;
}
} // namespace

void ChartsPage::buildToolbar(QVBoxLayout *layout) {
    // The buttons wrap onto a second line rather than widen the window (German at 1280 px).
    auto *row = new FlowLayout;
    // The label and its combo stay on one line together.
    auto *windowPair = new QWidget(this);
    auto *pairLayout = new QHBoxLayout(windowPair);
    pairLayout->setContentsMargins(0, 0, 0, 0);
    auto *windowLabel = new QLabel(tr("&Window"), windowPair);
    m_window = new QComboBox(windowPair);
    pairLayout->addWidget(windowLabel);
    pairLayout->addWidget(m_window);
    m_window->setObjectName(QStringLiteral("windowCombo"));
    m_window->setAccessibleName(tr("Time window"));
    // A zoom adds its own length ("1 min 36 s"), longer than the lengths offered: sized once,
    // the box cut it to "1 min 3".
    m_window->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    windowLabel->setBuddy(m_window);
    const std::pair<QString, qint64> windows[] = {
        {tr("30 s"), 30'000},        {tr("1 min"), 60'000},        {tr("5 min"), 300'000},
        {tr("15 min"), 900'000},     {tr("1 h"), 3600'000},        {tr("4 h"), 4 * 3600'000},
        {tr("12 h"), 12 * 3600'000}, {tr("24 h"), 24 * 3600'000LL}};
    for (const auto &[text, ms] : windows)
        m_window->addItem(text, ms);
    m_window->setCurrentIndex(m_window->findData(ChartViewport::kDefaultWindowMs));
    connect(m_window, &QComboBox::activated, this,
            [this] { m_viewport.setWindowLength(m_window->currentData().toLongLong()); });

    m_follow = toolButton(tr("&Follow"), QStringLiteral("followButton"), this);
    m_follow->setCheckable(true);
    m_follow->setChecked(true);
    m_follow->setToolTip(tr("Keep the newest data at the right edge; uncheck to pause"));
    connect(m_follow, &QToolButton::clicked, &m_viewport, &ChartViewport::setFollowing);
    connect(&m_viewport, &ChartViewport::followingChanged, m_follow, &QToolButton::setChecked);
    auto *reset = toolButton(tr("&Reset view"), QStringLiteral("resetButton"), this);
    connect(reset, &QToolButton::clicked, this, &ChartsPage::resetView);
    m_layoutBox = new QComboBox(this);
    m_layoutBox->setObjectName(QStringLiteral("layoutCombo"));
    m_layoutBox->setAccessibleName(tr("Pane layout"));
    m_layoutBox->addItem(tr("Ports overlaid"));
    m_layoutBox->addItem(tr("One pane per port"));
    connect(m_layoutBox, &QComboBox::activated, this,
            [this](int i) { setPaneLayout(i == 0 ? Layout::Overlaid : Layout::PerPort); });

    m_hardware = toolButton(tr("Trans&istor, transformer"), QStringLiteral("hardwareButton"), this);
    m_hardware->setCheckable(true);
    m_hardware->setToolTip(tr("Also draw each port's transistor temperature and the station's "
                              "transformer temperature (read every few seconds)"));
    connect(m_hardware, &QToolButton::toggled, this, &ChartsPage::rebuildPanes);

    auto *exportButton = toolButton(tr("&Export"), QStringLiteral("exportButton"), this);
    exportButton->setPopupMode(QToolButton::InstantPopup);
    auto *exportMenu = new QMenu(exportButton);
    exportMenu->addAction(tr("Visible window as &PNG…"), this, [this] { chooseAndExport(true); });
    exportMenu->addAction(tr("Visible window as &CSV…"), this, [this] { chooseAndExport(false); });
    exportButton->setMenu(exportMenu);
    m_record = toolButton(tr("Re&cord…"), QStringLiteral("recordButton"), this);
    m_record->setCheckable(true);
    m_record->setToolTip(tr("Write every new sample and event to a CSV file until unchecked"));
    connect(m_record, &QToolButton::clicked, this, &ChartsPage::toggleRecording);
    auto *open = toolButton(tr("&Open recording…"), QStringLiteral("openButton"), this);
    connect(open, &QToolButton::clicked, this, &ChartsPage::chooseReplay);
    m_live = toolButton(tr("Back to &live"), QStringLiteral("liveButton"), this);
    m_live->setVisible(false);
    connect(m_live, &QToolButton::clicked, this, &ChartsPage::showLive);
    m_source = new ElidedLabel(this);
    m_source->setObjectName(QStringLiteral("sourceLabel"));
    m_source->setAccessibleName(tr("Data shown"));
    connect(m_recorder, &ChartRecorder::failed, this, [this](const QString &why) {
        updateSourceLabel();
        QMessageBox::warning(this, tr("Recording stopped"),
                             tr("Writing %1 failed: %2").arg(m_recorder->path(), why));
    });

    for (QWidget *w : {windowPair, static_cast<QWidget *>(m_follow), static_cast<QWidget *>(reset),
                       static_cast<QWidget *>(m_layoutBox), static_cast<QWidget *>(m_hardware),
                       static_cast<QWidget *>(exportButton), static_cast<QWidget *>(m_record),
                       static_cast<QWidget *>(open), static_cast<QWidget *>(m_live)})
        row->addWidget(w);
    row->addWidget(m_source);
    layout->addLayout(row);
    updateSourceLabel();
}

// The length in the Window box: a preset's name, or after a zoom the span itself ("2 min 14 s"),
// never a blank box or a stale "5 min".
void ChartsPage::showWindowLength() {
    const qint64 ms = m_viewport.targetWindowMs();
    if (const int zoomed = m_window->findData(kZoomedSpan, Qt::UserRole + 1); zoomed >= 0)
        m_window->removeItem(zoomed);
    int index = m_window->findData(ms);
    if (index < 0) {
        index = 0;
        while (index < m_window->count() && m_window->itemData(index).toLongLong() < ms)
            ++index;
        m_window->insertItem(index, durationText(ms), ms);
        m_window->setItemData(index, kZoomedSpan, Qt::UserRole + 1);
    }
    m_window->setCurrentIndex(index);
}

QString ChartsPage::sourceText() const {
    QString text = m_replay ? tr("Replay: %1 (%Ln row(s))", nullptr, int(m_replay->rows))
                                  .arg(QFileInfo(m_replayPath).fileName())
                            : tr("Live");
    // Whose history the curves are: another device at the same address has a history of its own.
    if (!m_replay) {
        QStringList devices;
        for (const ChartChannel &c : m_liveChannels)
            if (!c.device.isEmpty() && !devices.contains(c.device.description()))
                devices.append(c.device.description());
        if (!devices.isEmpty())
            text += QStringLiteral(": ") + devices.join(QStringLiteral("; "));
    }
    return text;
}

void ChartsPage::updateSourceLabel() {
    QString text = sourceText();
    if (m_recorder->isRecording())
        text += tr(" · recording to %1").arg(QFileInfo(m_recorder->path()).fileName());
    m_source->setFullText(text);
    m_live->setVisible(m_replay != nullptr);
    m_record->setChecked(m_recorder->isRecording());
}

QString ChartsPage::startRecording(const QString &path) {
    // Fresh channels: the tools and alarm limits the file's header names are today's.
    m_liveChannels = sessionChannels(m_session);
    const QString error =
        m_recorder->start(path, m_liveChannels, m_session.temperatureUnit(), softwareVersion());
    updateSourceLabel();
    return error;
}

void ChartsPage::stopRecording() {
    m_recorder->stop();
    updateSourceLabel();
}

bool ChartsPage::isRecording() const {
    return m_recorder->isRecording();
}

void ChartsPage::toggleRecording(bool on) {
    if (!on) {
        stopRecording();
        return;
    }
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Record to CSV file"),
                                     suggestedPath(QStringLiteral(".csv")), tr("CSV file (*.csv)"));
    const QString error = path.isEmpty() ? QString() : startRecording(path);
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Record"), tr("Cannot record: %1").arg(error));
    updateSourceLabel();
}

} // namespace tipscope::gui
