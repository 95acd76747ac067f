// The mains notches' design: zeros at ±ω₀ on the unit circle, poles at radius r.
#include "core/dsp/MainsNotch.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace tactiscope::core::dsp {
namespace {

inline constexpr double kMostNotchCycles = 0.45;

}  // namespace

std::vector<double> notchedFrequencies(double mains_hz, double sampleRate_hz)
{
    std::vector<double> frequencies;
    for (int k = 1; k <= kNotchedHarmonics; ++k) {
        const double f = k * mains_hz;
        if (f < kMostNotchCycles * sampleRate_hz) frequencies.push_back(f);
    }
    return frequencies;
}

std::vector<Biquad> mainsNotches(double mains_hz, double sampleRate_hz, double width_hz)
{
    const std::vector<double> frequencies = notchedFrequencies(mains_hz, sampleRate_hz);
    if (!(mains_hz > 0.0) || frequencies.empty())
        throw std::invalid_argument("a " + std::to_string(static_cast<int>(std::lround(mains_hz))) +
                                    " Hz notch needs a sample rate above " +
                                    std::to_string(static_cast<int>(std::ceil(mains_hz / kMostNotchCycles))) + " Hz");
    // A pole radius r gives a −3 dB width of about (1 − r)·fs/π.
    const double r = 1.0 - std::numbers::pi * width_hz / sampleRate_hz;
    std::vector<Biquad> sections;
    for (const double f : frequencies) {
        const double c = std::cos(2.0 * std::numbers::pi * f / sampleRate_hz);
        const double a1 = -2.0 * r * c;
        const double a2 = r * r;
        const double gain = (1.0 + a1 + a2) / (2.0 - 2.0 * c);  // unit gain at DC
        sections.push_back(Biquad{gain, -2.0 * c * gain, gain, a1, a2});
    }
    return sections;
}

}  // namespace tactiscope::core::dsp
