// A stored joint as other programs read it: the CSV row has the header's columns, reads back
// through the CSV reader every export shares to the JSON's values, and a work order, board or
// operator typed with a comma, a quote, spaces at its ends or a line break stays one cell of one
// line; a joint that never recovered has an empty recovery and a null one in JSON.
#include "base/csv.h"
#include "journal/jointexport.h"
#include "journalfixture.h"
#include "testmain.h"

#include <QJsonObject>
#include <QTest>

namespace tst_jointexport {

using namespace tipscope;

journal::StoredJoint storedJoint(const model::WorkContext &context) {
    journal::StoredJoint stored;
    stored.id = 7;
    stored.uid = QUuid::createUuid();
    stored.context = context;
    stored.record = testing::sampleJoint(3, testing::kT0);
    return stored;
}

QStringList cellsOf(const QString &line) {
    const QByteArray bytes = line.toUtf8();
    base::csv::Cells cells;
    if (!base::csv::splitLine(bytes, cells))
        return {};
    QStringList texts;
    for (qsizetype i = 0; i < cells.size(); ++i)
        texts.append(QString::fromUtf8(cells.at(i)));
    return texts;
}

QString jsonText(const QJsonValue &value) {
    if (value.isNull() || value.isUndefined())
        return {};
    if (value.isBool())
        return value.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    if (value.isDouble())
        return QString::number(value.toDouble(), 'g', 12);
    return value.toString();
}

class TstJointExport : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void theRowReadsBackToTheJsonsValues_data();
    void theRowReadsBackToTheJsonsValues();
    void aJointThatNeverRecoveredHasNoRecovery();
};

void TstJointExport::theRowReadsBackToTheJsonsValues_data() {
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QString>("readBack");
    QTest::newRow("plain") << QStringLiteral("WO-7") << QStringLiteral("WO-7");
    QTest::newRow("comma") << QStringLiteral("WO-7, lot 3") << QStringLiteral("WO-7, lot 3");
    QTest::newRow("quote") << QStringLiteral("the \"red\" board")
                           << QStringLiteral("the \"red\" board");
    QTest::newRow("spaces at its ends") << QStringLiteral("  WO-7 ") << QStringLiteral("  WO-7 ");
    QTest::newRow("line break") << QStringLiteral("WO-7\nsecond line")
                                << QStringLiteral("WO-7 second line");
}

void TstJointExport::theRowReadsBackToTheJsonsValues() {
    QFETCH(QString, typed);
    QFETCH(QString, readBack);
    const journal::StoredJoint joint =
        storedJoint({typed, QStringLiteral("SN-42"), QStringLiteral("Ana")});
    const QString row = journal::jointCsvRow(joint);
    QVERIFY2(!row.contains(QLatin1Char('\n')), qPrintable(row));
    const QStringList header = cellsOf(journal::jointCsvHeader());
    const QStringList cells = cellsOf(row);
    QCOMPARE(cells.size(), header.size());
    const QJsonObject json = journal::jointJson(joint);
    for (qsizetype i = 0; i < header.size(); ++i) {
        const QString &field = header.at(i);
        if (field == QLatin1String("work_order"))
            QCOMPARE(cells.at(i), readBack);
        else
            QCOMPARE(cells.at(i), jsonText(json.value(field)));
    }
    QCOMPARE(json.value(QStringLiteral("work_order")).toString(), typed); // JSON keeps it whole
    QCOMPARE(json.value(QStringLiteral("id")).toString(), joint.uid.toString(QUuid::WithoutBraces));
}

void TstJointExport::aJointThatNeverRecoveredHasNoRecovery() {
    journal::StoredJoint joint = storedJoint({});
    joint.record.recoveryMs.reset();
    const QJsonObject json = journal::jointJson(joint);
    QVERIFY(json.value(QStringLiteral("recovery_ms")).isNull());
    const QStringList header = cellsOf(journal::jointCsvHeader());
    const QStringList cells = cellsOf(journal::jointCsvRow(joint));
    QCOMPARE(cells.at(header.indexOf(QStringLiteral("recovery_ms"))), QString());
}

TIPSCOPE_TEST_GUILESS_MAIN(TstJointExport)

} // namespace tst_jointexport

#include "tst_jointexport.moc"
