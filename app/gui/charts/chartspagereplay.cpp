// ChartsPage's replay: a recording is read by a RecordingLoader on a thread of its own while the
// page stays live; a progress dialog with Cancel shows after a moment if the reading takes
// longer, and the recording replaces the live view only once it is read whole. showMoment()
// leaves a replay for the live charts at a given moment (a joint picked on the Joints page).
#include "chartspage.h"

#include "base/timetext.h"
#include "model/recording/chartcsvreader.h"
#include "model/recording/recordingloader.h"

#include "widgets/startfolder.h"

#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QProgressDialog>
#include <QTimer>
#include <algorithm>

namespace tipscope::gui {

using namespace tipscope::model;

namespace {
// A recording read sooner than this shows no dialog at all.
constexpr int kShowProgressAfterMs = 300;
constexpr int kProgressSteps = 1000;
} // namespace

void ChartsPage::openReplay(const QString &path) {
    cancelReplayLoad();
    connect(m_loader, &RecordingLoader::finished, this, &ChartsPage::onReplayLoaded,
            Qt::UniqueConnection);
    m_loader->start(path);
    QTimer::singleShot(kShowProgressAfterMs, this, [this, path] {
        if (m_loader->isRunning() && m_loader->path() == path)
            showReplayProgress();
    });
}

bool ChartsPage::isLoadingReplay() const {
    return m_loader->isRunning();
}

void ChartsPage::cancelReplayLoad() {
    m_loader->cancel();
}

void ChartsPage::showReplayProgress() {
    // A dialog per load, so nothing of the last one (its cancel, its auto-show) carries over.
    if (!m_loadProgress) {
        m_loadProgress = new QProgressDialog(this);
        m_loadProgress->setObjectName(QStringLiteral("replayProgress"));
        m_loadProgress->setWindowTitle(tr("Open recording"));
        m_loadProgress->setWindowModality(Qt::WindowModal);
        m_loadProgress->setMinimumDuration(0);
        m_loadProgress->setAutoReset(false);
        m_loadProgress->setAutoClose(false);
        connect(m_loadProgress, &QProgressDialog::canceled, this, &ChartsPage::cancelReplayLoad);
        connect(m_loader, &RecordingLoader::progress, m_loadProgress,
                [this](qint64 read, qint64 total) {
                    const QString name = QFileInfo(m_loader->path()).fileName();
                    m_loadProgress->setLabelText(
                        tr("Reading %1: %2 MB").arg(name).arg(double(read) / (1 << 20), 0, 'f', 1));
                    // A FIFO has no size: the bar then only says that something happens.
                    m_loadProgress->setMaximum(total > 0 ? kProgressSteps : 0);
                    if (total > 0)
                        m_loadProgress->setValue(int(read * kProgressSteps / total));
                });
    }
    m_loadProgress->setLabelText(tr("Reading %1…").arg(QFileInfo(m_loader->path()).fileName()));
    m_loadProgress->setRange(0, m_loader->totalBytes() > 0 ? kProgressSteps : 0);
    m_loadProgress->setValue(0);
    m_loadProgress->show();
}

void ChartsPage::onReplayLoaded(const QString &error) {
    if (m_loadProgress) {
        m_loadProgress->hide();
        m_loadProgress->deleteLater();
        m_loadProgress = nullptr;
    }
    auto recording = m_loader->takeRecording();
    if (!recording) {
        Q_EMIT replayOpened(error);
        return;
    }
    m_replay = std::move(recording);
    m_replayPath = m_loader->path();
    rebuildPanes();
    m_viewport.setDataRange(m_replay->firstMs, m_replay->lastMs);
    resetView();
    updateSourceLabel();
    scheduleRedraw();
    Q_EMIT replayOpened(QString());
}

void ChartsPage::showLive() {
    m_replay.reset();
    m_replayPath.clear();
    rebuildPanes();
    onSamplesAdded();
    m_viewport.reset();
    updateSourceLabel();
}

QString ChartsPage::showMoment(const DeviceIdentity &device, qint64 fromMs, qint64 toMs) {
    if (isReplay())
        showLive();
    onSamplesAdded();
    const bool covered =
        std::any_of(m_liveChannels.cbegin(), m_liveChannels.cend(), [&](const ChartChannel &c) {
            const TelemetryBuffer *b = m_session.telemetry().buffer(c.key);
            return c.device == device && b && !b->isEmpty() && b->firstTime() <= toMs &&
                   b->lastTime() >= fromMs;
        });
    if (!covered)
        return tr("The charts hold no readings of %1 at %2: only this session's readings are kept.")
            .arg(device.description(), base::clockText(QDateTime::fromMSecsSinceEpoch(fromMs)));
    // Enough either side to see the tip before the joint and its recovery after it.
    constexpr qint64 kAroundMs = 10'000;
    m_viewport.showRange(fromMs - kAroundMs, toMs + kAroundMs);
    return {};
}

void ChartsPage::chooseReplay() {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open a chart recording"), startFolder(), tr("CSV file (*.csv);;All files (*)"));
    if (path.isEmpty())
        return;
    connect(
        this, &ChartsPage::replayOpened, this,
        [this](const QString &error) {
            if (!error.isEmpty() && !m_loader->wasCancelled())
                QMessageBox::warning(this, tr("Replay"), tr("Cannot replay %1").arg(error));
        },
        Qt::SingleShotConnection);
    openReplay(path);
}

} // namespace tipscope::gui
