// The detector's verdict on a panel as a decision of the session's verdict
// trail, with its grounds: which analysis, what it found, and the detector
// parameters it ran with, so a reviewer can tell what the machine judged on;
// and a session of several devices' verdict from its parts'.
#pragma once

#include "core/detector/DetectorParameters.h"
#include "core/detector/ProbeDecisionCheck.h"
#include "core/storage/SessionRecords.h"
#include "core/storage/SessionSource.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace tactiscope::core::storage {

// The verdict counts defect sites (a site crossed many times is one
// defect); `defects` is how many events the analysis found. `probe`: how
// far a probe's own decisions agreed with the analysis's, when it sent any.
VerdictDecision automaticDecision(const std::string& analysis, std::size_t defects, std::size_t sites,
                                  const detector::DetectorParameters& parameters,
                                  const std::optional<detector::ProbeAgreement>& probe = std::nullopt);

// The automatic verdict of a session of several devices from its parts'
// summaries (each with its device's name and mode): the worst wins
// (defects found over pass), and its grounds name the part that decided.
// None when no part found defects and some part of a mode that judges
// (core/modes: detectsDefects) has no verdict (too short to judge, cut
// by a lost probe), or when no part judges at all.
std::optional<VerdictDecision> partsDecision(std::span<const SessionSummary> parts);
// Why such a session has no verdict, from its parts' reasons: "left: too
// short to judge (…); right: not judged: …"; empty when none gave one.
std::string partsUnjudged(std::span<const SessionSummary> parts);
// How a reason other than a too-short recording begins: "not judged: it
// went past a critical limit". One prefix for those who write it and
// unjudgedReason(), which takes it off.
inline constexpr std::string_view kNotJudged = "not judged: ";
// The reason alone, for a sentence that already says there is no verdict
// ("No verdict: it went past a critical limit"): without kNotJudged.
std::string unjudgedReason(const std::string& unjudged);

}  // namespace tactiscope::core::storage
