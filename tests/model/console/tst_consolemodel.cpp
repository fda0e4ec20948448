// ConsoleModel takes the line's tap events in batches: a burst becomes one insertion, in order,
// nothing is lost below the capacity, the oldest rows go first above it, and pausing holds rows
// without dropping them. Rows say what they are in the user interface language.
#include "i18n/translations.h"
#include "model/console/consolemodel.h"
#include "testmain.h"

#include <QSignalSpy>
#include <QTest>
#include <QTranslator>

namespace tst_consolemodel {

using namespace tipscope;
using model::ConsoleModel;

namespace {
QString noteAt(const ConsoleModel &m, int row) {
    return m.entry(row).remark;
}

QString cell(const ConsoleModel &m, int row, int column) {
    return m.data(m.index(row, column), Qt::DisplayRole).toString();
}

// A model with one row of each kind: TX, RX chunk, a received frame, a decode error, a note.
void tapOneOfEach(link::FrameTap &tap) {
    using protocol::Frame;
    const QByteArray request = Frame::read("SMN").addressed(0, 1).encode();
    const QByteArray answer = Frame{1, 0, protocol::Header::Answer, "SMN", "DME-2C"}.encode();
    tap.tx(request);
    tap.rx(answer);
    protocol::FrameDecoder decoder;
    for (const protocol::DecodeEvent &e : decoder.feed(answer + request.chopped(1) + '^'))
        tap.decoded(e, false);
    tap.note(QStringLiteral("line open"));
}
} // namespace

class TestConsoleModel : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aBurstIsInsertedAtOnceAndInOrder();
    void flushShowsWhatArrivedWithoutWaiting();
    void beyondTheCapacityTheOldestRowsGo();
    void pauseHoldsRowsAndResumeShowsThemAll();
    void aCodeFamiliesShareIsNamedAsTheDeviceInTheFrameKnowsIt();
    void receivedFramesAreLabelledRx();
    void theHeldCountFollowsWhatArrivesWhilePaused();
    void headersAreNamedInTheInterfaceLanguage_data();
    void headersAreNamedInTheInterfaceLanguage();
};

void TestConsoleModel::aBurstIsInsertedAtOnceAndInOrder() {
    link::FrameTap tap;
    ConsoleModel model(nullptr, 1000);
    model.attach(&tap);
    QSignalSpy inserted(&model, &ConsoleModel::rowsInserted);
    for (int i = 0; i < 300; ++i)
        tap.note(QString::number(i));
    QCOMPARE(model.rowCount(), 0); // not yet: the batch is due
    QTRY_COMPARE_WITH_TIMEOUT(model.rowCount(), 300, 5 * ConsoleModel::kBatchMs + 2000);
    QCOMPARE(inserted.count(), 1);
    for (int i = 0; i < 300; ++i)
        QCOMPARE(noteAt(model, i), QString::number(i));
}

void TestConsoleModel::flushShowsWhatArrivedWithoutWaiting() {
    link::FrameTap tap;
    ConsoleModel model;
    model.attach(&tap);
    tap.tx("\x02R00SMN\x03?");
    tap.note(QStringLiteral("after"));
    model.flush();
    QCOMPARE(model.rowCount(), 2);
    QCOMPARE(model.entry(0).direction, model::ConsoleEntry::Direction::Tx);
    QCOMPARE(noteAt(model, 1), QStringLiteral("after"));
}

void TestConsoleModel::beyondTheCapacityTheOldestRowsGo() {
    link::FrameTap tap;
    ConsoleModel model(nullptr, 50);
    model.attach(&tap);
    for (int i = 0; i < 40; ++i)
        tap.note(QString::number(i));
    model.flush();
    for (int i = 40; i < 75; ++i) // overflows across batches
        tap.note(QString::number(i));
    model.flush();
    QCOMPARE(model.rowCount(), 50);
    QCOMPARE(noteAt(model, 0), QStringLiteral("25"));
    QCOMPARE(noteAt(model, 49), QStringLiteral("74"));
    for (int i = 75; i < 200; ++i) // one batch larger than the capacity
        tap.note(QString::number(i));
    model.flush();
    QCOMPARE(model.rowCount(), 50);
    QCOMPARE(noteAt(model, 0), QStringLiteral("150"));
    QCOMPARE(noteAt(model, 49), QStringLiteral("199"));
}

void TestConsoleModel::pauseHoldsRowsAndResumeShowsThemAll() {
    link::FrameTap tap;
    ConsoleModel model;
    model.attach(&tap);
    tap.note(QStringLiteral("before"));
    model.setPaused(true);
    QCOMPARE(model.rowCount(), 1); // what arrived before the pause is shown
    for (int i = 0; i < 20; ++i)
        tap.note(QString::number(i));
    QTest::qWait(3 * ConsoleModel::kBatchMs);
    QCOMPARE(model.rowCount(), 1);
    model.setPaused(false);
    QCOMPARE(model.rowCount(), 21);
    QCOMPARE(noteAt(model, 20), QStringLiteral("19"));
}

