// DispensingPage on a real Session with a simulated ALE (tipscope-sim over TCP): the page is for
// the stations whose catalog entries have dispensing settings, shows them with the dispensing
// status, length and cycles, and starts and stops the wire feed.
#include "pages/dispensingpage.h"
#include "testmain.h"
#include "widgets/parametereditor.h"

#include "model/simfixture.h"
#include "support/ptyfixtures.h"

#include <QLabel>
#include <QTest>

namespace tst_dispensingpage {

using namespace tipscope;
using namespace tipscope::model;
using protocol::Role;
using tipscope::gui::DispensingPage;
using tipscope::gui::ParameterEditor;

namespace {
constexpr int kConnectMs = 60000;
constexpr int kReadMs = 30000;
} // namespace

class TestDispensingPage : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();

    void onlyAStationWithDispensingSettingsHasThePage();
    void theWireFeedSettingsAndStatusAreShown();
    void startAndStopReachTheStation();

private:
    [[nodiscard]] QString liveText() const;

    testing::SimProcess m_sim;
    std::unique_ptr<Session> m_session;
    std::unique_ptr<DispensingPage> m_page;
};

void TestDispensingPage::initTestCase() {
    QString error;
    const QString where = m_sim.start({QStringLiteral("--model"), QStringLiteral("ALE"),
                                       QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:0")},
                                      &error);
    QVERIFY2(!where.isEmpty(), qPrintable(error));
    m_session = std::make_unique<Session>();
    m_page = std::make_unique<DispensingPage>(*m_session);
    Session::Settings settings;
    settings.line.kind = link::LineSettings::Kind::Tcp;
    settings.line.tcpHost = where.section(QLatin1Char(':'), 0, 0);
    settings.line.tcpPort = quint16(where.section(QLatin1Char(':'), 1).toUInt());
    m_session->connectTo(settings);
    QTRY_VERIFY_WITH_TIMEOUT(
        m_session->state() == Session::State::Connected && m_session->station(), kConnectMs);
    m_page->setSelection(m_session->station(), 1);
    m_page->resize(1000, 700);
    m_page->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_page.get()));
}

void TestDispensingPage::cleanupTestCase() {
    m_page.reset();
    m_session.reset();
    m_sim.stop();
}

QString TestDispensingPage::liveText() const {
    for (const QLabel *label : m_page->findChildren<QLabel *>())
        if (label->text().contains(QStringLiteral(" · dispensed ")))
            return label->text();
    return {};
}

void TestDispensingPage::onlyAStationWithDispensingSettingsHasThePage() {
    QVERIFY(m_page->appliesTo(m_session->station()));
    testing::SimFixture dme(testing::singleDevice(QStringLiteral("DME")));
    QVERIFY(!m_page->appliesTo(dme.station().get()));
    testing::SimFixture sfr(testing::singleDevice(QStringLiteral("SFR")));
    QVERIFY(!m_page->appliesTo(sfr.feeder().get()));
    QVERIFY(!m_page->appliesTo(nullptr));
}

void TestDispensingPage::theWireFeedSettingsAndStatusAreShown() {
    QStringList shown;
    for (const ParameterEditor *e : m_page->findChildren<ParameterEditor *>())
        shown.append(QString::fromLatin1(e->parameter()->code()));
    QCOMPARE(shown, (QStringList{"MOD", "LEN", "SPD", "DIA", "BCK", "WCD"}));
    m_session->station()->refreshAll(link::Priority::UserRead);
    QTRY_VERIFY_WITH_TIMEOUT(liveText().startsWith(QStringLiteral("Stopped · dispensed ")),
                             kReadMs);
    QTRY_VERIFY_WITH_TIMEOUT(!liveText().contains(QStringLiteral("—")), kReadMs);
    QVERIFY2(liveText().endsWith(QStringLiteral(" cycles · fuse present")), qPrintable(liveText()));
}

void TestDispensingPage::startAndStopReachTheStation() {
    StationModel *ale = m_session->station();
    QCOMPARE(m_page->startDispensing(), QString());
    QSignalSpy started(ale->action(Role::Start), &Action::finished);
    QVERIFY(started.isValid());
    QVERIFY(started.wait());
    ale->parameter(Role::Feeding)->refresh();
    QTRY_VERIFY_WITH_TIMEOUT(liveText().startsWith(QStringLiteral("Running · ")), kReadMs);
    QCOMPARE(m_page->stopDispensing(), QString());
    QSignalSpy stopped(ale->action(Role::Stop), &Action::finished);
    QVERIFY(stopped.isValid());
    QVERIFY(stopped.wait());
    ale->parameter(Role::Feeding)->refresh();
    QTRY_VERIFY_WITH_TIMEOUT(liveText().startsWith(QStringLiteral("Stopped · ")), kReadMs);
}

TIPSCOPE_TEST_MAIN(TestDispensingPage)

} // namespace tst_dispensingpage
#include "tst_dispensingpage.moc"
