// What the detector says about one sample.
#pragma once

#include <cstdint>

namespace tactiscope::core::detector {

struct DetectorOutput {
    // +1: some lag has R_ab above the threshold (A then B); −1: some lag has
    // R_ba above it (B then A); 0 otherwise. When both hold, the larger
    // maximum decides, and an exact tie gives 0 (no direction can be named).
    std::int8_t decision = 0;
    double rab = 0.0;         // max over lags of R_ab
    double rba = 0.0;         // max over lags of R_ba
    std::uint32_t lagAb = 0;  // lag of that maximum, in samples
    std::uint32_t lagBa = 0;
};

// The decision rule above, shared by every detector form.
inline std::int8_t decide(double rab, double rba, double threshold)
{
    const bool ab = rab > threshold;
    const bool ba = rba > threshold;
    if (ab && ba) return rab > rba ? 1 : (rba > rab ? -1 : 0);
    return ab ? 1 : (ba ? -1 : 0);
}

}  // namespace tactiscope::core::detector
