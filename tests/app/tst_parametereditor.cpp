// ParameterEditor before and after the device's value is known: a box not read yet shows a dash,
// never its minimum (which a technician would take for the station's setting).
#include "../model/simfixture.h"
#include "widgets/parametereditor.h"

#include <QDoubleSpinBox>
#include <QTest>

using namespace tipscope;
using tipscope::gui::ParameterEditor;

class TestParameterEditor : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void anUnreadValueShowsADashUntilTheDeviceAnswers();
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

QTEST_MAIN(TestParameterEditor)
#include "tst_parametereditor.moc"
