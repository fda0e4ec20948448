// The demo line as the page tests use it: the built-in simulated DME and SFR, answering at once
// (Session::Settings::demoPaced off), so a page fills in milliseconds instead of waiting on a
// simulated 19200-baud wire. Tests of the wire's timing use the paced line or tipscope-sim.
#pragma once

#include "model/session.h"

namespace tipscope::testing {

[[nodiscard]] model::Session::Settings unpacedDemoSettings();
// Connects `session` to the unpaced demo line and waits until it is connected with its station
// and feeder; false when that does not happen within `timeoutMs`.
[[nodiscard]] bool connectUnpacedDemo(model::Session &session, int timeoutMs = 30000);

} // namespace tipscope::testing
