// The panel-scan detector over a stored session, streamed from the store a
// window at a time (the CLI's analyze, the review's re-analysis): each
// window's chunks decode straight into the detector's input buffers, so
// memory stays a few windows whatever the recording's length, and the
// caller hears how far it got and may stop it.
#pragma once

#include "core/detector/StreamingDetection.h"
#include "core/storage/SessionStore.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <span>

namespace tactiscope::core::derived {

// Told the samples done and the total after every window; returning false
// cancels the run.
using DetectionProgress = std::function<bool(std::uint64_t done, std::uint64_t total)>;

// The events of `cantilevers` (channel indices, probe order) of `session`:
// the same as detector::detectStretches over the whole channels. Nothing
// when cancelled. Throws storage::StorageError, std::invalid_argument.
// `probeOut`: the channel of a probe's own recorded decisions
// (ProbeDecisionCheck), compared sample by sample with these after each
// stretch's warm-up; the result's probeAgreement says how far they agree.
std::optional<detector::StretchDetection> detectStoredSession(storage::SessionSource& store, std::int64_t session,
                                                              std::span<const std::size_t> cantilevers,
                                                              const detector::StretchSettings& settings,
                                                              const DetectionProgress& progress = {},
                                                              std::optional<std::size_t> probeOut = std::nullopt);

}  // namespace tactiscope::core::derived
