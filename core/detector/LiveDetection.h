// The detector on a live stream: a sink on the acquisition thread that runs
// a ProbeDetector over the cantilever channels, puts its output per sample
// (decision, best R_ab, best R_ba) into a LiveBuffer for display, and
// segments defect events for the operator's list and the session.
//
// With the rig's position channel, each event carries where the probe was
// at its crossing (DefectEvent::position_m), for its sites.
//
// Settings change while streaming: setSettings() builds (and so checks) the
// new detector on the caller's thread and hands it over; it takes effect at
// the next block with fresh statistics, so the output of every sample comes
// from one consistent set of parameters. Lost samples (a gap in the sample
// index) restart the detector the same way, as the lags would otherwise
// span the gap.
#pragma once

#include "core/BlockSink.h"
#include "core/ChannelDescriptor.h"
#include "core/LiveBuffer.h"
#include "core/detector/DefectEvent.h"
#include "core/detector/EventSegmenter.h"
#include "core/detector/PositionTrail.h"
#include "core/detector/ProbeDecisionCheck.h"
#include "core/detector/ProbeDetector.h"

#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace tactiscope::core::detector {

struct LiveDetectionSettings {
    DetectorParameters parameters;  // sampleInterval_s is set from the stream's rate
    double hold_s = 0.020;
    std::optional<double> spacing_m;
};

class LiveDetection final : public BlockSink {
public:
    // Throws std::invalid_argument for bad settings or fewer than two
    // cantilevers. `probe`: where the stream carries the probe's own
    // decisions, checked against these (ProbeDecisionCheck). `position`:
    // the rig's position channel (core/detector/PositionTrail.h).
    LiveDetection(std::vector<std::size_t> cantileverChannels, double sampleRate_hz, LiveDetectionSettings settings,
                  double displaySeconds, std::optional<ProbeDecisionChannels> probe = std::nullopt,
                  std::optional<std::size_t> position = std::nullopt);

    // The channels of output(): decision (−1, 0, +1), R_ab, R_ba.
    static std::vector<ChannelDescriptor> outputChannels();

    // GUI thread. Throws std::invalid_argument (nothing changes) for bad settings.
    void setSettings(LiveDetectionSettings settings);
    LiveDetectionSettings settings() const;

    // Acquisition thread.
    void consume(const SampleBlock& block) override;

    std::shared_ptr<const LiveBuffer> output() const { return m_output; }
    // Whether its events carry their positions.
    bool placesByPosition() const { return m_positionChannel.has_value(); }
    // Events completed since the last call, in time order.
    std::vector<DefectEvent> takeEvents();
    // The probe's own: its defect events and the disagreements that
    // lasted, since the last call; how far they agreed so far. Empty
    // and none for a stream without the probe's decisions.
    std::vector<DefectEvent> takeProbeEvents();
    std::vector<ProbeDisagreement> takeDisagreements();
    std::optional<ProbeAgreement> probeAgreement() const;

private:
    struct Engine {
        ProbeDetector detector;
        EventSegmenter segmenter;
    };
    std::unique_ptr<Engine> makeEngine(const LiveDetectionSettings& settings) const;

    std::vector<std::size_t> m_channels;
    std::optional<std::size_t> m_positionChannel;
    double m_sampleInterval_s;
    std::shared_ptr<LiveBuffer> m_output;

    mutable std::mutex m_mutex;  // guards the members below
    LiveDetectionSettings m_settings;
    std::unique_ptr<Engine> m_pending;  // new settings, waiting for the next block
    std::vector<DefectEvent> m_events;
    std::vector<DefectEvent> m_probeEvents;
    std::vector<ProbeDisagreement> m_disagreements;
    std::optional<ProbeAgreement> m_agreement;

    // Acquisition thread only.
    std::optional<ProbeDecisionCheck> m_probe;
    std::optional<PositionTrail> m_trail;
    std::vector<DefectEvent> m_probeCompleted;
    std::vector<ProbeDisagreement> m_disagreed;
    std::unique_ptr<Engine> m_engine;
    std::optional<std::uint64_t> m_nextIndex;
    std::vector<DefectEvent> m_completed;
};

}  // namespace tactiscope::core::detector
