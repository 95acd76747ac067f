// PalpationScenario: hand motion, series springs, gauge chain, noise.
#include "devices/simulator/PalpationScenario.h"

#include "core/SampleBlock.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tactiscope::devices::simulator {
namespace {

double uniform(std::mt19937_64& random, double from, double to)
{
    return from + (to - from) * std::uniform_real_distribution<double>(0.0, 1.0)(random);
}

// A smooth 0 → 1 ramp whose speed varies within the ramp, as a hand's does:
// a cosine ease warped by a gentle wobble of the progress rate.
double handRamp(double u, double wobble)
{
    const double warped =
        std::clamp(u + wobble * std::sin(2.0 * std::numbers::pi * u) / (2.0 * std::numbers::pi), 0.0, 1.0);
    return 0.5 * (1.0 - std::cos(std::numbers::pi * warped));
}

// The bridge as it is: the gauges' true factor, not the configured one.
core::straingauge::BridgeSettings withGaugeFactor(core::straingauge::BridgeSettings bridge, double gaugeFactor)
{
    if (!(gaugeFactor > 0.0)) throw std::invalid_argument("palpation: gauge factor must be positive");
    bridge.gaugeFactor = gaugeFactor;
    return bridge;
}

}  // namespace

PalpationScenario::PalpationScenario(const PalpationParameters& parameters)
    : m_p(parameters),
      m_channels{{"high", "count", core::ChannelKind::Other},
                 {"low", "count", core::ChannelKind::Other},
                 {"displacement", "m", core::ChannelKind::Position}},
      m_high(parameters.high),
      m_low(parameters.low),
      m_chain(parameters.adc, withGaugeFactor(parameters.bridge, parameters.trueGaugeFactor)),
      m_random(parameters.seed),
      m_noiseHigh(parameters.seed * 3 + 0, parameters.electricalNoise_v),
      m_noiseLow(parameters.seed * 3 + 1, parameters.electricalNoise_v),
      m_noiseDisplacement(parameters.seed * 3 + 2, parameters.displacementNoise_m)
{
    if (!(m_p.sampleRate_hz > 0.0)) throw std::invalid_argument("palpation: sample rate must be positive");
    if (!(m_p.objectStiffness_n_per_m > 0.0))
        throw std::invalid_argument("palpation: object stiffness must be positive");
    if (m_p.pressDepths_m.empty()) throw std::invalid_argument("palpation: no press depths");
    for (double depth : m_p.pressDepths_m) {
        if (!(depth > 0.0)) throw std::invalid_argument("palpation: press depths must be positive");
    }
    if (!(m_p.pause_s >= 0.0)) throw std::invalid_argument("palpation: pause must not be negative");
    m_press.start_s = m_p.pause_s;
    planNextPress();
}

void PalpationScenario::planNextPress()
{
    const double start_s =
        m_pressCount == 0 ? m_p.pause_s : m_press.start_s + m_press.in_s + m_press.hold_s + m_press.out_s + m_p.pause_s;
    m_press = {start_s,
               uniform(m_random, 0.6, 1.2),
               uniform(m_random, 0.3, 0.8),
               uniform(m_random, 0.5, 1.0),
               m_p.pressDepths_m[m_pressCount % m_p.pressDepths_m.size()],
               uniform(m_random, 8.0, 12.0),
               uniform(m_random, 0.0, 2.0 * std::numbers::pi)};
    ++m_pressCount;
}

double PalpationScenario::displacement_m(double t_s)
{
    if (t_s >= m_press.start_s + m_press.in_s + m_press.hold_s + m_press.out_s) planNextPress();
    const Press& p = m_press;
    const double u = t_s - p.start_s;
    // Lifted 1 mm off the specimen before and after.
    constexpr double kLifted_m = -0.001;
    double x = kLifted_m;
    if (u >= 0.0 && u < p.in_s) {
        x = kLifted_m + (p.depth_m - kLifted_m) * handRamp(u / p.in_s, 0.6);
    } else if (u >= p.in_s && u < p.in_s + p.hold_s) {
        x = p.depth_m;
    } else if (u >= p.in_s + p.hold_s) {
        x = p.depth_m - (p.depth_m - kLifted_m) * handRamp((u - p.in_s - p.hold_s) / p.out_s, -0.5);
    }
    return x + m_p.tremorAmplitude_m * std::sin(2.0 * std::numbers::pi * p.tremorFrequency_hz * t_s + p.tremorPhase);
}

double PalpationScenario::toCounts(double strain, double zeroOffset, GaussianNoise& noise) const
{
    const double noiseCounts = noise.next() / m_p.adc.reference_v * m_chain.fullScaleCounts();
    const double counts = std::round(m_chain.countsForStrain(strain, zeroOffset) + noiseCounts);
    return std::clamp(counts, -m_chain.fullScaleCounts(), m_chain.fullScaleCounts() - 1.0);
}

void PalpationScenario::generate(core::SampleBlock& block)
{
    const double kh = m_high.stiffness_n_per_m();
    const double kl = m_low.stiffness_n_per_m();
    const double ko = m_p.objectStiffness_n_per_m;
    auto high = block.channel(0);
    auto low = block.channel(1);
    auto displacement = block.channel(2);
    for (std::size_t i = 0; i < block.sampleCount(); ++i, ++m_nextSample) {
        const double t_s = static_cast<double>(m_nextSample) / m_p.sampleRate_hz;
        const double x = displacement_m(t_s);
        const double pressed = std::max(x, 0.0);
        const double fHigh = pressed * kh * ko / (kh + ko);
        const double fLow = pressed * kl * ko / (kl + ko);
        high[i] = toCounts(fHigh * m_high.rootStrainPerNewton(), m_p.zeroOffsetHigh_counts, m_noiseHigh);
        low[i] = toCounts(fLow * m_low.rootStrainPerNewton(), m_p.zeroOffsetLow_counts, m_noiseLow);
        displacement[i] = x + m_noiseDisplacement.next();
    }
}

}  // namespace tactiscope::devices::simulator
