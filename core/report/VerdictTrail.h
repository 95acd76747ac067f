// A session's verdict trail in words, for the report, the review window and
// `sessions show`: who decided what, when, on what grounds and why, e.g.
//   automatic: defects found (live detector: 21 defects at 3 sites, threshold 0.85), 2026-11-23 14:12 UTC
//   operator Ada kept it, 14:13 UTC
//   reviewer Q. Engineer changed it to pass, 2026-11-24 16:02 UTC: "bump is a marker pen line"
#pragma once

#include "core/storage/SessionRecords.h"

#include <functional>
#include <span>
#include <string>
#include <vector>

namespace tactiscope::core::report {

// How a decision's stored UTC time is written by whoever shows the trail:
// the windows in the user's locale, the report in ISO 8601 with its zone.
using DecisionTime = std::function<std::string(const std::string& decidedUtc)>;

// One line per decision, oldest first. Without `time`, as the CLI writes
// it: "2026-11-23 14:12 UTC", and a time on the day of the decision before
// it as the time only.
std::vector<std::string> verdictTrailLines(std::span<const storage::VerdictDecision> trail,
                                           const DecisionTime& time = {});

// A session its mode did not judge (`unjudged`, why: SessionSummary) whose
// verdict a reviewer gave: the trail begins with what the mode said,
// "automatic: none, not judged: it went past a critical limit", so the
// reason stays beside the decision. Empty when it was judged.
std::string unjudgedTrailLine(const std::string& unjudged);

// "live detector: 21 defects at 3 sites, threshold 0.85": the automatic
// verdict's grounds; empty when the basis cannot be read.
std::string basisText(const std::string& basisJson);

}  // namespace tactiscope::core::report
