// FeederPage on a real Session in demo mode (the simulated SFR at 10): Apply is on only with a
// value to write and none refused, and Revert discards what was typed, refused or not.
#include "pages/feederpage.h"
#include "testmain.h"
#include "widgets/parametereditor.h"

#include "sim/simfeeder.h"
#include "sim/simline.h"

#include "demosession.h"
#include "support/typing.h"

#include <QDoubleSpinBox>
#include <QPushButton>
#include <QTest>

namespace tst_feederpage {

using namespace tipscope;
using namespace tipscope::model;
using tipscope::gui::FeederPage;
using tipscope::gui::ParameterEditor;

namespace {
constexpr int kConnectMs = 60000;
} // namespace

class TestFeederPage : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void applyIsOffWithNothingToWriteAndWithARefusedValue();
    void revertDiscardsARefusedValueAndAnEdit();

private:
    [[nodiscard]] ParameterEditor *speedEditor();
    [[nodiscard]] QPushButton *button(const char *name) const {
        return m_page->button(QLatin1String(name));
    }

    std::unique_ptr<Session> m_session;
    std::unique_ptr<FeederPage> m_page;
};

void TestFeederPage::init() {
    m_session = std::make_unique<Session>();
    m_page = std::make_unique<FeederPage>(*m_session);
    m_page->resize(900, 640);
    m_page->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_page.get()));
    QVERIFY(testing::connectUnpacedDemo(*m_session, kConnectMs));
    m_page->setSelection(m_session->feeder(), 0);
}

void TestFeederPage::cleanup() {
    m_page.reset();
    m_session.reset();
}

ParameterEditor *TestFeederPage::speedEditor() {
    Parameter *p = m_session->feeder()->parameter("SPD");
    if (!p || !QTest::qWaitFor([p] { return p->value().has_value(); }, kConnectMs))
        return nullptr;
    return m_page->editorFor("SPD");
}

void TestFeederPage::applyIsOffWithNothingToWriteAndWithARefusedValue() {
    ParameterEditor *speed = speedEditor();
    QVERIFY(speed && button("apply") && button("revert"));
    QVERIFY(!button("apply")->isEnabled()); // nothing to write
    QVERIFY(!button("revert")->isEnabled());
    auto *spin = speed->findChild<QDoubleSpinBox *>();
    testing::typeInto(*spin, QStringLiteral("999"));
    QVERIFY(speed->hasRefusal());
    QVERIFY(!button("apply")->isEnabled()); // it would have done nothing and said nothing

    testing::typeInto(*spin, QStringLiteral("20"));
    QVERIFY(!speed->hasRefusal());
    QTRY_VERIFY(button("apply")->isEnabled());
    QTest::mouseClick(button("apply"), Qt::LeftButton);
    QTRY_COMPARE_WITH_TIMEOUT(m_session->demoLine()->feeder()->setting("SPD"),
                              std::optional<qint64>(200), kConnectMs);
    QTRY_VERIFY(!button("apply")->isEnabled()); // written and read back: nothing left to write
}

void TestFeederPage::revertDiscardsARefusedValueAndAnEdit() {
    ParameterEditor *speed = speedEditor();
    QVERIFY(speed);
    auto *spin = speed->findChild<QDoubleSpinBox *>();
    const QString before = spin->text();
    testing::typeInto(*spin, QStringLiteral("999"));
    QTRY_VERIFY(button("revert")->isEnabled());
    QTest::mouseClick(button("revert"), Qt::LeftButton);
    QVERIFY(!speed->hasRefusal());
    QVERIFY(speed->messageText().isEmpty());
    QTRY_COMPARE(spin->text(), before);

    testing::typeInto(*spin, QStringLiteral("25"));
    QTRY_VERIFY(button("revert")->isEnabled());
    QTest::mouseClick(button("revert"), Qt::LeftButton);
    QTRY_COMPARE(spin->text(), before);
    QVERIFY(!m_session->feeder()->parameter("SPD")->edit());
    QTRY_VERIFY(!button("apply")->isEnabled());
    QVERIFY(!button("revert")->isEnabled());
}

TIPSCOPE_TEST_MAIN(TestFeederPage)

} // namespace tst_feederpage
#include "tst_feederpage.moc"
