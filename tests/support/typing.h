// Typing into a number box as a person does: the whole text replaced by keystrokes, then Enter,
// so whatever the box does with typed text (clamp, refuse, keep) happens as it would for them.
#pragma once

#include <QAbstractSpinBox>
#include <QLineEdit>
#include <QTest>

namespace tipscope::testing {

inline void typeInto(QAbstractSpinBox &box, const QString &text, bool enter = true) {
    auto *edit = box.findChild<QLineEdit *>();
    QVERIFY(edit);
    box.setFocus();
    edit->selectAll();
    QTest::keyClicks(edit, text);
    if (enter)
        QTest::keyClick(edit, Qt::Key_Return);
}

} // namespace tipscope::testing
