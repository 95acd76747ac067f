// The detector for a whole probe: N cantilevers in a row (A, B, C, …),
// analysed pair by adjacent pair (A–B, B–C, …) with one PairDetector each,
// fed with SampleBlocks from acquisition or from a file.
//
// Probe-level output per sample: R_ab and R_ba are the maxima over all pairs
// (with the lag and the pair they came from), and the decision applies the
// paper's rule to them: +1 if some pair has some lag with R_ab above the
// threshold, −1 likewise for R_ba, the larger maximum deciding when both hold.
// Adjacent pairs share one direction of travel, so on a clean pass the pairs
// agree and the rule only adds sensitivity.
#pragma once

#include "core/detector/DetectorOutput.h"
#include "core/detector/PairDetector.h"

#include <cstddef>
#include <span>
#include <vector>

namespace tactiscope::core {
class SampleBlock;
}

namespace tactiscope::core::detector {

struct ProbeOutput {
    double t_s = 0.0;
    DetectorOutput combined;
    std::size_t pairAb = 0;  // pair of the R_ab maximum (0 = A–B)
    std::size_t pairBa = 0;
};

class ProbeDetector {
public:
    // cantileverChannels: channel indices in the blocks, in probe order; at
    // least two, all different. Throws std::invalid_argument otherwise or
    // for bad parameters.
    ProbeDetector(const DetectorParameters& parameters, std::vector<std::size_t> cantileverChannels,
                  KernelVariant variant = bestKernelVariant());

    // Processes a block; returns one output per sample, valid until the next
    // call. Throws std::invalid_argument if the block lacks a channel or its
    // sample interval differs from the parameters' by more than 0.1 %.
    std::span<const ProbeOutput> push(const SampleBlock& block);

    std::size_t pairCount() const { return m_pairs.size(); }
    // The last block's outputs of one pair.
    std::span<const DetectorOutput> pairOutputs(std::size_t pair) const { return m_pairOutputs[pair]; }
    const PairDetector& pair(std::size_t index) const { return m_pairs[index]; }
    const ResolvedParameters& parameters() const { return m_pairs.front().parameters(); }

    void reset();
    std::vector<PairDetector::Snapshot> snapshot() const;
    void restore(const std::vector<PairDetector::Snapshot>& snapshot);

private:
    std::vector<std::size_t> m_channels;
    std::vector<PairDetector> m_pairs;
    std::vector<std::vector<DetectorOutput>> m_pairOutputs;
    std::vector<ProbeOutput> m_outputs;
    std::vector<const DetectorOutput*> m_row;  // one sample's pair outputs
};

// The probe-level combination of per-pair outputs for one sample (see above).
ProbeOutput combinePairs(std::span<const DetectorOutput* const> pairs, double threshold);

}  // namespace tactiscope::core::detector
