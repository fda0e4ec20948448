// The charts page as people see it: in the real main window at 1280×720, in English, German and
// Spanish, on the demo line. Every pane puts the same instant at the same x, the temperature pane
// keeps at least 250 px, the readout has a fixed place that hovering never moves, the
// measurements fold away and keep their scroll position, and the first minutes fill the view.
#include "charts/chartspage.h"
#include "charts/chartwidget.h"
#include "charts/readoutpanel.h"
#include "i18n/translations.h"
#include "mainwindow.h"
#include "testmain.h"

#include <QComboBox>
#include <QMouseEvent>
#include <QPlainTextEdit>
#include <QScrollBar>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTest>
#include <QToolButton>
#include <QTranslator>

namespace tst_chartslayout {

using namespace tipscope;
using namespace tipscope::gui;
using namespace tipscope::model;

namespace {
constexpr int kConnectMs = 20000;
constexpr int kMinTemperaturePanePx = 250;

// Where `time` is drawn in `pane`, in the page's coordinates.
double pageX(ChartWidget *pane, QWidget *page, qint64 time) {
    const QWidget *surface = pane->plotSurface();
    return surface->mapTo(page, QPointF(pane->xAt(time), 0)).x();
}
} // namespace

class TestChartsLayout : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void cleanup();
    void at1280x720ThePanesShareOneTimeAxisAndThePlotsGetTheRoom_data();
    void at1280x720ThePanesShareOneTimeAxisAndThePlotsGetTheRoom();
    void hoveringNeverMovesThePlots();
    void theMeasurementsFoldAwayAndKeepTheirScrollPosition();
    void theFirstMinutesFillTheViewAndAZoomNamesItsSpan();
    void aPanePerPortSettlesWithinThePage_data();
    void aPanePerPortSettlesWithinThePage();

private:
    // The main window at `size`, connected to the demo, its charts page shown.
    ChartsPage *showCharts(QSize size);

    std::unique_ptr<MainWindow> m_window;
};

void TestChartsLayout::initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("TipScopeTests"));
    QSettings().clear();
}

void TestChartsLayout::cleanup() {
    m_window.reset();
    qDeleteAll(QCoreApplication::instance()->findChildren<QTranslator *>());
}

ChartsPage *TestChartsLayout::showCharts(QSize size) {
    m_window = std::make_unique<MainWindow>();
    m_window->resize(size);
    m_window->show();
    if (!QTest::qWaitForWindowExposed(m_window.get()))
        return nullptr;
    AppSettings demo;
    demo.kind = AppSettings::Kind::Demo;
    m_window->connectWith(demo);
    auto *page = m_window->findChild<ChartsPage *>();
    auto *tabs = m_window->findChild<QTabWidget *>();
    if (!page || !tabs)
        return nullptr;
    for (int i = 0; i < tabs->count(); ++i)
        if (tabs->widget(i)->isAncestorOf(page) || tabs->widget(i) == page)
            tabs->setCurrentIndex(i);
    if (!QTest::qWaitFor([&] { return m_window->session().state() == Session::State::Connected; },
                         kConnectMs))
        return nullptr;
    return page;
}

void TestChartsLayout::at1280x720ThePanesShareOneTimeAxisAndThePlotsGetTheRoom_data() {
    QTest::addColumn<QString>("language");
    QTest::addColumn<bool>("perPort");
    for (const char *language : {"en", "de", "es"}) {
        QTest::addRow("%s, ports overlaid", language) << QString::fromLatin1(language) << false;
        QTest::addRow("%s, a pane per port", language) << QString::fromLatin1(language) << true;
    }
}

