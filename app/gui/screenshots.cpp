#include "screenshots.h"

#include "charts/chartspage.h"
#include "devicetree.h"
#include "dialogs/profiledialog.h"
#include "linepages.h"
#include "mainwindow.h"
#include "pages/page.h"
#include "widgets/parametereditor.h"

#include "link/simtransport.h"
#include "protocol/valuecodec.h"
#include "sim/simline.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDir>
#include <QScreen>
#include <QTabWidget>
#include <QTextStream>
#include <QTimer>

namespace tipscope::gui {

namespace {
constexpr int kWarmUpMs = 9000;
constexpr int kPerPageMs = 1500;
constexpr int kSettingsReadMs = 12000; // at most, for every setting shown to be read
constexpr int kPollMs = 250;
constexpr int kUnpluggedMs = 2500;

void save(QWidget &widget, const QString &path) {
    if (!widget.grab().save(path))
        QTextStream(stderr) << "tipscope: cannot write " << path << Qt::endl;
    else
        QTextStream(stdout) << path << Qt::endl;
}

// The file name of a page, the same in every language: "01-overview" from OverviewPage.
QString stemOf(const QWidget *page, int index) {
    QString name = QString::fromLatin1(page->metaObject()->className())
                       .section(QStringLiteral("::"), -1)
                       .toLower();
    name.chop(QStringLiteral("page").size());
    return QStringLiteral("%1-%2").arg(index + 1, 2, 10, QLatin1Char('0')).arg(name);
}

// Whether every value the page shows for editing has been read (the Settings page reads them
// when it opens; a screenshot of "not read" everywhere shows nothing).
bool settled(const QWidget *page) {
    const auto editors = page->findChildren<ParameterEditor *>();
    return std::all_of(editors.begin(), editors.end(), [](const ParameterEditor *e) {
        return !e->parameter() || !e->parameter()->isReadable() || e->parameter()->value();
    });
}

class Shooter : public QObject {
public:
    Shooter(MainWindow &window, const QString &folder)
        : QObject(&window)
        , m_window(window)
        , m_folder(folder) {}

    void shootPage(int index);

private:
    void selectDeviceFor(Page *page);
    void whenSettled(int index, int waitedMs);
    void afterShot(int index);
    void shootDisconnected(int index);
    void shootProfile(int index);
    void whenCompared(int index, ProfileDialog *dialog, int waitedMs);
    void later(int ms, std::function<void()> f) { QTimer::singleShot(ms, this, std::move(f)); }
    [[nodiscard]] QString path(const QString &stem) const {
        return QDir(m_folder).filePath(stem + QStringLiteral(".png"));
    }

