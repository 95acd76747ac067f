// A stored panel scan's detector output — the best R over lags and pairs
// (max of R_ab and R_ba, read against the threshold) and the decision
// (+1 A then B, −1 B then A, 0 none) — computed from its strain samples by
// the offline detector (detector::StreamingDetection, the code `analyze` and the
// review's re-analysis run) with the parameters the recording ran with: the
// live lags for its rate, and the threshold, ε, λ rule and mounting named by
// its automatic verdict.
//
// The output at a sample depends on the samples before it, but with a
// memory that fades as r^k (r = exp(−Δt/λ), λ ≤ the longest lag): each read
// starts kWarmUpMemories longest-λ's earlier (or at the session's start, or
// after the last lost sample, where the live detector restarted too), so
// the output differs from a run over the whole session by less than e⁻²⁰.
// With the sliding-window form the warm-up is the window plus the longest
// lag, and the output is the same to rounding. R is not monotone in the
// strains, so there is no pyramid for it: the overview computes exact
// outputs, up to kExactLimit samples (the review says to zoom in beyond).
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/detector/DetectorParameters.h"
#include "core/detector/ProbeDetector.h"
#include "core/storage/SessionExport.h"
#include "core/storage/SessionStore.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tactiscope::core::derived {

class PanelScanChannels final : public storage::ComputedColumns {
public:
    static constexpr std::uint64_t kExactLimit = 100'000;  // samples per overview
    static constexpr double kWarmUpMemories = 20.0;

    // Throws std::invalid_argument for a session that is not a panel scan
    // or whose channels or rate the detector cannot run on (the message says
    // which); storage::StorageError when the store cannot be read.
    PanelScanChannels(storage::SessionSource& store, std::int64_t session);

    // best_r, decision.
    std::vector<ChannelDescriptor> channels() const override;
    std::string basis() const override { return m_basis; }
    const detector::DetectorParameters& parameters() const { return m_parameters; }

    // Exact outputs of samples [first, first + count), clipped to the
    // session; NaN where a strain was lost.
    std::vector<std::vector<double>> read(std::uint64_t first, std::uint64_t count) override;
    // About `points` min/max stretches of one channel; empty for a range
    // longer than kExactLimit.
    std::vector<storage::OverviewPoint> overview(std::size_t channel, std::uint64_t first, std::uint64_t count,
                                                 std::size_t points);

private:
    storage::SessionSource& m_store;
    std::int64_t m_session;
    std::uint64_t m_sampleCount = 0;
    std::vector<std::size_t> m_cantilevers;  // the strain channels, in probe order
    detector::DetectorParameters m_parameters;
    std::uint64_t m_warmUp = 0;  // samples read before a range
    std::string m_basis;
    // The last range read: the lanes of one view share one computation.
    std::uint64_t m_cachedFirst = 0;
    std::vector<std::vector<double>> m_cached;
};

// The detector parameters a panel scan was recorded with: the live lags for
// its rate, and whatever its automatic verdict's grounds name (threshold,
// ε, λ rule, window, gauge mounting).
detector::DetectorParameters recordedDetectorParameters(const std::vector<storage::VerdictDecision>& verdicts,
                                                        double sampleRate_hz);

}  // namespace tactiscope::core::derived
