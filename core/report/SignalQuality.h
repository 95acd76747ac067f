// A report's "Signal quality" (issue 57): each stored channel's health over
// the report's range (mains hum in the channel's unit, noise floor, drift
// with its ±, clipped samples: core/dsp/SignalHealth.h), the filters and
// math channels the session was recorded with, and for a capacitive beam
// the detection limit its noise floor gives beside its calibration's; the
// health of its filtered and math channels too, as they were live.
// The health reads the samples, in windows; the rest of a report does not.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/dsp/SignalHealth.h"
#include "core/dsp/StepCreep.h"
#include "core/storage/SessionSource.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tactiscope::core::report {

struct ChannelQuality {
    ChannelDescriptor channel;
    dsp::ChannelHealth health;
    bool drifts = true;  // its drift is a signal's (a position's is the probe moving)
    // A capacitive beam's creep after its load steps: judged on a
    // capacitance channel of at most kMostCreepSamples; none found, none.
    bool creepJudged = false;
    std::optional<dsp::StepCreep> creep = {};
};

// A capacitive beam's channel, whose creep is judged: by its role, or by
// its kind where it has none.
bool isBeamChannel(const ChannelDescriptor& channel);

// The longest capacitance channel whose creep is judged (it is held whole:
// 32 MB); an hour at 1 kHz is.
inline constexpr std::uint64_t kMostCreepSamples = std::uint64_t{1} << 22;

// A capacitive beam's detection limit two ways, in newtons: from the
// recording's noise floor over the band it samples, 3·floor·√(f_s/2)/S
// (what one sample resolves, had the noise been white), and from the
// calibration's baseline, 3σ/S. A calibration's well above the floor's
// says its baseline window held more than noise (creep, drift).
struct DetectionLimits {
    double fromNoiseFloor_n = 0.0;
    std::optional<double> fromCalibration_n;
};

struct SignalQuality {
    std::vector<ChannelQuality> channels;
    // Channels not read: a report's section is a page at most, as its plot
    // (`health --db … --session …` reads every one).
    std::size_t channelsLeftOut = 0;
    std::string setup = "none";  // the recorded signal setup in words
    // The health of its filtered and math channels, computed again from the
    // stored samples as they were live (a constant math channel left out);
    // why not, when its setup cannot be run here.
    std::vector<ChannelQuality> computed;
    std::string computedProblem;
    std::optional<DetectionLimits> detection;
};

// Each stored channel's health over samples [first, end) (a probe's own
// decisions left out), read in windows, and a capacitance channel's creep;
// the first `most` of them. Throws
// storage::StorageError.
std::vector<ChannelQuality> channelQuality(storage::SessionSource& store, std::int64_t session, std::uint64_t first,
                                           std::uint64_t end, std::size_t most = SIZE_MAX);

// The health of the filtered and math channels `session` was recorded
// with, over [first, end), computed again (core/signal/SignalColumns.h);
// the first `most` that are not constants. `problem` says why none, when
// its setup cannot be run.
std::vector<ChannelQuality> recordedSignalQuality(storage::SessionSource& store, std::int64_t session,
                                                  std::uint64_t first, std::uint64_t end, std::size_t most,
                                                  std::string& problem);

// The section for `session` over [first, end), of its first `most`
// channels. `perNewton_f`: a capacitive
// beam's sensitivity (F/N) as its readings used it, `calibrationLimit_n`
// the calibration's 3σ/S; none for other sessions.
SignalQuality gatherSignalQuality(storage::SessionSource& store, const storage::SessionSummary& session,
                                  std::uint64_t first, std::uint64_t end, std::optional<double> perNewton_f,
                                  std::optional<double> calibrationLimit_n, std::size_t most = SIZE_MAX);

}  // namespace tactiscope::core::report