void TestChartsLayout::at1280x720ThePanesShareOneTimeAxisAndThePlotsGetTheRoom() {
    QFETCH(QString, language);
    QFETCH(bool, perPort);
    QCOMPARE(i18n::installTranslators(*QCoreApplication::instance(), language), language);
    ChartsPage *page = showCharts(QSize(1280, 720));
    QVERIFY(page);
    if (perPort)
        page->setPaneLayout(ChartsPage::Layout::PerPort);
    QTRY_VERIFY_WITH_TIMEOUT(page->panes().size() == (perPort ? 5 : 2), kConnectMs);
    page->redrawNow();
    const QList<ChartWidget *> panes = page->panes();
    if (!perPort) {
        ChartWidget *temperature = panes.first();
        QTRY_VERIFY2(temperature->height() >= kMinTemperaturePanePx,
                     qPrintable(QStringLiteral("%1 px, page %2x%3, window %4x%5")
                                    .arg(temperature->height())
                                    .arg(page->width())
                                    .arg(page->height())
                                    .arg(m_window->width())
                                    .arg(m_window->height())));
        // And most of it is plot: no title row on screen, the devices are named above.
        QVERIFY2(temperature->plotArea().height() >= 0.6 * temperature->height(),
                 qPrintable(QStringLiteral("plot %1 of %2 px")
                                .arg(temperature->plotArea().height())
                                .arg(temperature->height())));
        // Four labelled temperatures at least, and the range is the curves', not the alarms':
        // the demo's high alarm (500 °C) is a band above them.
        const double step = temperature->valueTickStep(ChartAxis::Left);
        const auto [min, max] = temperature->valueRange(ChartAxis::Left);
        const double labels = std::floor(max / step + 1e-9) - std::ceil(min / step - 1e-9) + 1;
        QVERIFY2(labels >= 4,
                 qPrintable(QStringLiteral("%1 to %2 in steps of %3").arg(min).arg(max).arg(step)));
        QVERIFY2(max < 500, qPrintable(QString::number(max)));
    }
    // Qt Charts lays its charts out in posted events; the panes align once it has.
    const qint64 t0 = panes.first()->timeStart();
    const qint64 t1 = panes.first()->timeEnd();
    QTRY_VERIFY2(
        [&] {
            for (ChartWidget *pane : panes)
                for (qint64 t : {t0, (t0 + t1) / 2, t1})
                    if (std::abs(pageX(pane, page, t) - pageX(panes.first(), page, t)) > 1.0)
                        return false;
            return true;
        }(),
        qPrintable(QStringLiteral("x of the window's start: %1 (first pane) and %2 (last)")
                       .arg(pageX(panes.first(), page, t0))
                       .arg(pageX(panes.last(), page, t0))));
}

void TestChartsLayout::hoveringNeverMovesThePlots() {
    ChartsPage *page = showCharts(QSize(1280, 720));
    QVERIFY(page);
    QTRY_VERIFY_WITH_TIMEOUT(page->panes().size() == 2, kConnectMs);
    page->setPaneLayout(ChartsPage::Layout::PerPort);
    page->redrawNow();
    QTest::qWait(200);
    QList<QRect> before;
    for (ChartWidget *pane : page->panes())
        before.append(QRect(pane->mapTo(page, QPoint()), pane->size()));
    ChartWidget *first = page->panes().first();
    const QRectF plot = first->plotArea();
    QMouseEvent move(QEvent::MouseMove, plot.center(),
                     first->plotSurface()->mapToGlobal(plot.center()), Qt::NoButton, Qt::NoButton,
                     Qt::NoModifier);
    QApplication::sendEvent(first->plotSurface(), &move);
    // Every port's values, more than a line holds at this width: each port's cell whole, in
    // rows whose room was kept before the pointer came.
    QVERIFY2(page->readoutText().count(QStringLiteral(" · ")) >= 8,
             qPrintable(page->readoutText()));
    auto *readout = page->findChild<ReadoutPanel *>(QStringLiteral("chartReadout"));
    QVERIFY(readout);
    QVERIFY2(readout->columns() < 4, "four ports side by side do not fit in 1280 px");
    QCOMPARE(readout->height(), readout->heightForWidth(readout->width()));
    QCoreApplication::processEvents();
    QList<QRect> after;
    for (ChartWidget *pane : page->panes())
        after.append(QRect(pane->mapTo(page, QPoint()), pane->size()));
    QCOMPARE(after, before);
}

void TestChartsLayout::theMeasurementsFoldAwayAndKeepTheirScrollPosition() {
    // Short: folded until someone unfolds them, so the plots keep their room.
    ChartsPage *page = showCharts(QSize(1280, 720));
    QVERIFY(page);
    QVERIFY(!page->measurementsShown());
    auto *toggle = page->findChild<QToolButton *>(QStringLiteral("measurementsToggle"));
    auto *text = page->findChild<QPlainTextEdit *>(QStringLiteral("measurementText"));
    QVERIFY(toggle && text);
    QTRY_VERIFY_WITH_TIMEOUT(page->panes().size() == 2, kConnectMs);
    QTRY_VERIFY(page->panes().first()->height() >= kMinTemperaturePanePx);
    const int pane = page->panes().first()->height();
    toggle->click();
    QVERIFY(page->measurementsShown());
    QTRY_VERIFY(text->isVisible());
    QTRY_VERIFY(page->panes().first()->height() < pane);
    // Once chosen by hand, a resize no longer folds them.
    m_window->resize(1280, 700);
    QCoreApplication::processEvents();
    QVERIFY(page->measurementsShown());

    // Scrolled down to the feeder, the reader stays there while the numbers update. (The
    // transistor and transformer temperatures make the text longer than the panel at once.)
    page->findChild<QToolButton *>(QStringLiteral("hardwareButton"))->click();
    QTRY_VERIFY_WITH_TIMEOUT(text->verticalScrollBar()->maximum() > 0, kConnectMs);
    text->verticalScrollBar()->setValue(text->verticalScrollBar()->maximum());
    const int scrolled = text->verticalScrollBar()->value();
    const QString shown = page->measurementText();
    QTRY_VERIFY_WITH_TIMEOUT(page->measurementText() != shown, kConnectMs);
    QCOMPARE(text->verticalScrollBar()->value(), scrolled);

    // Tall: shown from the start.
    ChartsPage *tall = showCharts(QSize(1920, 1080));
    QVERIFY(tall);
    QVERIFY(tall->measurementsShown());
}

