// SettingsPage on a real Session in demo mode (a simulated 19200 Bd wire): what it shows while
// the line is down and after it is back, what a refused value looks like and how Revert and
// Refresh clear it, and what saving a profile says and writes.
#include "pages/settingspage.h"
#include "testmain.h"
#include "widgets/parametereditor.h"

#include "link/simtransport.h"
#include "model/profiles/profile.h"

#include "demosession.h"
#include "support/typing.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QTest>

namespace tst_settingspage {

using namespace tipscope;
using namespace tipscope::model;
using tipscope::gui::ParameterEditor;
using tipscope::gui::SettingsPage;

namespace {
constexpr int kConnectMs = 60000;
} // namespace

class TestSettingsPage : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void whileTheLineIsDownValuesAreStaleAndWritesAreOffWithTheReason();
    void aWriteTheLostLineRefusedIsNoErrorAfterTheReconnect();
    void revertAndRefreshDiscardARefusedValue_data();
    void revertAndRefreshDiscardARefusedValue();
    void aSavedProfileSaysWhereItWentAndCarriesTheComment();
    void thePortBoxShowsItsWholeText();
    void anEditCountsWhileItIsTyped();
    void aVerifiedWriteNotSavedToMemorySaysItIsInSync();
    void theSavedProfileMessageGoesWithTheNextAction();

private:
    void connectDemo();
    [[nodiscard]] link::SimTransport &transport() const {
        return *qobject_cast<link::SimTransport *>(&m_session->line()->transport());
    }
    [[nodiscard]] ParameterEditor *readEditor(const QByteArray &code);

    std::unique_ptr<Session> m_session;
    std::unique_ptr<SettingsPage> m_page;
};

void TestSettingsPage::init() {
    m_session = std::make_unique<Session>();
    m_page = std::make_unique<SettingsPage>(*m_session);
    m_page->resize(1100, 700);
    m_page->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_page.get()));
}

void TestSettingsPage::cleanup() {
    m_page.reset();
    m_session.reset();
}

void TestSettingsPage::connectDemo() {
    Session::Settings settings = tipscope::testing::unpacedDemoSettings();
    m_session->connectTo(settings);
    QTRY_VERIFY_WITH_TIMEOUT(m_session->state() == Session::State::Connected, kConnectMs);
    m_page->setSelection(m_session->station(), 1);
    m_page->setActive(true);
}

ParameterEditor *TestSettingsPage::readEditor(const QByteArray &code) {
    Parameter *p = m_session->station()->parameter(code);
    if (!p->value())
        p->refresh();
    if (!QTest::qWaitFor([p] { return p->value().has_value(); }, kConnectMs))
        return nullptr;
    return m_page->editorFor(code);
}

void TestSettingsPage::whileTheLineIsDownValuesAreStaleAndWritesAreOffWithTheReason() {
    connectDemo();
    ParameterEditor *mat = readEditor("MAT");
    QVERIFY(mat);
    QTRY_COMPARE(mat->stateText(), QStringLiteral("✓ in sync"));
    for (const char *name : {"save", "actions", "profiles", "refresh"})
        QVERIFY2(m_page->button(QLatin1String(name))->isEnabled(), name);
    QVERIFY(m_page->noticeText().isEmpty());

    transport().setPlugged(false);
    QTRY_VERIFY_WITH_TIMEOUT(!m_session->station()->isLineUp(), kConnectMs);
    const QString last = QLocale().toString(
        m_session->station()->parameter("MAT")->lastUpdate().time(), QStringLiteral("HH:mm:ss"));
    QTRY_COMPARE(mat->stateText(), QStringLiteral("last read %1").arg(last));
    for (const char *name : {"apply", "save", "actions", "profiles", "refresh"})
        QVERIFY2(!m_page->button(QLatin1String(name))->isEnabled(), name);
    // Why, where the eye is: not only in a tooltip.
    QVERIFY2(m_page->noticeText().contains(QStringLiteral("Not connected")) &&
                 m_page->noticeText().contains(QStringLiteral("Profiles")),
             qPrintable(m_page->noticeText()));
    QCOMPARE(mat->enterText(QStringLiteral("400")), QString()); // an edit waits for the line
    QVERIFY(!m_page->button(QStringLiteral("apply"))->isEnabled());

    transport().setPlugged(true);
    QTRY_VERIFY_WITH_TIMEOUT(m_session->station()->isLineUp(), kConnectMs);
    QTRY_VERIFY(m_page->button(QStringLiteral("apply"))->isEnabled());
    for (const char *name : {"save", "actions", "profiles", "refresh"})
        QVERIFY2(m_page->button(QLatin1String(name))->isEnabled(), name);
    QVERIFY(m_page->noticeText().isEmpty());
    QCOMPARE(mat->stateText(), QStringLiteral("edited"));
}

