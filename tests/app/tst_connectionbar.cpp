// ConnectionBar's state line names the state once, in every language: the bar's coloured word
// ("Disconnected") is not followed by the session's or the line's text saying it again
// ("disconnected"), whose own first words repeat it.
#include "connectionbar.h"
#include "testmain.h"

#include "i18n/translations.h"

#include <QRegularExpression>
#include <QTest>
#include <QTranslator>

Q_DECLARE_METATYPE(tipscope::model::Session::State)

namespace tst_connectionbar {

using namespace tipscope;
using model::Session;

class TestConnectionBar : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void theStateLineNamesTheStateOnce_data();
    void theStateLineNamesTheStateOnce();
    void cleanup();
};

void TestConnectionBar::cleanup() {
    qDeleteAll(QCoreApplication::instance()->findChildren<QTranslator *>());
}

void TestConnectionBar::theStateLineNamesTheStateOnce_data() {
    QTest::addColumn<QString>("language");
    QTest::addColumn<Session::State>("state");
    QTest::addColumn<QString>("context");
    QTest::addColumn<QString>("source"); // the text the session passes, as its source writes it
    QTest::addColumn<QString>("argument");
    const char *line = "tipscope::link::Line";
    for (const char *language : {"en", "de", "es"}) {
        QTest::addRow("%s disconnected", language)
            << language << Session::State::Disconnected << "Session"
            << "disconnected"
            << "";
        QTest::addRow("%s retrying", language) << language << Session::State::Retrying << line
                                               << "disconnected, retrying every %1 s: %2"
                                               << "/dev/ttyUSB0";
        QTest::addRow("%s never opened, retrying", language)
            << language << Session::State::Retrying << line
            << "cannot open %1, retrying every %2 s: %3"
            << "/dev/ttyUSB0";
        QTest::addRow("%s cannot connect", language)
            << language << Session::State::Failed << line << "cannot connect: %1"
            << "/dev/ttyUSB0";
        QTest::addRow("%s connecting", language)
            << language << Session::State::Connecting << line << "connecting to %1"
            << "/dev/ttyUSB0";
    }
}

void TestConnectionBar::theStateLineNamesTheStateOnce() {
    QFETCH(QString, language);
    QFETCH(Session::State, state);
    QFETCH(QString, context);
    QFETCH(QString, source);
    QFETCH(QString, argument);
    QCOMPARE(i18n::installTranslators(*QCoreApplication::instance(), language), language);
    QString text = QCoreApplication::translate(qPrintable(context), qPrintable(source));
    if (source.contains(QLatin1String("%3")))
        text = text.arg(argument).arg(5).arg(QStringLiteral("no such file"));
    else if (source.contains(QLatin1String("%2")))
        text = text.arg(5).arg(argument);
    else if (source.contains(QLatin1String("%1")))
        text = text.arg(argument);
    gui::ConnectionBar bar;
    bar.setState(state, text);
    const QString shown = bar.stateText();
    // The state's first word, wherever the bar's own word and the session's text each have it.
    const QString stateWord = shown.section(QLatin1Char(' '), 0, 0).remove(QLatin1Char(','));
    QVERIFY2(!stateWord.isEmpty(), qPrintable(shown));
    const QRegularExpression word(QStringLiteral("\\b%1\\b").arg(stateWord),
                                  QRegularExpression::CaseInsensitiveOption |
                                      QRegularExpression::UseUnicodePropertiesOption);
    int times = 0;
    for (auto it = word.globalMatch(shown); it.hasNext(); it.next())
        ++times;
    QVERIFY2(times == 1, qPrintable(shown));
    if (!argument.isEmpty())
        QVERIFY2(shown.contains(argument), qPrintable(shown)); // the detail is kept
}

TIPSCOPE_TEST_MAIN(TestConnectionBar)

} // namespace tst_connectionbar
#include "tst_connectionbar.moc"
