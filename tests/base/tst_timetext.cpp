// Time as people and files read it: a file's time carries its UTC offset, so another time zone
// reads the same instant; a table's clock leaves out the date only on the day itself; a duration
// follows the reader's locale.
#include "base/timetext.h"
#include "testmain.h"

#include <QLocale>
#include <QTest>
#include <QTimeZone>

namespace tst_timetext {

using namespace tipscope::base;

class TestTimeText : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aFilesTimeCarriesItsOffsetAndReadsBackAsTheSameInstant() {
        const QDateTime berlin(QDate(2024, 5, 1), QTime(10, 2, 3, 123), QTimeZone("Europe/Berlin"));
        QCOMPARE(isoTimeWithOffset(berlin), QStringLiteral("2024-05-01T10:02:03.123+02:00"));
        const QDateTime utc = berlin.toUTC();
        QCOMPARE(isoTimeWithOffset(utc), QStringLiteral("2024-05-01T08:02:03.123Z"));
        QCOMPARE(QDateTime::fromString(isoTimeWithOffset(berlin), Qt::ISODateWithMs), berlin);
        QCOMPARE(isoTimeWithOffset(QDateTime()), QString());
    }

    void aClockGivesTheDateOnlyOnAnotherDay() {
        const QDateTime time(QDate(2024, 4, 30), QTime(10, 2, 3));
        QCOMPARE(clockText(time, QDate(2024, 4, 30)), QStringLiteral("10:02:03"));
        QCOMPARE(clockText(time, QDate(2024, 5, 1)), QStringLiteral("2024-04-30 10:02:03"));
    }

    void aDurationIsWrittenInTheReadersLocale() {
        const QLocale before;
        QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
        const QString german = secondsText(4249);
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
        const QString english = secondsText(4249);
        const QString none = secondsText(0);
        QLocale::setDefault(before);
        QCOMPARE(german, QStringLiteral("4,2"));
        QCOMPARE(english, QStringLiteral("4.2"));
        QCOMPARE(none, QStringLiteral("0.0"));
    }
};

TIPSCOPE_TEST_GUILESS_MAIN(TestTimeText)

} // namespace tst_timetext

#include "tst_timetext.moc"
