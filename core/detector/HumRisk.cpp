// The hum the detector read, against its cantilevers' noise.
#include "core/detector/HumRisk.h"

#include <cmath>
#include <cstdio>

namespace tactiscope::core::detector {

namespace {

// From twice the gauges' noise a common hum begins to cost crossings
// (docs/detector.md: 1 µε over 0.5 µε of noise moves the site; 2 µε loses some).
constexpr double kRiskOverNoise = 2.0;

}  // namespace

std::optional<HumRisk> detectorHumRisk(const std::vector<std::string>& channels,
                                       const std::vector<dsp::ChannelHealth>& health, double sampleRate_hz,
                                       std::optional<double> notch_hz)
{
    std::optional<HumRisk> worst;
    for (std::size_t c = 0; c < channels.size() && c < health.size(); ++c) {
        const auto& hum = health[c].hum;
        if (!hum || (notch_hz && *notch_hz == hum->mains_hz)) continue;
        // The floor is the median density over the band: white noise's σ is it times √(f_s/2).
        const double noise = health[c].noiseFloor_per_sqrt_hz * std::sqrt(sampleRate_hz / 2.0);
        if (!std::isfinite(noise) || !(hum->amplitude >= kRiskOverNoise * noise)) continue;
        if (!worst || hum->amplitude / noise > worst->amplitude / worst->noise)
            worst = HumRisk{channels[c], hum->mains_hz, hum->amplitude, noise};
    }
    return worst;
}

std::string humRiskText(const HumRisk& risk, std::optional<double> notch_hz, double scale, const std::string& unit)
{
    char amount[64] = "";
    if (!unit.empty()) std::snprintf(amount, sizeof amount, "%.3g %s of ", risk.amplitude * scale, unit.c_str());
    char text[400];
    const double times = risk.noise > 0.0 ? risk.amplitude / risk.noise : 0.0;
    if (notch_hz)
        std::snprintf(text, sizeof text,
                      "%s carries %s%.0f Hz hum, %.0f times its noise, which the %.0f Hz notch leaves: the detector "
                      "loses crossings under such a hum (docs/detector.md, \"Under mains hum\")",
                      risk.channel.c_str(), amount, risk.mains_hz, times, *notch_hz);
    else
        std::snprintf(text, sizeof text,
                      "%s carries %s%.0f Hz hum, %.0f times its noise, which the detector read without a notch: it "
                      "loses crossings under such a hum (docs/detector.md, \"Under mains hum\")",
                      risk.channel.c_str(), amount, risk.mains_hz, times);
    return text;
}

}  // namespace tactiscope::core::detector