void TestConsoleModel::aCodeFamiliesShareIsNamedAsTheDeviceInTheFrameKnowsIt() {
    using protocol::Frame;
    link::FrameTap tap;
    ConsoleModel model(nullptr, 1000);
    model.attach(&tap);
    tap.tx(Frame::read("SPD").addressed(0, 10).encode());
    protocol::DecodeEvent answer;
    answer.frame = Frame{10, 0, protocol::Header::Answer, "SPD", "00100"};
    answer.raw = answer.frame.encode();
    tap.decoded(answer, false);
    tap.tx(Frame::read("SPD").addressed(0, 1).encode());
    model.flush();
    QCOMPARE(model.rowCount(), 3);
    const auto name = [&model](int row) {
        return model.data(model.index(row, ConsoleModel::Name), Qt::DisplayRole).toString();
    };
    // Nothing known of the devices yet: the name of some family that has the code.
    QVERIFY(!name(0).isEmpty());
    QSignalSpy renamed(&model, &ConsoleModel::dataChanged);
    model.setDeviceFamilies({{1, QStringLiteral("ALE")}, {10, QStringLiteral("SFR")}});
    QCOMPARE(renamed.count(), 1);
    QCOMPARE(name(0), QStringLiteral("Feeding speed"));    // the request to the feeder
    QCOMPARE(name(1), QStringLiteral("Feeding speed"));    // the feeder's answer
    QCOMPARE(name(2), QStringLiteral("Dispensing speed")); // the request to the ALE
    // Disconnected, then other devices at those addresses: the rows keep what they were.
    model.setDeviceFamilies({});
    model.setDeviceFamilies({{1, QStringLiteral("DME")}, {10, QStringLiteral("ALE")}});
    QCOMPARE(name(0), QStringLiteral("Feeding speed"));
    QCOMPARE(name(2), QStringLiteral("Dispensing speed"));
    tap.tx(Frame::read("SPD").addressed(0, 10).encode());
    model.flush();
    QCOMPARE(name(3), QStringLiteral("Dispensing speed")); // the new device at 10 is an ALE
}

void TestConsoleModel::receivedFramesAreLabelledRx() {
    link::FrameTap tap;
    ConsoleModel model;
    model.attach(&tap);
    tapOneOfEach(tap);
    model.flush();
    QCOMPARE(model.rowCount(), 5);
    QStringList directions;
    for (int row = 0; row < model.rowCount(); ++row)
        directions << cell(model, row, ConsoleModel::Direction);
    QCOMPARE(directions, QStringList({"TX", "RX chunk", "RX", "error", "note"}));
    QCOMPARE(cell(model, 2, ConsoleModel::Header), QStringLiteral("Answer"));
    QCOMPARE(cell(model, 3, ConsoleModel::Bcc), QStringLiteral("bad"));
}

void TestConsoleModel::theHeldCountFollowsWhatArrivesWhilePaused() {
    link::FrameTap tap;
    ConsoleModel model;
    model.attach(&tap);
    QSignalSpy held(&model, &ConsoleModel::heldCountChanged);
    QVERIFY(held.isValid());
    tap.note(QStringLiteral("shown"));
    QCOMPARE(model.heldCount(), 0);
    model.setPaused(true);
    for (int i = 1; i <= 3; ++i) {
        tap.note(QString::number(i));
        QCOMPARE(model.heldCount(), i);
        QCOMPARE(held.constLast().at(0).toInt(), i); // said as it happens, not on resume
    }
    model.setPaused(false);
    QCOMPARE(model.heldCount(), 0);
    QCOMPARE(held.constLast().at(0).toInt(), 0);
    QCOMPARE(model.rowCount(), 4);

    model.setPaused(true);
    tap.note(QStringLiteral("held, then cleared"));
    QCOMPARE(model.heldCount(), 1);
    model.clear();
    QCOMPARE(model.heldCount(), 0);
    QCOMPARE(held.constLast().at(0).toInt(), 0);
}

void TestConsoleModel::headersAreNamedInTheInterfaceLanguage_data() {
    QTest::addColumn<QString>("language");
    QTest::addColumn<QStringList>("headers"); // of the request sent and the answer received
    QTest::newRow("German") << "de" << QStringList{"Lesen", "Antwort"};
    QTest::newRow("Spanish") << "es" << QStringList{"Lectura", "Respuesta"};
}

void TestConsoleModel::headersAreNamedInTheInterfaceLanguage() {
    QFETCH(QString, language);
    QFETCH(QStringList, headers);
    QCOMPARE(i18n::installTranslators(*QCoreApplication::instance(), language), language);
    link::FrameTap tap;
    ConsoleModel model;
    model.attach(&tap);
    tapOneOfEach(tap);
    model.flush();
    QStringList shown;
    for (int row = 0; row < model.rowCount(); ++row)
        if (model.entry(row).frame)
            shown << cell(model, row, ConsoleModel::Header);
    const QString write = ConsoleModel::headerText(protocol::Header::Write);
    const QString nak = ConsoleModel::headerText(protocol::Header::Nak);
    const QString received = ConsoleModel::directionText(model::ConsoleEntry::Direction::Decoded);
    // Leave the application in English for whatever runs after this.
    qDeleteAll(QCoreApplication::instance()->findChildren<QTranslator *>());

    QCOMPARE(shown, headers);
    QVERIFY2(write != QLatin1String("Write") && !write.isEmpty(), qPrintable(write));
    QCOMPARE(nak, QStringLiteral("NAK")); // the protocol's word in every language
    QCOMPARE(received, QStringLiteral("RX"));
    QCOMPARE(ConsoleModel::headerText(protocol::Header::Read), QStringLiteral("Read"));
}

TIPSCOPE_TEST_MAIN(TestConsoleModel)

} // namespace tst_consolemodel
#include "tst_consolemodel.moc"
