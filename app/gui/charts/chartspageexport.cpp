// ChartsPage's exports of the visible window: a PNG drawn afresh at a chosen size, and the
// samples as CSV. Both go through the one atomic save, so a failed export never leaves half a
// file where a good one was.
#include "chartspage.h"

#include "base/atomicsave.h"
#include "chartwidget.h"
#include "model/recording/chartcsv.h"

#include <QBuffer>
#include <QDateTime>
#include <QFileDialog>
#include <QGuiApplication>
#include <QInputDialog>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QScreen>
#include <QTimeZone>
#include <QVBoxLayout>

namespace tipscope::gui {

using namespace tipscope::model;

namespace {
const QSize kMinimumPng(1920, 1080);
constexpr int kMaxLayoutRounds = 8;

QString offsetText(const QDateTime &time) {
    const int minutes = time.offsetFromUtc() / 60;
    return QStringLiteral("UTC%1%2:%3")
        .arg(minutes < 0 ? QLatin1Char('-') : QLatin1Char('+'))
        .arg(std::abs(minutes) / 60, 2, 10, QLatin1Char('0'))
        .arg(std::abs(minutes) % 60, 2, 10, QLatin1Char('0'));
}
} // namespace

QSize ChartsPage::defaultPngSize() const {
    return kMinimumPng.expandedTo(m_panesHost->size() * 2);
}

// "2026-12-02 05:10:30 – 05:15:00 (UTC+01:00)", the date again at the end when it differs.
QString ChartsPage::rangeText() const {
    const QDateTime from = QDateTime::fromMSecsSinceEpoch(m_viewport.start());
    const QDateTime to = QDateTime::fromMSecsSinceEpoch(m_viewport.end());
    const QString dateTime = QStringLiteral("yyyy-MM-dd HH:mm:ss");
    return tr("%1 – %2 (%3)")
        .arg(from.toString(dateTime),
             to.toString(from.date() == to.date() ? QStringLiteral("HH:mm:ss") : dateTime),
             offsetText(from));
}

QString ChartsPage::exportPng(const QString &path, QSize size) {
    redrawNow();
    if (m_panes.isEmpty())
        return tr("there is no chart to export");
    if (!size.isValid())
        size = defaultPngSize();
    // The panes are drawn again at the image's size, as charts of their own: a grab of the
    // screen would be as small as the window and cut the axis titles of short panes.
    QWidget sheet;
    sheet.setAttribute(Qt::WA_DontShowOnScreen);
    sheet.setAutoFillBackground(true);
    QPalette palette = sheet.palette();
    palette.setColor(QPalette::Window, Qt::white);
    sheet.setPalette(palette);
    auto *layout = new QVBoxLayout(&sheet);
    auto *heading = new QLabel(
        QStringLiteral("<b>%1</b><br>%2").arg(sourceText().toHtmlEscaped(), rangeText()), &sheet);
    layout->addWidget(heading);
    QList<Pane> panes = m_panes;
    QList<ChartWidget *> charts;
    for (Pane &pane : panes) {
        pane.widget = createPaneWidget(pane, true, &sheet);
        const bool feeder = shownChannels().at(pane.channels.first()).isFeeder();
        layout->addWidget(pane.widget, feeder ? kFeederStretch : kStationStretch);
        charts.append(pane.widget);
    }
    // Laid out at about the size the panes have on screen and drawn at the pixels asked for, so
    // the image reads like the screen, only sharper, rather than small print on a wide sheet.
    const QSize screen = m_panesHost->size();
    const double ratio = qMax(1.0, qMin(double(size.width()) / qMax(1, screen.width()),
                                        double(size.height()) / qMax(1, screen.height())));
    sheet.resize((QSizeF(size) / ratio).toSize());
    sheet.show();
    // Qt Charts lays its charts out in posted events, and the data's labels change the room the
    // axes take: draw and align until the plots stand still (a few rounds).
    const auto plotEdges = [&charts] {
        QList<QRectF> edges;
        for (const ChartWidget *c : std::as_const(charts))
            edges.append(c->plotArea());
        return edges;
    };
    QList<QRectF> before;
    for (int round = 0; round < kMaxLayoutRounds && plotEdges() != before; ++round) {
        before = plotEdges();
        for (Pane &pane : panes)
            drawPane(pane);
        QCoreApplication::processEvents();
        alignPlots(charts);
        QCoreApplication::processEvents();
    }
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(ratio);
    image.fill(Qt::white);
    sheet.render(&image);
    QByteArray png;
    QBuffer buffer(&png);
    if (!buffer.open(QIODevice::WriteOnly) || !image.save(&buffer, "PNG"))
        return tr("the image could not be encoded");
    const auto saved = base::io::saveAtomically(path, png);
    return saved.ok() ? QString() : saved.error();
}

QString ChartsPage::exportCsv(const QString &path) {
    if (!m_replay) // the header names today's tools and alarm limits
        m_liveChannels = sessionChannels(m_session);
    const auto saved = base::io::saveAtomically(path, [this](QIODevice &file) {
        ChartCsvWriter writer(file, shownChannels(), m_session.temperatureUnit());
        return writer.writeHeader(softwareVersion()) &&
               writer.writeWindow(shownTelemetry(), events(), m_viewport.start(), m_viewport.end());
    });
    return saved.ok() ? QString() : saved.error();
}

std::optional<QSize> ChartsPage::choosePngSize() {
    const QSize twice = m_panesHost->size() * 2;
    QList<QSize> sizes = {kMinimumPng, QSize(2560, 1440), QSize(3840, 2160)};
    if (!sizes.contains(twice) && twice.width() > kMinimumPng.width())
        sizes.append(twice);
    QStringList names;
    for (const QSize &s : std::as_const(sizes))
        names.append(s == twice
                         ? tr("%1 × %2 (twice the charts on screen)").arg(s.width()).arg(s.height())
                         : tr("%1 × %2").arg(s.width()).arg(s.height()));
    bool ok = false;
    const QString chosen = QInputDialog::getItem(
        this, tr("Export chart as PNG"), tr("Image size in pixels:"), names,
        int(sizes.indexOf(defaultPngSize()) < 0 ? 0 : sizes.indexOf(defaultPngSize())), false, &ok);
    if (!ok)
        return std::nullopt;
    return sizes.value(names.indexOf(chosen));
}

void ChartsPage::chooseAndExport(bool png) {
    std::optional<QSize> size;
    if (png && !(size = choosePngSize()))
        return;
    const QString path = QFileDialog::getSaveFileName(
        this, png ? tr("Export chart as PNG") : tr("Export chart data as CSV"),
        suggestedPath(png ? QStringLiteral(".png") : QStringLiteral(".csv")),
        png ? tr("PNG image (*.png)") : tr("CSV file (*.csv)"));
    if (path.isEmpty())
        return;
    // Read before the export: the older tier keeps folding while the file is written.
    const std::optional<qint64> fullRate =
        png ? std::nullopt
            : ChartCsvWriter::fullRateFrom(shownTelemetry(), shownChannels(), m_viewport.start());
    const QString error = png ? exportPng(path, *size) : exportCsv(path);
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Export"), tr("Export failed: %1").arg(error));
    else if (fullRate)
        QMessageBox::information(
            this, tr("Export"),
            tr("The file holds every sample from %1 on. The chart's older history is kept only "
               "as min and max per few seconds, which a file of samples cannot hold.")
                .arg(QLocale().toString(QDateTime::fromMSecsSinceEpoch(*fullRate),
                                        QLocale::ShortFormat)));
}

} // namespace tipscope::gui