    MainWindow &m_window;
    QString m_folder;
};

void Shooter::selectDeviceFor(Page *page) {
    QTreeWidgetItem *line = m_window.deviceTree().topLevelItem(0);
    for (int i = 0; line && i < line->childCount(); ++i) {
        model::DeviceModel *d = m_window.session().devices().value(i);
        if (d && page->appliesTo(d)) {
            m_window.deviceTree().setCurrentItem(line->child(i));
            return;
        }
    }
}

void Shooter::shootPage(int index) {
    QTabWidget &tabs = m_window.pages();
    if (index >= tabs.count()) {
        QApplication::quit();
        return;
    }
    if (auto *page = qobject_cast<Page *>(tabs.widget(index))) {
        selectDeviceFor(page);           // the feeder page shows the feeder
        if (!tabs.isTabVisible(index)) { // nothing on this line for it (the ALE's page)
            shootPage(index + 1);
            return;
        }
    }
    tabs.setCurrentIndex(index);
    later(kPerPageMs, [this, index] { whenSettled(index, kPerPageMs); });
}

void Shooter::whenSettled(int index, int waitedMs) {
    QWidget *page = m_window.pages().widget(index);
    if (!settled(page) && waitedMs < kSettingsReadMs) {
        later(kPollMs, [this, index, waitedMs] { whenSettled(index, waitedMs + kPollMs); });
        return;
    }
    save(m_window, path(stemOf(page, index)));
    afterShot(index);
}

// Some pages once more in a state worth documenting.
void Shooter::afterShot(int index) {
    QWidget *page = m_window.pages().widget(index);
    const QString name = stemOf(page, index);
    if (name.endsWith(QLatin1String("-overview"))) {
        shootDisconnected(index);
        return;
    }
    if (name.endsWith(QLatin1String("-settings"))) {
        shootProfile(index);
        return;
    }
    // The charts with the optional hardware curves, whose stats need more room.
    auto *hardware = page->findChild<QAbstractButton *>(QStringLiteral("hardwareButton"));
    if (!hardware || hardware->isChecked()) {
        shootPage(index + 1);
        return;
    }
    hardware->click();
    later(kPerPageMs, [this, index, name, hardware, page] {
        save(m_window, path(name + QStringLiteral("-hardware")));
        // And what the PNG export makes of it, at its default size.
        if (auto *charts = qobject_cast<ChartsPage *>(page))
            if (const QString error = charts->exportPng(path(name + QStringLiteral("-export")));
                !error.isEmpty())
                qWarning("chart export: %s", qPrintable(error));
        hardware->click();
        shootPage(index + 1);
    });
}

// The line pulled: what a technician sees until it is back.
void Shooter::shootDisconnected(int index) {
    auto *transport =
        m_window.session().line()
            ? qobject_cast<link::SimTransport *>(&m_window.session().line()->transport())
            : nullptr;
    if (!transport) {
        shootPage(index + 1);
        return;
    }
    transport->setPlugged(false);
    later(kUnpluggedMs, [this, index, transport] {
        save(m_window,
             path(stemOf(m_window.pages().widget(index), index) + QStringLiteral("-disconnected")));
        transport->setPlugged(true);
        later(kUnpluggedMs, [this, index] { shootPage(index + 1); });
    });
}

// Two settings of the first port as a profile for another line might have them: the setpoint
// and the high alarm, found and encoded by the catalog for whatever family is connected.
void changeTwoSettings(model::Profile &profile, const model::StationModel &station) {
    const std::pair<protocol::Role, qint64> changes[] = {{protocol::Role::Setpoint, 320},
                                                         {protocol::Role::HighAlarm, 450}};
    for (const auto &[role, value] : changes) {
        const auto write =
            station.catalog().resolve(station.family(), role, 1, protocol::Direction::Write);
        if (!write)
            continue;
        const auto data = protocol::encodeWrite(*write, value);
        for (auto &[code, field] : profile.values)
            if (data && code == write->code)
                field = *data;
    }
}

// A profile against the station: two settings differ.
void Shooter::shootProfile(int index) {
    model::StationModel *st = m_window.session().station();
    if (!st) {
        shootPage(index + 1);
        return;
    }
    model::Profile profile = model::Profile::capture(*st);
    changeTwoSettings(profile, *st);
    profile.comment = QStringLiteral("line 3, lead-free");
    auto *dialog = new ProfileDialog(*st, profile, &m_window);
    dialog->resize(m_window.width() * 3 / 4, m_window.height() * 3 / 4);
    dialog->show();
    later(kPerPageMs, [this, index, dialog] { whenCompared(index, dialog, kPerPageMs); });
}

// The comparison reads every setting first; the table is worth a picture once it is there.
void Shooter::whenCompared(int index, ProfileDialog *dialog, int waitedMs) {
    if (dialog->isRunning() && waitedMs < kSettingsReadMs) {
        later(kPollMs,
              [this, index, dialog, waitedMs] { whenCompared(index, dialog, waitedMs + kPollMs); });
        return;
    }
    save(*dialog, path(stemOf(m_window.pages().widget(index), index) + QStringLiteral("-profile")));
    dialog->deleteLater();
    shootPage(index + 1);
}

// A workspace: its fleet overview, and the first station of its first line on the Charts page.
void shootWorkspace(MainWindow &window, const QString &folder) {
    const auto shot = [folder](QWidget &widget, const QString &stem) {
        save(widget, QDir(folder).filePath(stem + QStringLiteral(".png")));
    };
    QTimer::singleShot(kWarmUpMs, &window, [&window, shot] {
        window.deviceTree().selectFleet();
        QTimer::singleShot(kPerPageMs, &window, [&window, shot] {
            shot(window, QStringLiteral("10-fleet"));
            model::Session *first =
                window.workspace().count() > 0 ? window.workspace().session(0) : nullptr;
            if (!first || first->devices().isEmpty()) {
                QApplication::quit();
                return;
            }
            window.deviceTree().select(0, first->devices().first());
            window.linePages(0).showPage(ChartsPage::tr("Charts"));
            QTimer::singleShot(kWarmUpMs, &window, [&window, shot] {
                shot(window, QStringLiteral("10-fleet-charts"));
                QApplication::quit();
            });
        });
    });
}
} // namespace

void takeScreenshots(MainWindow &window, const QString &folder) {
    QDir().mkpath(folder);
    // The window is the screen (the size a tester chose for the virtual display), whole.
    if (const QScreen *screen = window.screen())
        window.setGeometry(screen->geometry());
    if (window.workspace().count() > 0) {
        shootWorkspace(window, folder);
        return;
    }
    // Something worth seeing: a port in the stand, an injected port error.
    QTimer::singleShot(kWarmUpMs / 2, &window, [&window] {
        if (sim::SimLine *line = window.session().demoLine()) {
            line->station()->setStatus(3, 1);
            line->station()->setPortError(4, 4);
            line->station()->setTool(4, 0);
        }
    });
    auto *shooter = new Shooter(window, folder);
    QTimer::singleShot(kWarmUpMs, shooter, [shooter] { shooter->shootPage(0); });
}

} // namespace tipscope::gui
