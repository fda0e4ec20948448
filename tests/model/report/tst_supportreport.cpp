// The support report on a real Session in demo mode (the simulated DME at 01 and SFR at 10):
// what support staff read in it names each setting's tool and port, says what to check for an
// error, carries the UTC offset on every time, collapses a flood into one line, leaves nothing
// blank that is not known, and gives each line of a workspace its own part under its names.
#include "model/report/supportreport.h"
#include "testmain.h"

#include "model/session.h"
#include "sim/simline.h"

#include <QJsonArray>
#include <QRegularExpression>
#include <QTest>

namespace tst_supportreport {

using namespace tipscope;
using namespace tipscope::model;
using protocol::Role;

namespace {
constexpr int kConnectMs = 60000;
constexpr int kReadMs = 30000;

// An ISO time with its offset from UTC ("…T10:02:03.123+02:00" or "…Z").
bool hasOffset(const QString &time) {
    static const QRegularExpression offset(QStringLiteral("T\\d\\d:\\d\\d:\\d\\d(\\.\\d+)?"
                                                          "([+-]\\d\\d:\\d\\d|Z)$"));
    return offset.match(time).hasMatch();
}
} // namespace

class TestSupportReport : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();

    void aPortErrorComesWithWhatToCheck();
    void perPortSettingsNameTheirPort();
    void everyTimeCarriesItsOffsetFromUtc();
    void aFloodIsOneLineWithItsCountAndSpan();
    void whatIsNotKnownIsLeftOutNotBlank();
    void aWorkspaceLineComesUnderItsNamesWithItsOwnDevicesAndEvents();
    void anUnusedBarLineBesideAWorkspaceIsLeftOut();

private:
    [[nodiscard]] QJsonObject device(const QJsonObject &report, const QString &family) const;
    std::unique_ptr<Session> m_session;
};

void TestSupportReport::init() {
    m_session = std::make_unique<Session>();
    m_session->scheduler().setInterval(PollClass::Status, 200);
    Session::Settings settings;
    settings.line.kind = link::LineSettings::Kind::Demo;
    m_session->connectTo(settings);
    QTRY_VERIFY_WITH_TIMEOUT(m_session->station() && m_session->feeder(), kConnectMs);
}

void TestSupportReport::cleanup() {
    m_session.reset();
}

QJsonObject TestSupportReport::device(const QJsonObject &report, const QString &family) const {
    for (const QJsonValue &d : report.value(QStringLiteral("devices")).toArray())
        if (d.toObject().value(QStringLiteral("family")).toString() == family)
            return d.toObject();
    return {};
}

void TestSupportReport::aPortErrorComesWithWhatToCheck() {
    StationModel *station = m_session->station();
    QTRY_COMPARE_WITH_TIMEOUT(station->number(Role::Error, 2), std::optional<qint64>(0), kReadMs);
    QVERIFY(device(supportReportJson(*m_session), QStringLiteral("DME"))
                .value(QStringLiteral("whatToCheck"))
                .toArray()
                .isEmpty());

    m_session->demoLine()->station()->setPortError(2, 1);
    QTRY_COMPARE_WITH_TIMEOUT(station->number(Role::Error, 2), std::optional<qint64>(1), kReadMs);
    const QJsonObject report = supportReportJson(*m_session);
    const QJsonArray advice =
        device(report, QStringLiteral("DME")).value(QStringLiteral("whatToCheck")).toArray();
    QCOMPARE(advice.size(), 1);
    const QJsonObject check = advice.first().toObject();
    QVERIFY2(check.value(QStringLiteral("label")).toString().endsWith(QStringLiteral("port 2")),
             qPrintable(check.value(QStringLiteral("label")).toString()));
    QVERIFY(check.value(QStringLiteral("check"))
                .toString()
                .contains(QStringLiteral("cartridge is seated")));
    const QString text = supportReportText(report);
    QVERIFY2(text.contains(QStringLiteral("What to check:")), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("(Short circuit): The heater circuit")),
             qPrintable(text));
}

void TestSupportReport::perPortSettingsNameTheirPort() {
    StationModel *station = m_session->station();
    station->refreshAll();
    QTRY_VERIFY_WITH_TIMEOUT(station->number(Role::Setpoint, 4).has_value(), kReadMs);
    const QString text = supportReportText(supportReportJson(*m_session));
    QStringList lines;
    for (const QString &line : text.split(QLatin1Char('\n')))
        if (line.contains(QStringLiteral("Selected temperature")))
            lines.append(line);
    QVERIFY2(lines.size() >= 4, qPrintable(text));
    // Four ports, four different lines: each names its port.
    lines.removeDuplicates();
    for (int port = 1; port <= 4; ++port)
        QVERIFY2(lines.filter(QStringLiteral("port %1:").arg(port)).size() == 1,
                 qPrintable(lines.join(QLatin1Char('\n'))));
}

void TestSupportReport::everyTimeCarriesItsOffsetFromUtc() {
    m_session->eventLog().add(Event::Kind::Write, Event::Severity::Info, QStringLiteral("test"),
                              QStringLiteral("something happened"));
    const QJsonObject report = supportReportJson(*m_session);
    QVERIFY2(hasOffset(report.value(QStringLiteral("created")).toString()),
             qPrintable(report.value(QStringLiteral("created")).toString()));
    const QJsonArray events = report.value(QStringLiteral("events")).toArray();
    QVERIFY(!events.isEmpty());
    for (const QJsonValue &e : events)
        QVERIFY2(hasOffset(e.toObject().value(QStringLiteral("time")).toString()),
                 qPrintable(e.toObject().value(QStringLiteral("time")).toString()));
    for (const QJsonValue &v :
         device(report, QStringLiteral("DME")).value(QStringLiteral("values")).toArray())
        QVERIFY2(hasOffset(v.toObject().value(QStringLiteral("updated")).toString()),
                 qPrintable(v.toObject().value(QStringLiteral("updated")).toString()));
}

