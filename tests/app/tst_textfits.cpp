// What a person sees fits where it is shown: the real main window at 1280×720, on the demo line,
// in English, German and Spanish; on every page, each visible label, button, check box, tab,
// combo box and device tree entry is checked against the room it has, no two widgets of a layout
// cover each other and no page needs a horizontal scroll bar (support/screencheck.h). A text cut
// short ("Port 1 (T2", "Tempera…") fails the test with its page, widget and words.
#include "devicetree.h"
#include "i18n/translations.h"
#include "mainwindow.h"
#include "pages/feederpage.h"
#include "pages/settingspage.h"
#include "testmain.h"
#include "widgets/parametereditor.h"

#include "support/screencheck.h"
#include "support/typing.h"

#include <QDoubleSpinBox>
#include <QLabel>
#include <QScrollArea>
#include <QSettings>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTest>
#include <QTranslator>

namespace tst_textfits {

using namespace tipscope;
using namespace tipscope::gui;
using namespace tipscope::model;

namespace {
constexpr int kConnectMs = 20000;

// The window at the smallest screen size it is made for, on the demo line.
void showOnTheDemoLine(MainWindow &window) {
    window.resize(1280, 720);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    AppSettings demo;
    demo.kind = AppSettings::Kind::Demo;
    window.connectWith(demo);
    QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), Session::State::Connected, kConnectMs);
}

// Types `text` into the editor's box; why its refusal is not shown whole under the field, or
// empty when it is (with the allowed range).
QString refusalCut(ParameterEditor &editor, const QString &text) {
    auto *box = editor.findChild<QDoubleSpinBox *>();
    if (!box)
        return QStringLiteral("no number box");
    testing::typeInto(*box, text);
    const QString why = editor.messageText();
    if (!editor.hasRefusal() || why.isEmpty())
        return QStringLiteral("%1 was not refused").arg(text);
    const QString allowed = editor.parameter()->allowedText();
    if (!why.contains(allowed))
        return QStringLiteral("\"%1\" does not say what is allowed (%2)").arg(why, allowed);
    QLabel *message = nullptr;
    for (QLabel *label : editor.findChildren<QLabel *>())
        if (label->isVisible() && label->text() == why)
            message = label;
    if (!message)
        return QStringLiteral("\"%1\" is not shown under the field").arg(why);
    for (QWidget *w = &editor; w; w = w->parentWidget())
        if (auto *scroll = qobject_cast<QScrollArea *>(w)) {
            scroll->ensureWidgetVisible(message);
            break;
        }
    QCoreApplication::processEvents();
    // Room of its own, and not cut by the field, the form or the page around it.
    const int needed = message->heightForWidth(message->width());
    const QRect seen = message->visibleRegion().boundingRect();
    if (seen.height() + 1 < needed || seen.width() + 1 < message->width())
        return QStringLiteral("\"%1\" needs %2×%3 px, %4×%5 are seen")
            .arg(why)
            .arg(message->width())
            .arg(needed)
            .arg(seen.width())
            .arg(seen.height());
    return {};
}
} // namespace

class TestTextFits : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void everyTextOnEveryPageFitsAt1280x720_data();
    void everyTextOnEveryPageFitsAt1280x720();
    void aRefusalShowsItsWholeReasonUnderTheFieldAt1280x720_data();
    void aRefusalShowsItsWholeReasonUnderTheFieldAt1280x720();
};

void TestTextFits::initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("TipScopeTests"));
    QSettings().clear();
}

void TestTextFits::everyTextOnEveryPageFitsAt1280x720_data() {
    QTest::addColumn<QString>("language");
    for (const char *language : {"en", "de", "es"})
        QTest::newRow(language) << QString::fromLatin1(language);
}

