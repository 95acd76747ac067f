// The rig's position channel on a stream (an encoder or a linear
// potentiometer along the panel-scan stroke): which channel it is, and its
// recent samples, so that each defect crossing the detector completes can
// be stamped with where the probe was when its centre passed the dent
// (DefectEvent::position_m). The live detector and `detect --position`
// stamp through it; a stored session reads its channel instead
// (core/storage/StoredSites.h).
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/detector/DefectEvent.h"

#include <cstddef>
#include <deque>
#include <optional>
#include <span>
#include <utility>

namespace tactiscope::core::detector {

// The channel with the role `position`, else the first of the kind
// position without a role; none without either.
std::optional<std::size_t> positionChannel(std::span<const ChannelDescriptor> channels);

class PositionTrail {
public:
    // Keeps at least the last `keepSamples` samples, `period_s` apart:
    // enough to reach back from an event's completion to its crossing.
    PositionTrail(std::size_t keepSamples, double period_s);

    // The next sample, later than the last; NaN where the rig gave none.
    void push(double t_s, double position_m);
    // Linearly between the two samples around t_s; none outside the trail,
    // beside a NaN, or across a gap (samples more than 1.5 periods apart).
    std::optional<double> at(double t_s) const;
    // Each event's position at its crossing (core/detector/DefectSites.h's
    // crossing time); none where the trail cannot say.
    void stamp(std::span<DefectEvent> events) const;

private:
    std::size_t m_keep;
    double m_period_s;
    std::deque<std::pair<double, double>> m_samples;  // (t, x), in time order
};

}  // namespace tactiscope::core::detector
