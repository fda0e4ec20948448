#include "demosession.h"

#include <QTest>

namespace tipscope::testing {

model::Session::Settings unpacedDemoSettings() {
    model::Session::Settings settings;
    settings.line.kind = link::LineSettings::Kind::Demo;
    settings.demoPaced = false;
    return settings;
}

bool connectUnpacedDemo(model::Session &session, int timeoutMs) {
    session.connectTo(unpacedDemoSettings());
    return QTest::qWaitFor(
        [&] {
            return session.state() == model::Session::State::Connected && session.station() &&
                   session.feeder();
        },
        timeoutMs);
}

} // namespace tipscope::testing