void TestChartsLayout::theFirstMinutesFillTheViewAndAZoomNamesItsSpan() {
    ChartsPage *page = showCharts(QSize(1280, 720));
    QVERIFY(page);
    QTRY_VERIFY_WITH_TIMEOUT(page->viewport().dataEnd() > page->viewport().dataStart(), kConnectMs);
    page->redrawNow();
    // A few seconds of data: the window starts at the first sample, not 5 minutes before the last.
    QCOMPARE(page->viewport().start(), page->viewport().dataStart());
    QCOMPARE(page->panes().first()->timeStart(), page->viewport().dataStart());
    auto *window = page->findChild<QComboBox *>(QStringLiteral("windowCombo"));
    QVERIFY(window);
    QCOMPARE(window->currentData().toLongLong(), ChartViewport::kDefaultWindowMs);
    // Zoomed, the box names the span shown rather than going blank.
    page->viewport().setFollowing(false);
    page->viewport().setWindowLength(ChartViewport::kDefaultWindowMs);
    page->viewport().zoom(0.64, page->viewport().end());
    page->redrawNow();
    QCOMPARE(window->currentText(), QStringLiteral("3 min 12 s"));
    page->viewport().reset();
    page->redrawNow();
    QCOMPARE(window->currentText(), QStringLiteral("5 min"));
    QCOMPARE(window->findText(QStringLiteral("3 min 12 s")), -1);
}

void TestChartsLayout::aPanePerPortSettlesWithinThePage_data() {
    QTest::addColumn<QString>("language");
    QTest::addColumn<QSize>("window");
    for (const char *language : {"en", "de", "es"}) {
        QTest::addRow("%s, the window's own default on a 1280x720 screen", language)
            << QString::fromLatin1(language) << QSize(1147, 692);
        QTest::addRow("%s, 1280x720", language)
            << QString::fromLatin1(language) << QSize(1280, 720);
        QTest::addRow("%s, 1920x1080", language)
            << QString::fromLatin1(language) << QSize(1900, 1040);
    }
}

// Issue 39: the panes, made while the page was shown, padded each other's plots to line them
// up, and each padding widened the panes, which asked for more padding: the window spent a core
// laying out charts millions of pixels wide, drew no curve, and starved the line.
void TestChartsLayout::aPanePerPortSettlesWithinThePage() {
    QFETCH(QString, language);
    QFETCH(QSize, window);
    QCOMPARE(i18n::installTranslators(*QCoreApplication::instance(), language), language);
    ChartsPage *page = showCharts(window);
    QVERIFY(page);
    QTRY_VERIFY_WITH_TIMEOUT(page->panes().size() == 2, kConnectMs);
    page->setPaneLayout(ChartsPage::Layout::PerPort);
    page->redrawNow();
    const QList<ChartWidget *> panes = page->panes();
    QCOMPARE(panes.size(), 5);
    QSignalSpy resized(panes.first(), &ChartWidget::plotResized);
    // Laid out, the plots stay as they are: no pane asks the next one for more room.
    QTRY_VERIFY_WITH_TIMEOUT(
        [&] {
            const qsizetype seen = resized.size();
            QTest::qWait(300);
            return resized.size() == seen;
        }(),
        kConnectMs);
    for (ChartWidget *pane : panes) {
        const QString where = QStringLiteral("pane %1 px wide, plot %2 px from %3, page %4 px")
                                  .arg(pane->width())
                                  .arg(pane->plotArea().width())
                                  .arg(pane->plotArea().left())
                                  .arg(page->width());
        QVERIFY2(pane->width() <= page->width(), qPrintable(where));
        QVERIFY2(pane->plotArea().width() >= 0.6 * pane->width() &&
                     pane->plotArea().right() < pane->width(),
                 qPrintable(where));
    }
}

TIPSCOPE_TEST_MAIN(TestChartsLayout)

} // namespace tst_chartslayout
#include "tst_chartslayout.moc"
