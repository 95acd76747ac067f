// The surface-deflection detector computed the direct way, as the paper
// writes it: for every sample and lag form u = [a(t), b(t), a(t−c), b(t−c)],
// update ū and S (eqs 8–9) or average over the window (eqs 2–3), form V,
// invert it with Eigen's fixed-size 4×4 inverse and read R_ab and R_ba from
// U = V⁻¹ (eqs 4–5). The sliding window is recomputed from its samples every
// time (brute force).
//
// Slow on purpose: it is the baseline of the benchmarks and the independent
// ground truth of the tests for the fast kernel in core/detector.
#pragma once

#include "core/detector/DetectorOutput.h"
#include "core/detector/DetectorParameters.h"

#include <Eigen/Core>

#include <span>
#include <vector>

namespace tactiscope::reference {

class DirectDetector {
public:
    explicit DirectDetector(const core::detector::DetectorParameters& parameters);

    void process(std::span<const double> a, std::span<const double> b, std::span<core::detector::DetectorOutput> out);

    // Per-lag values after the last processed sample.
    const std::vector<double>& lastRab() const { return m_rab; }
    const std::vector<double>& lastRba() const { return m_rba; }
    // Plain (total) correlation of b(t) and a(t−c), for comparison.
    const std::vector<double>& lastPlainAb() const { return m_plainAb; }

private:
    Eigen::Matrix4d covariance(std::size_t lag, std::size_t t);
    double delayed(const std::vector<double>& x, std::size_t t, std::size_t k) const;

    std::vector<std::uint32_t> m_lags;
    std::vector<double> m_r;
    double m_eps2;
    double m_threshold;
    double m_bSign;
    std::size_t m_window;
    std::vector<double> m_a, m_b;  // every sample so far
    std::vector<Eigen::Vector4d> m_mean;
    std::vector<Eigen::Matrix4d> m_second;
    std::vector<double> m_rab, m_rba, m_plainAb;
};

}  // namespace tactiscope::reference