void TestTextFits::everyTextOnEveryPageFitsAt1280x720() {
    QFETCH(QString, language);
    QCOMPARE(i18n::installTranslators(*QCoreApplication::instance(), language), language);
    QStringList problems;
    {
        MainWindow window;
        showOnTheDemoLine(window);
        if (QTest::currentTestFailed())
            return;
        // Every port's tool and every setting read, so the texts are the real ones.
        QTest::qWait(3000);
        QTabWidget &pages = window.pages();
        int treeWidth = -1;
        for (int i = 0; i < pages.count(); ++i) {
            pages.setCurrentIndex(i);
            QTest::qWait(300);
            // A page wider than the others takes its width from the device tree while it is
            // shown: the tree narrows and the tabs jump as a person goes from page to page.
            if (treeWidth < 0)
                treeWidth = window.deviceTree().width();
            else if (window.deviceTree().width() != treeWidth)
                problems.append(QStringLiteral("%1: the device tree is %2 px wide, %3 on the "
                                               "first page")
                                    .arg(pages.tabText(i))
                                    .arg(window.deviceTree().width())
                                    .arg(treeWidth));
            // A page that needs more than the screen widens the window past its edge and takes
            // the device tree's width as it comes and goes.
            if (const int needed = window.minimumSizeHint().width(); needed > 1280)
                problems.append(QStringLiteral("%1: the window needs %2 px of width, the screen "
                                               "has 1280")
                                    .arg(pages.tabText(i))
                                    .arg(needed));
            for (const QString &why : testing::screenProblems(window))
                problems.append(QStringLiteral("%1: %2").arg(pages.tabText(i), why));
        }
    }
    qDeleteAll(QCoreApplication::instance()->findChildren<QTranslator *>());
    problems.removeDuplicates();
    // One line each: QVERIFY2 cuts a long message short.
    for (const QString &p : std::as_const(problems))
        qWarning("%s", qPrintable(p));
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
}

void TestTextFits::aRefusalShowsItsWholeReasonUnderTheFieldAt1280x720_data() {
    everyTextOnEveryPageFitsAt1280x720_data();
}

// 600 °C on Settings and 999 mm/s on the Feeder page are refused; the reason and the range
// allowed are read whole under the field, in every language, at the smallest screen size.
void TestTextFits::aRefusalShowsItsWholeReasonUnderTheFieldAt1280x720() {
    QFETCH(QString, language);
    QCOMPARE(i18n::installTranslators(*QCoreApplication::instance(), language), language);
    QStringList problems;
    {
        MainWindow window;
        showOnTheDemoLine(window);
        if (QTest::currentTestFailed())
            return;
        QTRY_VERIFY_WITH_TIMEOUT(window.session().station() && window.session().feeder(),
                                 kConnectMs);
        StationModel *station = window.session().station();
        FeederModel *feeder = window.session().feeder();
        QTRY_VERIFY_WITH_TIMEOUT(
            station->parameter("MAT")->value() && feeder->parameter("SPD")->value(), kConnectMs);

        QVERIFY(window.deviceTree().select(DeviceTree::kBarLine, station, 1));
        auto *settings = window.findChild<SettingsPage *>();
        QVERIFY(settings);
        window.pages().setCurrentWidget(settings);
        QTRY_VERIFY(settings->editorFor("MAT") && settings->editorFor("MAT")->isVisible());
        if (const QString why = refusalCut(*settings->editorFor("MAT"), QStringLiteral("600"));
            !why.isEmpty())
            problems.append(QStringLiteral("Settings: ") + why);

        QVERIFY(window.deviceTree().select(DeviceTree::kBarLine, feeder));
        auto *feederPage = window.findChild<FeederPage *>();
        QVERIFY(feederPage);
        window.pages().setCurrentWidget(feederPage);
        QTRY_VERIFY(feederPage->editorFor("SPD") && feederPage->editorFor("SPD")->isVisible());
        if (const QString why = refusalCut(*feederPage->editorFor("SPD"), QStringLiteral("999"));
            !why.isEmpty())
            problems.append(QStringLiteral("Feeder: ") + why);
    }
    qDeleteAll(QCoreApplication::instance()->findChildren<QTranslator *>());
    for (const QString &p : std::as_const(problems))
        qWarning("%s", qPrintable(p));
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
}

TIPSCOPE_TEST_MAIN(TestTextFits)

} // namespace tst_textfits
#include "tst_textfits.moc"
