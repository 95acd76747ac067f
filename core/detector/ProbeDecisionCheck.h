// What a probe's own detector decided, checked against the workstation's
// on the same samples (issue 38). A probe that runs the detector
// (firmware/probe-detector) sends its decision and its best R each way as
// channels of kind "decision" named out, rab and rba, and may send the
// lags of those R as lag_ab and lag_ba, in seconds (docs/protocol.md).
// Per sample this compares the probe's decision with the workstation's,
// segments the probe's decisions into defect events (recorded as the
// analysis "probe"), and names a disagreement that lasts: a probe with
// broken firmware is caught on the line. Both detectors start from silence
// at different moments (a probe runs before the host connects, the
// workstation restarts after lost samples), so each (re)start is followed
// by a warm-up in which nothing is compared.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/detector/DefectEvent.h"
#include "core/detector/DetectorOutput.h"
#include "core/detector/EventSegmenter.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tactiscope::core {
class SampleBlock;
}

namespace tactiscope::core::detector {

// Where a stream carries a probe's decisions; none unless out, rab and rba
// are all there. Without its lags a probe's events have no lag, speed or
// place along the stroke.
struct ProbeDecisionChannels {
    std::size_t out = 0, rab = 0, rba = 0;
    std::optional<std::size_t> lagAb, lagBa;
};
std::optional<ProbeDecisionChannels> probeDecisionChannels(const std::vector<ChannelDescriptor>& channels);

// A disagreement that lasted: from its first sample's time on, the probe
// said `probe` and the workstation `workstation`.
struct ProbeDisagreement {
    double start_s = 0.0;
    int probe = 0;
    int workstation = 0;
    std::string text() const;  // a sentence for the alarm
};

struct ProbeAgreement {
    std::uint64_t compared = 0;  // samples compared (after each warm-up)
    std::uint64_t agreeing = 0;
};
// "probe and workstation agree on 3 998 of 4 000 decisions"
std::string agreementText(const ProbeAgreement& agreement);

// A probe's `out` value as a decision: −1, 0 or +1; anything else (a
// garbled channel) is none.
int probeDecisionOf(double value);

class ProbeDecisionCheck {
public:
    // The time two detectors need from silence to forget where they began
    // (25 of the longest forgetting time, 150 ms), and how many samples in
    // a row a disagreement must last to be one: a decision a hair from θ
    // may tip either way for a sample, while a defect is above θ for 4 to
    // 10 samples at 500 Hz, so a probe that misses one, or names it the
    // wrong way, is caught.
    static constexpr double kWarmUp_s = 4.0;
    static constexpr std::uint64_t kLastingSamples = 3;

    ProbeDecisionCheck(ProbeDecisionChannels channels, double sampleInterval_s, double hold_s,
                       std::optional<double> spacing_m);

    // Sample `s` of `block`, which the workstation decided as `workstation`.
    void push(const SampleBlock& block, std::size_t s, const DetectorOutput& workstation,
              std::vector<DefectEvent>& probeEvents, std::vector<ProbeDisagreement>& disagreements);
    // Lost samples: the workstation starts again from silence.
    void restart(std::vector<DefectEvent>& probeEvents);
    void finish(std::vector<DefectEvent>& probeEvents) { m_segmenter.finish(probeEvents); }

    ProbeAgreement agreement() const { return m_agreement; }

private:
    ProbeDecisionChannels m_channels;
    double m_sampleInterval_s;
    EventSegmenter m_segmenter;
    std::uint64_t m_sinceStart = 0;  // samples since the last (re)start
    std::uint64_t m_warmUp;          // samples
    std::uint64_t m_run = 0;         // disagreeing samples in a row
    bool m_told = false;             // this run was named
    ProbeAgreement m_agreement;
};

}  // namespace tactiscope::core::detector