void TestSettingsPage::aWriteTheLostLineRefusedIsNoErrorAfterTheReconnect() {
    connectDemo();
    ParameterEditor *mat = readEditor("MAT");
    QVERIFY(mat);
    transport().setPlugged(false);
    QTRY_VERIFY_WITH_TIMEOUT(!m_session->station()->isLineUp(), kConnectMs);
    QCOMPARE(mat->enterText(QStringLiteral("400")), QString());
    m_page->applyEdits(); // as a shortcut would, with the button off
    QTRY_COMPARE_WITH_TIMEOUT(mat->stateText(), QStringLiteral("✗ failed"), kConnectMs);
    QVERIFY2(mat->messageText().contains(QStringLiteral("not sent: the line is not connected")),
             qPrintable(mat->messageText()));

    transport().setPlugged(true);
    QTRY_VERIFY_WITH_TIMEOUT(m_session->station()->isLineUp(), kConnectMs);
    QTRY_VERIFY(mat->messageText().isEmpty());
    QCOMPARE(mat->stateText(), QStringLiteral("edited")); // kept, to apply now
    QCOMPARE(m_page->editedCount(), 1);
}

void TestSettingsPage::revertAndRefreshDiscardARefusedValue_data() {
    QTest::addColumn<QString>("button");
    QTest::newRow("Revert") << QStringLiteral("revert");
    QTest::newRow("Refresh") << QStringLiteral("refresh");
}

void TestSettingsPage::revertAndRefreshDiscardARefusedValue() {
    QFETCH(QString, button);
    connectDemo();
    ParameterEditor *mat = readEditor("MAT");
    QVERIFY(mat);
    const QString before = m_session->station()->parameter("MAT")->displayText();
    auto *spin = mat->findChild<QDoubleSpinBox *>();
    testing::typeInto(*spin, QStringLiteral("600"));
    QCOMPARE(spin->text(), QStringLiteral("600 °C"));
    QVERIFY2(mat->messageText().contains(QStringLiteral("500 °C")), qPrintable(mat->messageText()));
    QCOMPARE(m_page->editedCount(), 0);
    QVERIFY(!m_page->button(QStringLiteral("apply"))->isEnabled());
    QTRY_VERIFY(m_page->button(QStringLiteral("revert"))->isEnabled());
    QTest::mouseClick(m_page->button(button), Qt::LeftButton);
    QVERIFY(!mat->hasRefusal());
    QVERIFY(mat->messageText().isEmpty());
    QCOMPARE(spin->text(), before);
    QTRY_VERIFY(!m_page->button(QStringLiteral("revert"))->isEnabled());
}

void TestSettingsPage::aSavedProfileSaysWhereItWentAndCarriesTheComment() {
    connectDemo();
    StationModel *st = m_session->station();
    st->refreshAll(link::Priority::UserRead);
    QTRY_VERIFY_WITH_TIMEOUT(m_session->line()->queue().pendingCount() == 0, kConnectMs);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("line 3.json"));
    const auto saved = m_page->saveProfileTo(path, QStringLiteral("  line 3, lead-free  "));
    QVERIFY2(saved, qPrintable(saved.error()));
    const QString said = saved.value();
    QVERIFY2(said.contains(path) && said.contains(st->displayName()), qPrintable(said));
    QVERIFY(m_page->noticeText().contains(path));
    const auto profile = Profile::load(path);
    QVERIFY2(profile.ok(), qPrintable(profile.error()));
    QCOMPARE(profile->comment, QStringLiteral("line 3, lead-free"));
    QVERIFY2(said.contains(QString::number(profile->values.size())), qPrintable(said));

    const auto failed = m_page->saveProfileTo(dir.filePath(QStringLiteral("no/such/dir.json")), {});
    QVERIFY(!failed);
    QVERIFY(failed.error().contains(QStringLiteral("cannot write")));
}

void TestSettingsPage::thePortBoxShowsItsWholeText() {
    connectDemo();
    auto *box = m_page->findChild<QComboBox *>();
    QVERIFY(box);
    QTRY_VERIFY_WITH_TIMEOUT(box->currentText().contains(QStringLiteral("T210")), kConnectMs);
    for (int i = 0; i < box->count(); ++i)
        QVERIFY2(box->sizeHint().width() > box->fontMetrics().horizontalAdvance(box->itemText(i)),
                 qPrintable(box->itemText(i)));
    QVERIFY(box->width() >= box->sizeHint().width());
}

