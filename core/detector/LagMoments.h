// The running moments of u = [a(t), b(t), a(t−k), b(t−k)] for every lag k,
// stored structure-of-arrays (one array per moment, indexed by lag) so the
// kernel updates many lags with one vector instruction. Arrays are padded to
// a multiple of kLaneWidth; padding lanes have weight 0 and never change.
//
// Exponential form: mean[j] and moment[jk] are the weighted mean ū and the
// second moment S of eqs 8–9 (ε² included). Sliding-window form: they are
// plain sums of u and uuᵀ over the window.
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
    std::vector<std::uint32_t> lag;  // k per lane; 0 in padding
    std::vector<double> weight;      // exponential: 1 − r; sliding: 1; padding: 0
    std::array<std::vector<double>, 4> mean;
    std::array<std::vector<double>, kMomentCount> moment;

    // Sets up zeroed moments for the given lags and per-lag weights.
    void assign(const std::vector<std::uint32_t>& lags, const std::vector<double>& weights);
    void zero();
};

}  // namespace tactiscope::core::detector