void TestSupportReport::aFloodIsOneLineWithItsCountAndSpan() {
    for (int i = 0; i < 75; ++i)
        m_session->eventLog().add(Event::Kind::Communication, Event::Severity::Warning,
                                  QStringLiteral("DME-2C at 01"),
                                  QStringLiteral("not sent: the line is not connected"));
    const QJsonObject report = supportReportJson(*m_session);
    const QJsonObject last = report.value(QStringLiteral("events")).toArray().last().toObject();
    QCOMPARE(last.value(QStringLiteral("count")).toInt(), 75);
    QVERIFY(hasOffset(last.value(QStringLiteral("lastTime")).toString()));
    const QString text = supportReportText(report);
    QCOMPARE(text.count(QStringLiteral("not sent: the line is not connected")), 1);
    QVERIFY2(text.contains(QStringLiteral("not sent: the line is not connected (75 times, until ")),
             qPrintable(text));
}

void TestSupportReport::whatIsNotKnownIsLeftOutNotBlank() {
    QJsonObject report = supportReportJson(*m_session);
    QJsonArray devices = report.value(QStringLiteral("devices")).toArray();
    QJsonObject feeder = devices.last().toObject();
    feeder.insert(QStringLiteral("softwareVersion"), QString());
    devices.replace(devices.size() - 1, feeder);
    report.insert(QStringLiteral("devices"), devices);
    const QString text = supportReportText(report);
    for (const QString &line : text.split(QLatin1Char('\n'))) {
        QVERIFY2(!line.endsWith(QLatin1Char(' ')) && !line.contains(QStringLiteral(" ,")) &&
                     !line.contains(QStringLiteral("()")),
                 qPrintable(line));
        if (line.startsWith(QStringLiteral("Device ")) &&
            line.contains(feeder.value(QStringLiteral("model")).toString()))
            QVERIFY2(!line.contains(QStringLiteral("software")), qPrintable(line));
    }
}

void TestSupportReport::aWorkspaceLineComesUnderItsNamesWithItsOwnDevicesAndEvents() {
    Session cell;
    Session::Settings settings;
    settings.line.kind = link::LineSettings::Kind::Demo;
    cell.connectTo(settings);
    QTRY_VERIFY_WITH_TIMEOUT(cell.station() && cell.feeder(), kConnectMs);
    cell.eventLog().add(Event::Kind::Write, Event::Severity::Info, QStringLiteral("DME-2C at 01"),
                        QStringLiteral("happened on cell-3 only"));

    const QJsonObject report = supportReportJson(
        *m_session,
        {{QStringLiteral("cell-3"), QStringLiteral("Cell 3"), QStringLiteral("Hall B"), &cell}});
    const QJsonArray lines = report.value(QStringLiteral("lines")).toArray();
    QCOMPARE(lines.size(), 1);
    const QJsonObject line = lines.first().toObject();
    QCOMPARE(line.value(QStringLiteral("name")).toString(), QStringLiteral("cell-3"));
    QCOMPARE(line.value(QStringLiteral("location")).toString(), QStringLiteral("Hall B"));
    QVERIFY(!line.value(QStringLiteral("line"))
                 .toObject()
                 .value(QStringLiteral("summary"))
                 .toString()
                 .isEmpty());
    QStringList families;
    for (const QJsonValue &d : line.value(QStringLiteral("devices")).toArray())
        families << d[QStringLiteral("family")].toString();
    QCOMPARE(families, QStringList({"DME", "SFR"}));
    const auto mentions = [](const QJsonArray &events) {
        for (const QJsonValue &e : events)
            if (e[QStringLiteral("text")].toString() == QLatin1String("happened on cell-3 only"))
                return true;
        return false;
    };
    QVERIFY(mentions(line.value(QStringLiteral("events")).toArray()));
    QVERIFY(!mentions(report.value(QStringLiteral("events")).toArray())); // not the bar line's

    // People read the line's part under its names, its events with it.
    const QString text = supportReportText(report);
    const qsizetype heading =
        text.indexOf(QStringLiteral("Workspace line cell-3 (Cell 3, Hall B)"));
    const qsizetype event = text.indexOf(QStringLiteral("happened on cell-3 only"));
    const qsizetype barEvents = text.indexOf(QStringLiteral("\nRecent events:"));
    QVERIFY2(heading > 0 && heading < event && event < barEvents, qPrintable(text));
    QVERIFY2(text.indexOf(QStringLiteral("Device 01: DME-2C"), heading) > heading,
             qPrintable(text));
}

void TestSupportReport::anUnusedBarLineBesideAWorkspaceIsLeftOut() {
    Session unused;
    const QString text = supportReportText(
        supportReportJson(unused, {{QStringLiteral("cell-3"), {}, {}, m_session.get()}}));
    QVERIFY2(text.contains(QStringLiteral("\nWorkspace line cell-3\nLine: ")), qPrintable(text));
    QCOMPARE(text.count(QStringLiteral("\nLine: ")), 1); // the workspace line's alone
    for (const QString &line : text.split(QLatin1Char('\n')))
        QVERIFY2(!line.endsWith(QLatin1Char(' ')) && !line.contains(QStringLiteral("()")),
                 qPrintable(line));
}

TIPSCOPE_TEST_MAIN(TestSupportReport)

} // namespace tst_supportreport
#include "tst_supportreport.moc"
