// The one rule for echoing input in messages: short input whole, long input cut with its length,
// control characters by their code.
#include "base/elide.h"
#include "testmain.h"

#include <QTest>

namespace tst_elide {

using namespace tipscope::base;

class TestElide : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void inputIsEchoedWholeUpToTheLimit_data();
    void inputIsEchoedWholeUpToTheLimit();
    void longInputIsCutAndSaysItsLength();
    void aCharacterOutsideTheBasicPlaneIsNeverCutInHalf();
    void controlCharactersAreShownByTheirCode();
    void pathsKeepMoreOfTheirLength();
};

void TestElide::inputIsEchoedWholeUpToTheLimit_data() {
    QTest::addColumn<QString>("text");
    QTest::newRow("empty") << QString();
    QTest::newRow("a code") << QStringLiteral("ST1");
    QTest::newRow("exactly the limit") << QString(kElideChars, QLatin1Char('x'));
    QTest::newRow("umlauts") << QStringLiteral("Lötstation für Linie 3");
}

void TestElide::inputIsEchoedWholeUpToTheLimit() {
    QFETCH(QString, text);
    QCOMPARE(elided(text), text);
}

void TestElide::longInputIsCutAndSaysItsLength() {
    const QString huge(100 * 1024, QLatin1Char('S'));
    const QString e = elided(huge);
    QCOMPARE(e, QString(kElideChars, QLatin1Char('S')) + QStringLiteral("… (102400 characters)"));
    QCOMPARE(elided(QString(kElideChars + 1, QLatin1Char('y'))),
             QString(kElideChars, QLatin1Char('y')) + QStringLiteral("… (41 characters)"));
}

void TestElide::aCharacterOutsideTheBasicPlaneIsNeverCutInHalf() {
    const QString flame = QString::fromUtf8("\xf0\x9f\x94\xa5"); // two UTF-16 units
    QString text;
    for (int i = 0; i < 50; ++i)
        text += flame;
    const QString e = elided(text);
    QVERIFY2(e.startsWith(text.left(2 * kElideChars) + QStringLiteral("…")), qPrintable(e));
    QVERIFY2(e.endsWith(QStringLiteral("(50 characters)")), qPrintable(e));
    QCOMPARE(elided(text.left(2 * kElideChars)), text.left(2 * kElideChars));
}

void TestElide::controlCharactersAreShownByTheirCode() {
    QCOMPARE(elided(QStringLiteral("a\x1b[2Jb")), QStringLiteral("a<1B>[2Jb"));
    QCOMPARE(elided(QString(QChar(0)) + QStringLiteral("1\n")), QStringLiteral("<00>1<0A>"));
}

void TestElide::pathsKeepMoreOfTheirLength() {
    const QString path = QStringLiteral("/home/anna/Dokumente/TipScope/Profile/Linie 3/a.json");
    QVERIFY(path.size() > kElideChars);
    QCOMPARE(elidedPath(path), path);
    QVERIFY(
        elidedPath(QString(5000, QLatin1Char('p'))).endsWith(QStringLiteral("(5000 characters)")));
}

TIPSCOPE_TEST_GUILESS_MAIN(TestElide)

} // namespace tst_elide
#include "tst_elide.moc"
