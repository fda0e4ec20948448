// The raw console's composition rules without a widget: what is encoded and what is refused
// (with the reason), the catalog's advice that never blocks, addressing from the device, the
// command list of the device's family, and raw hex read for people.
#include "i18n/translations.h"
#include "model/console/framecomposer.h"
#include "testmain.h"

#include "protocol/framedecoder.h"
#include "protocol/hexbytes.h"

#include <QTest>

namespace tst_framecomposer {

using namespace tipscope;
using model::FrameComposer;
using model::FrameTarget;
using protocol::Header;

namespace {
Header headerOf(QChar c) {
    return c == QLatin1Char('W') ? Header::Write : Header::Read;
}

// A DME at 01, a feeder at 10, and a device of a family the catalog does not know.
FrameComposer lineOfThree(int robotAddress) {
    FrameComposer composer;
    composer.setTargets({{QStringLiteral("01 DME-2C"), 1, QStringLiteral("DME")},
                         {QStringLiteral("10 SFR-A"), 10, QStringLiteral("SFR")},
                         {QStringLiteral("XYZ-1 (no address)"), std::nullopt, QString()}});
    composer.setRobotAddress(robotAddress);
    return composer;
}

QStringList codes(const QList<model::CommandChoice> &choices) {
    QStringList out;
    for (const model::CommandChoice &c : choices)
        out.append(c.code);
    return out;
}
} // namespace

class TestFrameComposer : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void composeEncodesWhatCanBeEncoded_data();
    void composeEncodesWhatCanBeEncoded();
    void refusalsSayWhyNothingCanBeSent_data();
    void refusalsSayWhyNothingCanBeSent();
    void catalogAdviceWarnsButNeverBlocks_data();
    void catalogAdviceWarnsButNeverBlocks();
    void framesGoFromTheRobotToTheDeviceChosen();
    void withoutADeviceNothingCanBeComposed();
    void commandsAreTheDeviceFamilysForTheHeader();
    void theListStartsFromTheIdentityRead();
    void aPickedCommandBringsTheDataItTakes();
    void thePickedLabelGivesItsCode();
    void rawHexSaysWhatTheBytesAre_data();
    void rawHexSaysWhatTheBytesAre();
    void theRawHexExampleIsAValidReadOfTheModelName();
};

void TestFrameComposer::initTestCase() {
    // English counts ("11 bytes") come from the English plurals catalogue, as in the programs.
    QCOMPARE(i18n::installTranslators(*QCoreApplication::instance(), QStringLiteral("en")),
             QStringLiteral("en"));
}

void TestFrameComposer::composeEncodesWhatCanBeEncoded_data() {
    QTest::addColumn<int>("target"); // -1: no addresses
    QTest::addColumn<QChar>("header");
    QTest::addColumn<QString>("command");
    QTest::addColumn<QString>("data");
    QTest::addColumn<QByteArray>("hex");

    const QChar w(QLatin1Char('W')), r(QLatin1Char('R'));
    // The guide's worked frames.
    QTest::newRow("addressed write, guide example")
        << 1 << w << "MAT"
        << "00375" << QByteArray("0230303031574D41543030333735033E");
    QTest::newRow("write without addresses, guide example")
        << -1 << w << "MAT"
        << "00375" << QByteArray("02574D41543030333735033F");
    QTest::newRow("read of the model name") << 1 << r << "SMN"
                                            << "" << QByteArray("023030303152534D4E0302");
    QTest::newRow("an action with its own data field")
        << 1 << w << "NVS"
        << "00000" << QByteArray("0230303031574E56533030303030032C");
    QTest::newRow("padding around the command is dropped")
        << 1 << r << " SMN "
        << "" << QByteArray("023030303152534D4E0302");
}

void TestFrameComposer::composeEncodesWhatCanBeEncoded() {
    QFETCH(int, target);
    QFETCH(QChar, header);
    QFETCH(QString, command);
    QFETCH(QString, data);
    QFETCH(QByteArray, hex);

    model::FrameInput in;
    if (target >= 0)
        in.target = target;
    in.family = QStringLiteral("DME");
    in.header = headerOf(header);
    in.command = command;
    in.data = data;
    const model::FrameDraft draft = FrameComposer::compose(in);
    QVERIFY2(draft.encodable, qPrintable(draft.problem));
    QVERIFY(draft.problem.isEmpty());
    QVERIFY2(!draft.warning, qPrintable(draft.hint));
    QVERIFY(!draft.hint.isEmpty()); // the command's name and description
    QCOMPARE(draft.frame.encode().toHex().toUpper(), hex);
    QVERIFY(protocol::parseFrame(draft.frame.encode()).ok());
}

