// ElidedLabel shows its whole text when given the width it asks for, in any font and size; at its
// minimum a long text is cut with "…" and still shows some of itself; a short text never asks for
// more room than it needs.
#include "testmain.h"
#include "widgets/elidedlabel.h"

#include <QTest>

namespace tst_elidedlabel {

using namespace tipscope::gui;

namespace {
const QString kLong = QStringLiteral("line-3-station-12-2026-12-02T04-21-42-recording.csv");
} // namespace

class TestElidedLabel : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aTextGivenItsSizeHintIsShownWhole_data();
    void aTextGivenItsSizeHintIsShownWhole();
    void atItsMinimumALongTextIsCutAndShowsSomeOfItself_data();
    void atItsMinimumALongTextIsCutAndShowsSomeOfItself();
    void theMinimumGrowsWithTheFont();
    void aShortTextAsksNoMoreThanItself();
};

void TestElidedLabel::aTextGivenItsSizeHintIsShownWhole_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<qreal>("pointSize");
    const QStringList texts{kLong, QStringLiteral("Replay: 12,345 rows"),
                            QStringLiteral("iiiiiiiiiiiiiiiiiiiii"), QStringLiteral("WWWWWWW"),
                            QStringLiteral("Aufzeichnung läuft: Schlüssel-Datei.csv")};
    // Fractional sizes give fractional advances, which QFontMetrics rounds.
    for (const qreal size : {7.3, 9.0, 10.5, 11.7, 13.1, 17.9}) {
        for (const QString &text : texts)
            QTest::addRow("%s at %.1f pt", qPrintable(text.left(12)), size) << text << size;
    }
}

void TestElidedLabel::aTextGivenItsSizeHintIsShownWhole() {
    QFETCH(QString, text);
    QFETCH(qreal, pointSize);
    ElidedLabel label;
    QFont font = label.font();
    font.setPointSizeF(pointSize);
    label.setFont(font);
    label.setFullText(text);
    label.show(); // a hidden label gets its resize event only when shown
    label.resize(label.sizeHint());
    QVERIFY2(!label.isElided(), qPrintable(label.text()));
    QCOMPARE(label.text(), text);
}

void TestElidedLabel::atItsMinimumALongTextIsCutAndShowsSomeOfItself_data() {
    QTest::addColumn<qreal>("pointSize");
    for (const qreal size : {7.0, 10.0, 14.0, 24.0})
        QTest::addRow("%.0f pt", size) << size;
}

void TestElidedLabel::atItsMinimumALongTextIsCutAndShowsSomeOfItself() {
    QFETCH(qreal, pointSize);
    ElidedLabel label;
    QFont font = label.font();
    font.setPointSizeF(pointSize);
    label.setFont(font);
    label.setFullText(kLong);
    label.show();
    label.resize(label.minimumSizeHint());
    QVERIFY(label.isElided());
    QVERIFY2(label.text().contains(QChar(0x2026)), qPrintable(label.text()));
    QVERIFY2(label.text().size() >= 2, qPrintable(label.text()));
    QCOMPARE(label.toolTip(), kLong);
}

void TestElidedLabel::theMinimumGrowsWithTheFont() {
    ElidedLabel small;
    ElidedLabel large;
    QFont font = small.font();
    font.setPointSizeF(8);
    small.setFont(font);
    font.setPointSizeF(24);
    large.setFont(font);
    small.setFullText(kLong);
    large.setFullText(kLong);
    QVERIFY2(large.minimumSizeHint().width() >= 2 * small.minimumSizeHint().width(),
             qPrintable(QStringLiteral("%1 at 24 pt, %2 at 8 pt")
                            .arg(large.minimumSizeHint().width())
                            .arg(small.minimumSizeHint().width())));
    QVERIFY(large.minimumSizeHint().width() < large.sizeHint().width());
}

void TestElidedLabel::aShortTextAsksNoMoreThanItself() {
    ElidedLabel label;
    label.setFullText(QStringLiteral("ab"));
    QCOMPARE(label.minimumSizeHint().width(), label.sizeHint().width());
    label.show();
    label.resize(label.minimumSizeHint());
    QCOMPARE(label.text(), QStringLiteral("ab"));
}

TIPSCOPE_TEST_MAIN(TestElidedLabel)

} // namespace tst_elidedlabel
#include "tst_elidedlabel.moc"
