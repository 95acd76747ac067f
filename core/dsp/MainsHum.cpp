// Finding the mains line and the noise floor in a spectrum.
#include "core/dsp/MainsHum.h"

#include "core/dsp/Median.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace tactiscope::core::dsp {
namespace {

constexpr double kMainsTolerance_hz = 1.5;
constexpr double kStandsAbove = 10.0;  // 20 dB in amplitude

}  // namespace

std::optional<MainsHum> findMainsHum(const Spectrum& spectrum)
{
    if (spectrum.amplitude.empty()) return std::nullopt;
    const double floor = median(spectrum.amplitude);
    std::optional<MainsHum> strongest;
    for (const double mains : std::array{50.0, 60.0}) {
        std::size_t best = 0;
        for (std::size_t k = 0; k < spectrum.amplitude.size(); ++k) {
            if (std::abs(spectrum.frequency_hz[k] - mains) > kMainsTolerance_hz) continue;
            if (best == 0 || spectrum.amplitude[k] > spectrum.amplitude[best]) best = k;
        }
        if (best == 0 || !(spectrum.amplitude[best] > kStandsAbove * floor)) continue;
        if (!strongest || spectrum.amplitude[best] > strongest->amplitude)
            strongest = MainsHum{mains, spectrum.frequency_hz[best], spectrum.amplitude[best]};
    }
    if (strongest) {
        // The line's place from the peak finder, which centres its lobe.
        for (const SpectrumPeak& peak : spectrum.peaks)
            if (std::abs(peak.frequency_hz - strongest->line_hz) <= spectrum.resolution_hz())
                strongest->line_hz = peak.frequency_hz;
    }
    return strongest;
}

double noiseFloor(const Spectrum& spectrum)
{
    const double lowest = std::max(1.0, 5.0 * spectrum.resolution_hz());
    const double highest = 0.45 * spectrum.sampleRate_hz;
    std::vector<double> densities;
    for (std::size_t k = 0; k < spectrum.psd.size(); ++k)
        if (spectrum.frequency_hz[k] >= lowest && spectrum.frequency_hz[k] <= highest)
            densities.push_back(std::sqrt(spectrum.psd[k]));
    return median(std::move(densities));
}

}  // namespace tactiscope::core::dsp