void TestFrameComposer::refusalsSayWhyNothingCanBeSent_data() {
    QTest::addColumn<int>("source");
    QTest::addColumn<int>("target"); // -1: no addresses
    QTest::addColumn<QString>("command");
    QTest::addColumn<QString>("data");
    QTest::addColumn<QString>("reason");

    QTest::newRow("two-character command") << 0 << 1 << "SM"
                                           << ""
                                           << "3 printable characters";
    QTest::newRow("four-character command") << 0 << 1 << "SMNX"
                                            << ""
                                            << "3 printable characters";
    QTest::newRow("empty command") << 0 << 1 << ""
                                   << ""
                                   << "3 printable characters";
    QTest::newRow("control character in the command") << 0 << 1 << QStringLiteral("S\tN") << ""
                                                      << "3 printable characters";
    QTest::newRow("control character in data") << 0 << 1 << "MAT"
                                               << QString::fromLatin1("003\x03"
                                                                      "5")
                                               << "printable ASCII";
    QTest::newRow("non-ASCII data")
        << 0 << 1 << "MAT" << QStringLiteral("00°75") << "printable ASCII";
    QTest::newRow("target above 99") << 0 << 100 << "SMN"
                                     << ""
                                     << "00 to 99";
    QTest::newRow("negative target") << 0 << -2 << "SMN"
                                     << ""
                                     << "00 to 99";
    QTest::newRow("robot address above 99") << 100 << 1 << "SMN"
                                            << ""
                                            << "00 to 99";
}

void TestFrameComposer::refusalsSayWhyNothingCanBeSent() {
    QFETCH(int, source);
    QFETCH(int, target);
    QFETCH(QString, command);
    QFETCH(QString, data);
    QFETCH(QString, reason);

    model::FrameInput in;
    in.source = source;
    if (target != -1)
        in.target = target;
    in.family = QStringLiteral("DME");
    in.header = data.isEmpty() ? Header::Read : Header::Write;
    in.command = command;
    in.data = data;
    const model::FrameDraft draft = FrameComposer::compose(in);
    QVERIFY(!draft.encodable);
    QVERIFY2(draft.problem.startsWith(QLatin1String("Not sendable: ")), qPrintable(draft.problem));
    QVERIFY2(draft.problem.contains(reason), qPrintable(draft.problem));
}

void TestFrameComposer::catalogAdviceWarnsButNeverBlocks_data() {
    QTest::addColumn<QString>("family");
    QTest::addColumn<QChar>("header");
    QTest::addColumn<QString>("command");
    QTest::addColumn<QString>("data");
    QTest::addColumn<QString>("advice");

    const QChar w(QLatin1Char('W')), r(QLatin1Char('R'));
    QTest::newRow("out of range") << "DME" << w << "MAT"
                                  << "00900"
                                  << "Catalog check:";
    QTest::newRow("off the step") << "DME" << w << "MAT"
                                  << "00377"
                                  << "Catalog check:";
    QTest::newRow("short number") << "DME" << w << "MAT"
                                  << "375"
                                  << "On the wire this value is written 00375.";
    QTest::newRow("not a number") << "DME" << w << "MAT"
                                  << "abc"
                                  << "Catalog check:";
    QTest::newRow("write without data") << "DME" << w << "MAT"
                                        << ""
                                        << "A write needs a data field";
    QTest::newRow("action with other data") << "DME" << w << "NVS"
                                            << "00001"
                                            << "NVS carries the data field 00000.";
    QTest::newRow("dangerous action") << "DME" << w << "RSP"
                                      << "00000"
                                      << "Dangerous:";
    QTest::newRow("dangerous action with other data") << "DME" << w << "RSP"
                                                      << "1"
                                                      << "carries the data field 00000";
    QTest::newRow("unknown command") << "DME" << r << "XYZ"
                                     << ""
                                     << "XYZ is not a DME read command in the catalog.";
    QTest::newRow("a read-only code written") << "DME" << w << "SMN"
                                              << "00001"
                                              << "SMN is not a DME write command";
    QTest::newRow("lower case") << "DME" << r << "smn"
                                << ""
                                << "Did you mean SMN?";
    QTest::newRow("read with data") << "DME" << r << "SMN"
                                    << "1"
                                    << "Reads carry no data field";
    QTest::newRow("another family's code") << "SFR" << r << "ST1"
                                           << ""
                                           << "ST1 is not a SFR read command";
    QTest::newRow("unknown family") << "" << r << "SMN"
                                    << ""
                                    << "Unknown device family";
}