// Typing a value is an edit before the field is left: the field is highlighted and Apply is on
// at once; a value on its way through numbers not allowed ("4", "43") neither counts nor is
// refused until the typing ends.
void TestSettingsPage::anEditCountsWhileItIsTyped() {
    connectDemo();
    ParameterEditor *mat = readEditor("MAT");
    QVERIFY(mat);
    auto *spin = mat->findChild<QDoubleSpinBox *>();
    QTRY_VERIFY(spin->isVisible()); // a box shown later takes its value again
    testing::typeInto(*spin, QStringLiteral("4"), false);
    QVERIFY(!mat->hasRefusal());
    QCOMPARE(m_page->editedCount(), 0);
    QTest::keyClicks(spin->findChild<QLineEdit *>(), QStringLiteral("35"));
    QVERIFY(spin->hasFocus()); // still typing
    QTRY_COMPARE(mat->stateText(), QStringLiteral("edited"));
    QCOMPARE(m_page->editedCount(), 1);
    QTRY_VERIFY(m_page->button(QStringLiteral("apply"))->isEnabled());
    QVERIFY(spin->findChild<QLineEdit *>()->styleSheet().contains(QStringLiteral("background")));
    QCOMPARE(spin->findChild<QLineEdit *>()->text(), QStringLiteral("435 °C")); // as typed

    // Back through a number not allowed: the earlier edit is not left to be applied instead.
    QTest::keyClick(spin->findChild<QLineEdit *>(), Qt::Key_Backspace);
    QTRY_COMPARE(m_page->editedCount(), 0);
    QVERIFY(!mat->hasRefusal());
    QTRY_VERIFY(!m_page->button(QStringLiteral("apply"))->isEnabled());
    QTest::keyClick(spin->findChild<QLineEdit *>(), Qt::Key_Return);
    QVERIFY(mat->hasRefusal()); // said once the typing ends
}

// The selected temperature is volatile: written and read back, it is in sync, and not yet in
// the station's memory. A grey "not saved" alone read as a failed write.
void TestSettingsPage::aVerifiedWriteNotSavedToMemorySaysItIsInSync() {
    connectDemo();
    Parameter *st1 = m_session->station()->parameter("ST1");
    ParameterEditor *editor = readEditor("ST1");
    QVERIFY(editor);
    const qint64 next = st1->number().value_or(350) == 300 ? 310 : 300;
    QCOMPARE(editor->enterText(QString::number(next)), QString());
    m_page->applyEdits();
    QTRY_COMPARE_WITH_TIMEOUT(st1->state(), Parameter::State::InSync, kConnectMs);
    QVERIFY(!st1->isSavedToMemory());
    QTRY_COMPARE(editor->stateText(), QStringLiteral("✓ in sync, not yet saved"));
    auto *state = editor->findChild<QLabel *>();
    for (QLabel *label : editor->findChildren<QLabel *>())
        if (label->text() == editor->stateText())
            state = label;
    QVERIFY2(state->toolTip().contains(QStringLiteral("station memory")),
             qPrintable(state->toolTip()));
    QVERIFY(!state->styleSheet().contains(QStringLiteral("palette(mid)"))); // not greyed
    QVERIFY(state->width() >= state->fontMetrics().horizontalAdvance(state->text()));
}

// "✓ Profile saved" is about that save: the next action has its own result, and the old
// message stays on screen no longer.
void TestSettingsPage::theSavedProfileMessageGoesWithTheNextAction() {
    connectDemo();
    m_session->station()->refreshAll(link::Priority::UserRead);
    QTRY_VERIFY_WITH_TIMEOUT(m_session->line()->queue().pendingCount() == 0, kConnectMs);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("line.json"));
    QVERIFY(m_page->saveProfileTo(path, {}));
    QVERIFY(m_page->noticeText().contains(path));
    QTest::mouseClick(m_page->button(QStringLiteral("refresh")), Qt::LeftButton);
    QVERIFY2(!m_page->noticeText().contains(path), qPrintable(m_page->noticeText()));

    QVERIFY(m_page->saveProfileTo(path, {}));
    ParameterEditor *mat = readEditor("MAT");
    QVERIFY(mat);
    testing::typeInto(*mat->findChild<QDoubleSpinBox *>(), QStringLiteral("420"));
    QTRY_VERIFY2(!m_page->noticeText().contains(path), qPrintable(m_page->noticeText()));
}

TIPSCOPE_TEST_MAIN(TestSettingsPage)

} // namespace tst_settingspage
#include "tst_settingspage.moc"
