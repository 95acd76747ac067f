// The device the benchmarks stream: 8 strain channels at 2 kHz (the
// workstation's sizing case), noisy sines that differ per channel; and the
// same at any channel count and rate (16 at 10 kHz: issue 40).
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/SampleBlock.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace tactiscope::bench {

inline constexpr std::size_t kChannels = 8;
inline constexpr double kRate_hz = 2000.0;

// Strain channels s0, s1, …
inline std::vector<core::ChannelDescriptor> strainChannels(std::size_t count)
{
    std::vector<core::ChannelDescriptor> result;
    for (std::size_t c = 0; c < count; ++c)  // not "s" + …: GCC 12 warns falsely (-Wrestrict)
        result.push_back({std::string(1, 's').append(std::to_string(c)), "", core::ChannelKind::Strain});
    return result;
}

// Samples [first, first + count) of a stream of `channels` at `rate_hz`:
// the same signals in time at any rate (channel c a sine of 0.318·(c + 1) Hz,
// plus a small one at 541 Hz), so rates compare on the same traces.
inline core::SampleBlock streamBlock(std::size_t channels, double rate_hz, std::uint64_t first, std::size_t count)
{
    core::SampleBlock block(channels, count, static_cast<double>(first) / rate_hz, 1.0 / rate_hz, first);
    for (std::size_t c = 0; c < channels; ++c) {
        auto values = block.channel(c);
        for (std::size_t s = 0; s < count; ++s) {
            const double t = static_cast<double>(first + s) / rate_hz;
            values[s] = 1e-4 * std::sin(2.0 * t * static_cast<double>(c + 1)) + 1e-6 * std::sin(3400.0 * t);
        }
    }
    return block;
}

inline std::vector<core::ChannelDescriptor> eightChannels()
{
    return strainChannels(kChannels);
}

inline core::SampleBlock eightChannelBlock(std::uint64_t first, std::size_t count)
{
    return streamBlock(kChannels, kRate_hz, first, count);
}

}  // namespace tactiscope::bench
