// The partial-correlation detector for one pair of cantilevers (A, B), as a
// streaming processor: feed it samples in runs of any length, get one
// DetectorOutput per sample. The same object serves live acquisition,
// offline re-analysis and the CLI.
//
// Before a lag's history exists the delayed samples are zero, like the
// paper's zero initial mean and moment: the detector starts from silence.
// The sliding-window form likewise treats samples before the first as zero.
//
// Steady state allocates nothing. Not thread-safe; one detector per thread.
#pragma once

#include "core/detector/DetectorOutput.h"
#include "core/detector/DetectorParameters.h"
#include "core/detector/LagMoments.h"
#include "core/detector/PartialCorrelationKernel.h"

#include <cstdint>
#include <span>
#include <vector>

namespace tactiscope::core::detector {

class PairDetector {
public:
    // Throws std::invalid_argument for bad parameters (see resolve()), and
    // when `variant` is given but not supported by this CPU.
    explicit PairDetector(const DetectorParameters& parameters, KernelVariant variant = bestKernelVariant());

    KernelVariant kernelVariant() const { return m_variant; }

    const ResolvedParameters& parameters() const { return m_parameters; }

    // a, b and out must have the same length. b is negated here for
    // face-to-face gauges.
    void process(std::span<const double> a, std::span<const double> b, std::span<DetectorOutput> out);

    // Back to the state before the first sample.
    void reset();

    // Everything the detector remembers; restoring it into a detector with the
    // same parameters continues exactly where the snapshot was taken.
    struct Snapshot {
        LagMoments moments;
        std::vector<double> historyA;
        std::vector<double> historyB;
        std::size_t position = 0;
        std::uint64_t samplesProcessed = 0;
    };
    Snapshot snapshot() const { return m_state; }
    // Throws std::invalid_argument if the snapshot is from other parameters.
    void restore(const Snapshot& snapshot);

    std::uint64_t samplesProcessed() const { return m_state.samplesProcessed; }

    // R_ab and R_ba of every lag after the last processed sample, in the
    // order of parameters().lags.
    void currentCorrelations(std::span<double> rab, std::span<double> rba) const;

private:
    void compactHistory();

    ResolvedParameters m_parameters;
    KernelVariant m_variant;
    std::size_t m_historyBack = 0;  // samples kept behind the current one
    Snapshot m_state;
    std::vector<SampleMaxima> m_maxima;
    std::vector<double> m_scratch;  // the kernel's working memory
};

}  // namespace tactiscope::core::detector
