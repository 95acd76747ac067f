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
#include <vector>

namespace tactiscope::core::detector {

// The lags and forgetting times a probe's kernel is configured with, as
// resolve() gives them (pd_config in probe_detector.h; the emulated probe's
// input file carries the same, ProbeScanFiles).
struct ProbeLags {
    std::vector<unsigned short> lags;  // k in samples
    std::vector<double> lambda_s;      // forgetting time per lag
};

class FirmwarePairDetector {
public:
    // Throws std::invalid_argument for parameters the probe cannot run: the
    // sliding window, more lags or a longer lag than it is built for.
    static ProbeLags probeLags(const DetectorParameters& parameters);

    // Configured with probeLags(parameters); throws as it does.
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