void TestFrameComposer::catalogAdviceWarnsButNeverBlocks() {
    QFETCH(QString, family);
    QFETCH(QChar, header);
    QFETCH(QString, command);
    QFETCH(QString, data);
    QFETCH(QString, advice);

    model::FrameInput in;
    in.target = 1;
    in.family = family;
    in.header = headerOf(header);
    in.command = command;
    in.data = data;
    const model::FrameDraft draft = FrameComposer::compose(in);
    QVERIFY2(draft.encodable, qPrintable(draft.problem));
    QVERIFY2(draft.warning, qPrintable(draft.hint));
    QVERIFY2(draft.hint.contains(advice), qPrintable(draft.hint));
    // Sent as typed: never "corrected".
    QCOMPARE(draft.frame.command, command.trimmed().toLatin1());
    QCOMPARE(draft.frame.data, data.toLatin1());
}

void TestFrameComposer::framesGoFromTheRobotToTheDeviceChosen() {
    const FrameComposer composer = lineOfThree(7);
    const model::FrameDraft toFeeder =
        composer.compose(1, Header::Read, QStringLiteral("SPD — Feeding speed"), {});
    QVERIFY2(toFeeder.encodable, qPrintable(toFeeder.problem));
    QCOMPARE(toFeeder.frame.source, std::optional<int>(7));
    QCOMPARE(toFeeder.frame.target, std::optional<int>(10));
    QCOMPARE(toFeeder.frame.command, QByteArray("SPD"));
    QVERIFY2(toFeeder.hint.startsWith(QLatin1String("Feeding speed:")), qPrintable(toFeeder.hint));

    // The device on a line without addresses gets a frame without them, and a family the
    // catalog does not know is a warning, not a refusal.
    const model::FrameDraft bare = composer.compose(2, Header::Read, QStringLiteral("SMN"), {});
    QVERIFY(bare.encodable);
    QVERIFY(!bare.frame.isAddressed());
    QVERIFY(bare.warning);
    QCOMPARE(bare.frame.encode(), protocol::Frame::read("SMN").encode());
}

void TestFrameComposer::withoutADeviceNothingCanBeComposed() {
    FrameComposer composer;
    for (int target : {-1, 0, 3}) {
        const model::FrameDraft draft =
            composer.compose(target, Header::Read, QStringLiteral("SMN"), {});
        QVERIFY(!draft.encodable);
        QVERIFY2(draft.problem.contains(QLatin1String("No device is known")),
                 qPrintable(draft.problem));
    }
    QVERIFY(composer.commands(0, Header::Read).isEmpty());
    QVERIFY(composer.firstCommand(0, Header::Read).isEmpty());
}

void TestFrameComposer::commandsAreTheDeviceFamilysForTheHeader() {
    const FrameComposer composer = lineOfThree(0);
    const QStringList stationReads = codes(composer.commands(0, Header::Read));
    const QStringList stationWrites = codes(composer.commands(0, Header::Write));
    const QStringList feederWrites = codes(composer.commands(1, Header::Write));
    QVERIFY(stationReads.contains(QLatin1String("SMN")));
    QVERIFY(stationReads.contains(QLatin1String("ST4"))); // ports expanded: the DME has four
    QVERIFY(!stationReads.contains(QLatin1String("ST5")));
    QVERIFY(!stationWrites.contains(QLatin1String("SMN"))); // read-only
    QVERIFY(stationWrites.contains(QLatin1String("MAT")));
    QVERIFY(!feederWrites.contains(QLatin1String("MAT")));
    QVERIFY(feederWrites.contains(QLatin1String("SPD")));
    QVERIFY(composer.commands(2, Header::Read).isEmpty()); // the catalog knows no such family
    for (const model::CommandChoice &c : composer.commands(1, Header::Write))
        if (c.code == QLatin1String("SPD"))
            QCOMPARE(c.label, QStringLiteral("SPD — Feeding speed")); // the feeder's own name
}

