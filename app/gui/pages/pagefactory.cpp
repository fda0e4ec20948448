#include "pagefactory.h"

#include "consolepage.h"
#include "counterspage.h"
#include "dispensingpage.h"
#include "errorspage.h"
#include "feederpage.h"
#include "jointspage.h"
#include "overviewpage.h"
#include "settingspage.h"

#include "charts/chartspage.h"

namespace tipscope::gui {

QList<Page *> createPages(model::Session &session, QWidget *parent) {
    auto *charts = new ChartsPage(session, parent);
    auto *joints = new JointsPage(session, parent);
    joints->setChartsPage(charts);
    return {new OverviewPage(session, parent),
            new SettingsPage(session, parent),
            new FeederPage(session, parent),
            new DispensingPage(session, parent),
            new CountersPage(session, parent),
            new ErrorsPage(session, parent),
            new ConsolePage(session, parent),
            charts,
            joints};
}

} // namespace tipscope::gui
