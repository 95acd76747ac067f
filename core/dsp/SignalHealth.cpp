// One pass, three accumulators: spectrum, drift, clipping.
#include "core/dsp/SignalHealth.h"

#include <algorithm>
#include <cmath>

namespace tactiscope::core::dsp {
namespace {

constexpr double kWantedResolution_hz = 0.25;
constexpr std::size_t kHealthAverages = 8;

}  // namespace

std::size_t healthSegmentLength(double sampleRate_hz, std::uint64_t samples)
{
    const std::size_t lengths[] = {static_cast<std::size_t>(samples)};
    std::size_t fitting = segmentLengthFor(lengths, kHealthAverages);
    std::size_t fine = kShortestSegment;
    while (fine < kLongestSegment && static_cast<double>(fine) < sampleRate_hz / kWantedResolution_hz) fine *= 2;
    return std::min(fitting, fine);
}

std::size_t streamSegmentLength(double sampleRate_hz)
{
    std::size_t length = kShortestSegment;
    while (length < kLongestSegment && static_cast<double>(length) < sampleRate_hz) length *= 2;
    return length;
}

HealthAccumulator::HealthAccumulator(double sampleRate_hz, std::size_t segmentLength,
                                     std::uint64_t driftIntervalSamples, bool judgeClipping)
    : m_spectrum(sampleRate_hz, segmentLength, SpectralWindow::Hann),
      m_drift(sampleRate_hz, driftIntervalSamples),
      m_judgeClipping(judgeClipping)
{
}

HealthAccumulator::HealthAccumulator(double sampleRate_hz, std::uint64_t expectedSamples,
                                     std::optional<ChannelRange> range, bool judgeClipping)
    : m_spectrum(sampleRate_hz, healthSegmentLength(sampleRate_hz, expectedSamples), SpectralWindow::Hann),
      m_drift(sampleRate_hz, driftIntervalSamples(expectedSamples)),
      m_clips(range),
      m_judgeClipping(judgeClipping)
{
}

void HealthAccumulator::push(std::span<const double> values)
{
    m_spectrum.push(values);
    for (const double v : values) {
        m_drift.push(v);
        if (m_judgeClipping) m_clips.push(v);
        if (!std::isfinite(v)) ++m_missing;
    }
    m_samples += values.size();
}

ChannelHealth HealthAccumulator::result() const
{
    ChannelHealth health;
    health.samples = m_samples;
    health.missing = m_missing;
    const Spectrum spectrum = m_spectrum.result();
    health.hum = findMainsHum(spectrum);
    health.noiseFloor_per_sqrt_hz = noiseFloor(spectrum);
    health.resolution_hz = spectrum.resolution_hz();
    health.averages = spectrum.averages;
    health.span_s = m_drift.span_s();
    if (health.span_s >= kShortestDrift_s) health.drift = m_drift.result();
    health.clipped = m_clips.clipped();
    return health;
}

}  // namespace tactiscope::core::dsp
