// Min/max stretches of exactly computed values, for a derived quantity
// that has no pyramid of its own (or a stretch across a zero change):
// lost and undefined samples (NaN) are left out of a stretch's extremes.
#pragma once

#include "core/storage/SessionStore.h"

#include <cstdint>
#include <span>
#include <vector>

namespace tactiscope::core::derived {

// Appends about `stretches` stretches of `values`, whose first is sample `first`.
void appendExactOverview(std::span<const double> values, std::uint64_t first, std::size_t stretches,
                         std::vector<storage::OverviewPoint>& into);

}  // namespace tactiscope::core::derived