void TestFrameComposer::theListStartsFromTheIdentityRead() {
    const FrameComposer composer = lineOfThree(0);
    QCOMPARE(composer.firstCommand(0, Header::Read), QStringLiteral("SMN"));
    QCOMPARE(composer.firstCommand(1, Header::Read), QStringLiteral("SMN"));
    // Nothing identifies a device by writing: the list's first entry.
    QCOMPARE(composer.firstCommand(0, Header::Write),
             composer.commands(0, Header::Write).constFirst().code);
    QVERIFY(composer.firstCommand(2, Header::Read).isEmpty());
}

void TestFrameComposer::aPickedCommandBringsTheDataItTakes() {
    const FrameComposer composer = lineOfThree(0);
    QCOMPARE(composer.dataOfPicked(0, Header::Read, QStringLiteral("ST1 — Selected temperature")),
             std::optional<QString>(QString()));
    QCOMPARE(composer.dataOfPicked(0, Header::Write, QStringLiteral("NVS")),
             std::optional<QString>(QStringLiteral("00000")));
    QCOMPARE(composer.dataOfPicked(1, Header::Write, QStringLiteral("CTP")),
             std::optional<QString>(QStringLiteral("00000")));
    // A value is the person's to type: whatever is there stays.
    QCOMPARE(composer.dataOfPicked(0, Header::Write, QStringLiteral("MAT")), std::nullopt);
}

void TestFrameComposer::thePickedLabelGivesItsCode() {
    QCOMPARE(FrameComposer::codeOf(QStringLiteral("ST1 — Selected temperature")),
             QStringLiteral("ST1"));
    QCOMPARE(FrameComposer::codeOf(QStringLiteral(" xyz ")), QStringLiteral("xyz"));
    QCOMPARE(FrameComposer::codeOf(QString()), QString());
}

void TestFrameComposer::rawHexSaysWhatTheBytesAre_data() {
    QTest::addColumn<QString>("hex");
    QTest::addColumn<bool>("bytes");
    QTest::addColumn<bool>("frame");
    QTest::addColumn<QString>("text");

    QTest::newRow("a valid read") << "02 30 30 30 31 52 53 4D 4E 03 02" << true << true
                                  << "11 bytes, a valid frame: 00→01 R SMN";
    QTest::newRow("a wrong BCC") << "02 30 30 30 31 52 53 4D 4E 03 5E" << true << false
                                 << "11 bytes, not a valid frame (BCC is 5e, expected 02)";
    QTest::newRow("one byte") << "06" << true << false << "1 byte, not a valid frame";
    QTest::newRow("a bad digit") << "02 30 4G" << false << false << "'G'";
    QTest::newRow("nothing") << "" << false << false << "no bytes";
}

void TestFrameComposer::rawHexSaysWhatTheBytesAre() {
    QFETCH(QString, hex);
    QFETCH(bool, bytes);
    QFETCH(bool, frame);
    QFETCH(QString, text);

    const model::RawHex raw = FrameComposer::readHex(hex);
    QCOMPARE(raw.bytes.has_value(), bytes);
    QCOMPARE(raw.frame.has_value(), frame);
    QCOMPARE(raw.warning, bytes && !frame);
    QVERIFY2(raw.text.contains(text), qPrintable(raw.text));
    QVERIFY(!raw.text.isEmpty());
}

void TestFrameComposer::theRawHexExampleIsAValidReadOfTheModelName() {
    const auto bytes = protocol::parseHexBytes(FrameComposer::exampleHex());
    QVERIFY(bytes);
    const auto frame = protocol::parseFrame(*bytes);
    QVERIFY2(frame, qPrintable(frame.error().why));
    QCOMPARE(*frame, protocol::Frame::read("SMN").addressed(0, 1));
}

TIPSCOPE_TEST_MAIN(TestFrameComposer)

} // namespace tst_framecomposer
#include "tst_framecomposer.moc"
