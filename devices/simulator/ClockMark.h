// A mark at one instant of the host's steady clock, put on a simulated
// device's first channel (the emulator's `--mark-at`, the simulator's
// SimulatorOptions::markAt_s): a ramp from −kMarkHeight to +kMarkHeight
// over markHalfWidth_s either side of the instant, on top of the scenario,
// by the host instant each sample is taken at. Devices given one instant
// mark one event, whose places in a session of them show how well their
// clocks were mapped onto one (issues 40 and 55).
#pragma once

#include "core/SampleBlock.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace tactiscope::devices::simulator {

inline constexpr double kMarkHeight = 1e-3;

// The mark's half-width: 10 ms, or two and a half sample periods of a slower
// device, so that its ramp holds samples either side of its zero at any rate.
inline double markHalfWidth_s(double rate_hz)
{
    return std::max(0.01, 2.5 / rate_hz);
}

// Adds the mark at `markAt_s` to the block's first channel; `takenAt`
// gives the host instant (s) of a sample by its index.
template <typename TakenAt>
void addClockMark(core::SampleBlock& block, double markAt_s, double rate_hz, const TakenAt& takenAt)
{
    if (block.channelCount() == 0) return;
    auto values = block.channel(0);
    const double halfWidth_s = markHalfWidth_s(rate_hz);
    for (std::size_t s = 0; s < values.size(); ++s) {
        const double x = (takenAt(block.firstSampleIndex() + s) - markAt_s) / halfWidth_s;
        if (std::abs(x) <= 1.0) values[s] += kMarkHeight * x;
    }
}

}  // namespace tactiscope::devices::simulator
