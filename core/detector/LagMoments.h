// The running moments of u = [a(t), b(t), a(t−k), b(t−k)] for every lag k,
// stored structure-of-arrays (one array per moment, indexed by lag) so the
// kernel updates many lags with one vector instruction. Arrays are padded to
// a multiple of kLaneWidth; padding lanes have weight 0 and never change.
//
// Exponential form: mean[j] is the weighted mean ū of eq. 8 and moment[jk]
// the covariance V of eq. 10 divided by w·r (w = 1 − r), updated in Welford
// form (see PartialCorrelationKernel.cpp). Sliding-window form: plain sums of
// u and uuᵀ over the window.
//
// Padding lanes continue the lag sequence (last lag + 1, + 2, …) so that
// contiguous lag sets stay contiguous; their weight is 0 and they never win.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tactiscope::core::detector {

inline constexpr std::size_t kLaneWidth = 8;

// Index of S_jk (j ≤ k) in LagMoments::moment: 00 01 02 03 11 12 13 22 23 33.
enum MomentIndex : std::size_t { S00, S01, S02, S03, S11, S12, S13, S22, S23, S33, kMomentCount };

struct LagMoments {
    std::size_t lagCount = 0;
    std::size_t paddedCount = 0;
    std::vector<std::uint32_t> lag;  // k per lane
    std::vector<double> weight;      // exponential: 1 − r; sliding: 1; padding: 0
    std::vector<double> forgetting;  // exponential: r; padding: ½
    bool contiguous = false;         // lag[i] == lag[0] + i for every lane
    std::array<std::vector<double>, 4> mean;
    std::array<std::vector<double>, kMomentCount> moment;

    // Sets up zeroed moments for increasing lags and their forgetting factors
    // r (exponential form) or an empty vector (sliding form).
    void assign(const std::vector<std::uint32_t>& lags, const std::vector<double>& forgettingFactors);
    std::uint32_t largestLaneLag() const { return lag.back(); }
    void zero();
};

}  // namespace tactiscope::core::detector
