// ParameterEditor before and after the device's value is known: a box not read yet shows a dash,
// never its minimum (which a technician would take for the station's setting). A value out of
// range is never clamped: it stays as typed, refused, with the reason and the allowed range under
// the field, and nothing becomes an edit until a value is allowed.
#include "../model/simfixture.h"
#include "testmain.h"
#include "widgets/parametereditor.h"

#include "support/typing.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QTest>

namespace tst_parametereditor {

using namespace tipscope;
using tipscope::gui::ParameterEditor;

class TestParameterEditor : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void anUnreadValueShowsADashUntilTheDeviceAnswers();
    void aValueAboveTheMaximumIsRefusedAsTypedWithTheRangeUnderIt_data();
    void aValueAboveTheMaximumIsRefusedAsTypedWithTheRangeUnderIt();
    void aDiscardedRefusalShowsTheDevicesValueAgain();
    void aDisabledValueShowsADashAndEnablingItStartsAtTheLowestAllowed();
};

void TestParameterEditor::anUnreadValueShowsADashUntilTheDeviceAnswers() {
    testing::SimFixture f(testing::singleDevice(QStringLiteral("DME")));
    f.simLine->devices().first()->setSetting("MAT", 450);
    auto station = f.station();
    model::Parameter *mat = station->parameter("MAT");
    QVERIFY(mat && !mat->value());
    ParameterEditor editor(mat);
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    auto *spin = editor.findChild<QDoubleSpinBox *>();
    QVERIFY(spin);
    QCOMPARE(spin->text(), QStringLiteral("—"));
    mat->refresh();
    f.settle();
    QCOMPARE(mat->number(), 450);
    QCOMPARE(spin->text(), QStringLiteral("450 °C"));
    QVERIFY(!mat->edit()); // showing the value edited nothing
}

void TestParameterEditor::aValueAboveTheMaximumIsRefusedAsTypedWithTheRangeUnderIt_data() {
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QString>("shown");
    QTest::addColumn<QString>("why");
    QTest::newRow("600 where 500 is the maximum")
        << QStringLiteral("600") << QStringLiteral("600 °C") << QStringLiteral("90 °C to 500 °C");
    QTest::newRow("50 where 90 is the minimum")
        << QStringLiteral("50") << QStringLiteral("50 °C") << QStringLiteral("90 °C to 500 °C");
    QTest::newRow("453, between the steps")
        << QStringLiteral("453") << QStringLiteral("453 °C") << QStringLiteral("steps of 5 °C");
}

void TestParameterEditor::aValueAboveTheMaximumIsRefusedAsTypedWithTheRangeUnderIt() {
    QFETCH(QString, typed);
    QFETCH(QString, shown);
    QFETCH(QString, why);
    testing::SimFixture f(testing::singleDevice(QStringLiteral("DME")));
    f.simLine->devices().first()->setSetting("MAT", 450);
    f.simLine->devices().first()->setSetting("MIT", 90);
    auto station = f.station();
    model::Parameter *mat = station->parameter("MAT");
    station->parameter("MIT")->refresh();
    mat->refresh();
    f.settle();
    ParameterEditor editor(mat);
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    auto *spin = editor.findChild<QDoubleSpinBox *>();
    QVERIFY(spin);
    QVERIFY(editor.messageText().isEmpty());
    testing::typeInto(*spin, typed);
    QCOMPARE(spin->text(), shown); // as typed, not clamped to a limit
    QCOMPARE(editor.stateText(), QStringLiteral("✗ refused"));
    QVERIFY2(editor.messageText().contains(why) &&
                 editor.messageText().contains(QStringLiteral("not allowed")),
             qPrintable(editor.messageText()));
    QVERIFY(!mat->edit());
    QCOMPARE(mat->state(), model::Parameter::State::InSync);
    testing::typeInto(*spin, QStringLiteral("400")); // an allowed value replaces the refusal
    QVERIFY(!editor.hasRefusal());
    QVERIFY(editor.messageText().isEmpty());
    QCOMPARE(mat->edit(), std::optional<qint64>(400));
}

void TestParameterEditor::aDiscardedRefusalShowsTheDevicesValueAgain() {
    testing::SimFixture f(testing::singleDevice(QStringLiteral("DME")));
    f.simLine->devices().first()->setSetting("MAT", 450);
    auto station = f.station();
    model::Parameter *mat = station->parameter("MAT");
    mat->refresh();
    f.settle();
    ParameterEditor editor(mat);
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    auto *spin = editor.findChild<QDoubleSpinBox *>();
    testing::typeInto(*spin, QStringLiteral("600"));
    QVERIFY(editor.hasRefusal());
    editor.discardRefusal();
    QVERIFY(!editor.hasRefusal());
    QCOMPARE(spin->text(), QStringLiteral("450 °C"));
    QVERIFY(editor.messageText().isEmpty());
    QCOMPARE(editor.stateText(), QStringLiteral("✓ in sync"));
}

void TestParameterEditor::aDisabledValueShowsADashAndEnablingItStartsAtTheLowestAllowed() {
    testing::SimFixture f(testing::singleDevice(QStringLiteral("DME")));
    f.simLine->devices().first()->setSetting("HD1", 99999); // the alarm delay "disabled"
    auto station = f.station();
    model::Parameter *delay = station->parameter("HD1");
    QVERIFY(delay);
    delay->refresh();
    f.settle();
    ParameterEditor editor(delay);
    editor.show();
    QVERIFY(QTest::qWaitForWindowExposed(&editor));
    auto *spin = editor.findChild<QDoubleSpinBox *>();
    auto *disabled = editor.findChild<QCheckBox *>();
    QVERIFY(spin && disabled);
    QVERIFY(disabled->isChecked());
    QCOMPARE(spin->text(), QStringLiteral("—")); // not the box's own lower bound
    disabled->click();
    QVERIFY2(!editor.hasRefusal(), qPrintable(editor.messageText()));
    QCOMPARE(delay->edit(), std::optional<qint64>(delay->minimum()));
}

TIPSCOPE_TEST_MAIN(TestParameterEditor)

} // namespace tst_parametereditor
#include "tst_parametereditor.moc"
