// A stored calibration sweep of a capacitive beam against a reference
// force (issue 40): the channel that plays each role, looked for across a
// session's devices, and the beam's samples paired with the reference at
// their instants on the session's clock (the reference interpolated
// linearly between its own samples; each device's time mapped by its
// stored clock). What the pairing cannot know, it says: the two clocks'
// relative uncertainty and the force it can shift a pairing by on the
// sweep's steepest part. The pairing itself is core/calibration/ReferencePairing.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/calibration/CapacitiveSteps.h"
#include "core/storage/SessionSource.h"
#include "core/timing/ClockAlignment.h"

#include <cstdint>
#include <optional>
#include <string>

namespace tactiscope::core::derived {

// One channel of a session: of the session itself, or of one device's part.
struct SessionChannel {
    std::int64_t source = 0;  // the session or part whose samples it is
    std::string device;       // the part's device name; empty in a session of one device
    std::size_t channel = 0;
    storage::StoredChannel stored;
    std::optional<timing::ClockMapping> clock;  // the part's mapping; none: its own time is the session's

    // "load-cell/force", or "force" in a session of one device.
    std::string label() const;
};

// The channel given `role` in any device of the session, else the first
// with no role that can play it (core::canPlay). None when none
// can.
std::optional<SessionChannel> channelPlaying(storage::SessionSource& store, std::int64_t session, ChannelRole role);
// "DEVICE/CHANNEL", or "CHANNEL" in a session of one device; none when
// there is no such channel.
std::optional<SessionChannel> channelNamed(storage::SessionSource& store, std::int64_t session,
                                           const std::string& label);

struct ReferencedSweep {
    calibration::CapacitiveRecording recording;  // seconds on the session's clock, F and N
    std::size_t outsideReference = 0;            // beam samples with no reference around them, left out
    // The standard uncertainty of the two devices' relative timing, at
    // its largest over the recording; 0 for channels of one device. None
    // when a clock was not mapped with a stated one.
    std::optional<double> clockUncertainty_s;
    double steepest_n_per_s = 0.0;  // the reference's fastest change, between half-second means
};

// Throws std::invalid_argument for a capacitance channel not in F, pF, nF
// or fF, a reference not in N, mN, µN (uN), or fewer than three paired
// samples.
ReferencedSweep referencedSweep(storage::SessionSource& store, const SessionChannel& capacitance,
                                const SessionChannel& reference);

}  // namespace tactiscope::core::derived
