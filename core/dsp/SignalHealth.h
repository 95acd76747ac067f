// A channel's signal health, gathered in one pass over its samples (a
// stored session read in windows, a CSV file a block at a time): mains
// hum (which mains, and its amplitude in the channel's unit), the noise
// floor (unit/√Hz), the drift (unit/s with its ±) and the clipped samples.
#pragma once

#include "core/dsp/ClipCount.h"
#include "core/dsp/DriftRate.h"
#include "core/dsp/MainsHum.h"
#include "core/dsp/WelchSpectrum.h"

#include <cstdint>
#include <optional>
#include <span>

namespace tactiscope::core::dsp {

struct ChannelHealth {
    std::uint64_t samples = 0;
    std::uint64_t missing = 0;
    std::optional<MainsHum> hum;
    double noiseFloor_per_sqrt_hz = 0.0;  // NaN when too short for a spectrum
    double resolution_hz = 0.0;
    std::size_t averages = 0;
    std::optional<Drift> drift;  // none under kShortestDrift_s, or too much of it lost
    double span_s = 0.0;         // the time judged, missing samples included
    std::uint64_t clipped = 0;   // 0 where clipping is not judged
};

class HealthAccumulator {
public:
    // `expectedSamples` sizes the spectrum's segments (0.25 Hz resolution
    // where eight averages fit) and the drift's intervals.
    // `judgeClipping` false: a channel that cannot clip as a converter
    // does (a position dwelling at an end stop, a probe's decisions).
    HealthAccumulator(double sampleRate_hz, std::uint64_t expectedSamples,
                      std::optional<ChannelRange> range = std::nullopt, bool judgeClipping = true);
    // A stream of no known length (the live panel): spectrum segments and
    // drift intervals of the sizes given.
    HealthAccumulator(double sampleRate_hz, std::size_t segmentLength, std::uint64_t driftIntervalSamples,
                      bool judgeClipping);

    void push(std::span<const double> values);
    ChannelHealth result() const;

private:
    WelchAccumulator m_spectrum;
    DriftAccumulator m_drift;
    ClipCounter m_clips;
    bool m_judgeClipping = true;
    std::uint64_t m_samples = 0;
    std::uint64_t m_missing = 0;
};

// The segment length health takes for a recording of `samples` at `rate`.
std::size_t healthSegmentLength(double sampleRate_hz, std::uint64_t samples);

// The segment length for a stream read as it comes: about a second (1 Hz
// resolution, 50 and 60 Hz lines well apart), a first spectrum soon.
std::size_t streamSegmentLength(double sampleRate_hz);

}  // namespace tactiscope::core::dsp
