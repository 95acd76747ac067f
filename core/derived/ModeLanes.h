// What a mode adds to a stored session's lanes: its physical quantities,
// before and after the stored channels, and the stored channels they
// replace. Each mode's definition (core/modes) points to the function that
// makes them; core/derived/SessionLanes puts them in order.
#pragma once

#include "core/storage/TraceWindow.h"

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace tactiscope::core::derived {

struct LaneOptions;

struct ModeLanes {
    std::vector<std::unique_ptr<storage::LaneSource>> before, after;
    std::vector<std::size_t> replaced;  // stored channels not shown on their own
    std::string basis;                  // what they were computed with
};

}  // namespace tactiscope::core::derived
