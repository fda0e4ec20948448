#include "screenshots.h"

#include "devicetree.h"
#include "mainwindow.h"
#include "pages/page.h"

#include "sim/simline.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDir>
#include <QTabWidget>
#include <QTextStream>
#include <QTimer>

namespace tipscope::gui {

namespace {
constexpr int kWarmUpMs = 9000;
constexpr int kPerPageMs = 1500;

void save(MainWindow &window, const QString &path) {
    if (!window.grab().save(path))
        QTextStream(stderr) << "tipscope: cannot write " << path << Qt::endl;
    else
        QTextStream(stdout) << path << Qt::endl;
}

void shootPage(MainWindow &window, const QString &folder, int index) {
    QTabWidget &tabs = window.pages();
    if (index >= tabs.count()) {
        QApplication::quit();
        return;
    }
    // Select the device the page is for (the feeder page shows the feeder).
    if (auto *page = qobject_cast<Page *>(tabs.widget(index))) {
        QTreeWidgetItem *line = window.deviceTree().topLevelItem(0);
        for (int i = 0; line && i < line->childCount(); ++i) {
            model::DeviceModel *d = window.session().devices().value(i);
            if (d && page->appliesTo(d)) {
                window.deviceTree().setCurrentItem(line->child(i));
                break;
            }
        }
        if (!tabs.isTabVisible(index)) { // nothing on this line for it (the ALE's page)
            shootPage(window, folder, index + 1);
            return;
        }
    }
    tabs.setCurrentIndex(index);
    QTimer::singleShot(kPerPageMs, &window, [&window, folder, index] {
        const QString name = window.pages()
                                 .tabText(index)
                                 .toLower()
                                 .remove(QLatin1Char('&'))
                                 .replace(QLatin1Char(' '), QLatin1Char('-'));
        const QString stem =
            QStringLiteral("%1-%2").arg(index + 1, 2, 10, QLatin1Char('0')).arg(name);
        save(window, QDir(folder).filePath(stem + QStringLiteral(".png")));
        // The charts once more with the optional hardware curves, whose stats need more room.
        auto *hardware = window.pages().widget(index)->findChild<QAbstractButton *>(
            QStringLiteral("hardwareButton"));
        if (!hardware || hardware->isChecked()) {
            shootPage(window, folder, index + 1);
            return;
        }
        hardware->click();
        QTimer::singleShot(kPerPageMs, &window, [&window, folder, index, stem, hardware] {
            save(window, QDir(folder).filePath(stem + QStringLiteral("-hardware.png")));
            hardware->click();
            shootPage(window, folder, index + 1);
        });
    });
}
} // namespace

void takeScreenshots(MainWindow &window, const QString &folder) {
    QDir().mkpath(folder);
    window.resize(1360, 860);
    // Something worth seeing: a port in the stand, an injected port error.
    QTimer::singleShot(kWarmUpMs / 2, &window, [&window] {
        if (sim::SimLine *line = window.session().demoLine()) {
            line->station()->setStatus(3, 1);
            line->station()->setPortError(4, 4);
            line->station()->setTool(4, 0);
        }
    });
    QTimer::singleShot(kWarmUpMs, &window, [&window, folder] { shootPage(window, folder, 0); });
}

} // namespace tipscope::gui
