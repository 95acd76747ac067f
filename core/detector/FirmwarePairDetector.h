// The probe's own detector (firmware/probe-detector, single precision) for
// one pair of cantilevers, behind the same process() as PairDetector: what
// `detect --engine probe` runs, and what the emulated probe runs to send
// its decisions. The kernel is the probe's C file itself, so the
// workstation runs the code a probe runs, bit for bit.
#pragma once

#include "core/detector/DetectorOutput.h"
#include "core/detector/DetectorParameters.h"

#include <memory>
#include <span>

namespace tactiscope::core::detector {

class FirmwarePairDetector {
public:
    // The lags and forgetting times as resolve() gives them. Throws
    // std::invalid_argument for parameters the probe cannot run: the
    // sliding window, more lags or a longer lag than it is built for.
    explicit FirmwarePairDetector(const DetectorParameters& parameters);
    ~FirmwarePairDetector();
    FirmwarePairDetector(FirmwarePairDetector&&) noexcept;
    FirmwarePairDetector& operator=(FirmwarePairDetector&&) noexcept;

    // a, b and out of one length; b as measured (face to face is the
    // kernel's to apply). Each value goes in as the float a probe holds.
    void process(std::span<const double> a, std::span<const double> b, std::span<DetectorOutput> out);
    void reset();

    // The probe's build-time capacity.
    static std::size_t mostLags();
    static std::size_t longestLag();  // in samples

private:
    struct State;
    std::unique_ptr<State> m_state;
};

}  // namespace tactiscope::core::detector
