// The sites of a panel scan as JSON, the one form `detect --json`,
// `analyze --json` and `sessions show --json` print (a contract other tools
// read): "sites": [{"position_mm": X or null, "spread_mm": S, "crossings": N,
// "a_then_b": N, "b_then_a": N, "first_s": T, "last_s": T}] and the
// "sites_method" they were placed by.
#pragma once

#include "core/detector/DefectSites.h"
#include "core/text/JsonWriter.h"

namespace tactiscope::core::detector {

// Writes the keys "sites" and "sites_method" into the object being written.
void writeSitesJson(text::JsonWriter& json, const SiteGrouping& grouping);

}  // namespace tactiscope::core::detector
