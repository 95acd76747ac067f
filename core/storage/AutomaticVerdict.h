// The detector's verdict on a panel as a decision of the session's verdict
// trail, with its grounds: which analysis, what it found, and the detector
// parameters it ran with, so a reviewer can tell what the machine judged on.
#pragma once

#include "core/detector/DetectorParameters.h"
#include "core/detector/ProbeDecisionCheck.h"
#include "core/storage/SessionRecords.h"

#include <cstddef>
#include <string>

namespace tactiscope::core::storage {

// The verdict counts defect sites (a site crossed many times is one
// defect); `defects` is how many events the analysis found. `probe`: how
// far a probe's own decisions agreed with the analysis's, when it sent any.
VerdictDecision automaticDecision(const std::string& analysis, std::size_t defects, std::size_t sites,
                                  const detector::DetectorParameters& parameters,
                                  const std::optional<detector::ProbeAgreement>& probe = std::nullopt);

}  // namespace tactiscope::core::storage
