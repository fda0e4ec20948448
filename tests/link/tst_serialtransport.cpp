// SerialTransport on the PTY of a real tipscope-sim: it opens, carries a request and its answer,
// and explains a pulled cable in words a person understands.
#include "link/serialtransport.h"
#include "protocol/frame.h"
#include "ptyfixtures.h"
#include "testmain.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

namespace tst_serialtransport {

using namespace tipscope::link;
using tipscope::testing::SimProcess;

namespace {
constexpr int kWaitMs = 10000; // a generous ceiling for "eventually", never asserted on
} // namespace

class TestSerialTransport : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void opensAndCarriesARequestAndItsAnswer();
    void unpluggedPortIsSaidToHaveDisappeared();
};

namespace {

// tipscope-sim serving a DME on a PTY, reached through a link in a folder of its own.
struct SimPty {
    SimPty() {
        settings.portName = dir.filePath(QStringLiteral("tty"));
        QString error;
        if (sim.start({"--model", "DME", "--pty", "--link", settings.portName}, &error).isEmpty())
            qWarning("%s", qPrintable(error));
    }
    QTemporaryDir dir;
    SimProcess sim;
    SerialSettings settings;
};

} // namespace

void TestSerialTransport::opensAndCarriesARequestAndItsAnswer() {
    SimPty pty;
    SerialTransport t(pty.settings);
    QSignalSpy opened(&t, &Transport::opened);
    QSignalSpy received(&t, &Transport::received);
    QVERIFY(opened.isValid() && received.isValid());
    t.open();
    QCOMPARE(opened.count(), 1);
    t.write(tipscope::protocol::Frame::read("SMN").addressed(0, 1).encode());
    QByteArray got;
    QTRY_VERIFY_WITH_TIMEOUT(
        [&] {
            for (const QList<QVariant> &chunk : received)
                got += chunk.first().toByteArray();
            received.clear();
            return got.contains("DME-2C");
        }(),
        kWaitMs);
}

// The system's text for a vanished PTY or USB adapter is the failing ioctl's: "Inappropriate
// ioctl for device".
void TestSerialTransport::unpluggedPortIsSaidToHaveDisappeared() {
    SimPty pty;
    SerialTransport t(pty.settings);
    QSignalSpy lost(&t, &Transport::disconnected);
    QVERIFY(lost.isValid());
    t.open();
    QVERIFY(t.isOpen());
    QCOMPARE(pty.sim.command(QStringLiteral("unplug")), QStringLiteral("ok"));
    QVERIFY(lost.wait(kWaitMs));
    const QString why = lost.first().first().toString();
    QCOMPARE(why,
             QStringLiteral("the port %1 disappeared (unplugged?)").arg(pty.settings.portName));
    QVERIFY(!t.isOpen());
    QTest::qWait(200);
    QCOMPARE(lost.count(), 1);
}

TIPSCOPE_TEST_GUILESS_MAIN(TestSerialTransport)

} // namespace tst_serialtransport
#include "tst_serialtransport.moc"
