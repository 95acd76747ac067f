// A session's verdict trail in words, for the report, the review window and
// `sessions show`: who decided what, when, on what grounds and why, e.g.
//   automatic: defects found (live detector: 21 defects at 3 sites, threshold 0.85), 2026-11-23 14:12 UTC
//   operator Ada kept it, 14:13 UTC
//   reviewer Q. Engineer changed it to pass, 2026-11-24 16:02 UTC: "bump is a marker pen line"
#pragma once

#include "core/storage/SessionRecords.h"

#include <span>
#include <string>
#include <vector>

namespace tactiscope::core::report {

// One line per decision, oldest first. A time on the day of the decision
// before it shows the time only.
std::vector<std::string> verdictTrailLines(std::span<const storage::VerdictDecision> trail);

// "live detector: 21 defects at 3 sites, threshold 0.85": the automatic
// verdict's grounds; empty when the basis cannot be read.
std::string basisText(const std::string& basisJson);

}  // namespace tactiscope::core::report
