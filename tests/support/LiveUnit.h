// A live session's mode unit by its type (LiveSession::unitAs) for a test
// that knows the mode runs: a reference, and a thrown std::logic_error (a
// failed test, not a crash) when no unit of that type runs.
#pragma once

#include "devices/session/LiveSession.h"

#include <stdexcept>

namespace tactiscope::testing {

template <typename Unit>
const Unit& liveUnit(const devices::session::LiveSession& session)
{
    if (const auto* unit = session.unitAs<Unit>()) return *unit;
    throw std::logic_error("no live unit of that type runs on this device");
}

template <typename Unit>
Unit& liveUnit(devices::session::LiveSession& session)
{
    if (auto* unit = session.unitAs<Unit>()) return *unit;
    throw std::logic_error("no live unit of that type runs on this device");
}

}  // namespace tactiscope::testing
