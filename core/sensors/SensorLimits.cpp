// SensorLimits: the capacitive beam's force limits from the elastica, the
// compliance probe's stiff-beam ADC limits.
#include "core/sensors/SensorLimits.h"

#include "core/UnitScale.h"
#include "core/sensors/LargeDeflection.h"

#include <algorithm>
#include <cmath>

namespace tactiscope::core::sensors {
namespace {

// Three significant digits, towards zero: a limit that reads as it is
// written, and never later than the model's.
double threeDigits(double value)
{
    const double scale = std::pow(10.0, 2 - std::floor(std::log10(std::abs(value))));
    return std::trunc(value * scale) / scale;
}

std::vector<SensorLimit> capacitiveLimits(const CapacitiveBeamProfile& probe)
{
    const CapacitiveBeam beam(probe.geometry);
    const auto stiffness = bendingStiffness(beam);
    const double length_m = probe.geometry.beam.length_m;
    trigger::LimitSpec force;
    force.quantity = "force";
    force.warning = threeDigits(forceAtModelError(stiffness, length_m, kWarningModelError));
    force.critical = threeDigits(forceAtModelError(stiffness, length_m, kCriticalModelError));
    return {{force, "the beam's safe force: its small-deflection model errs by 2 % (warning) and 5 % (critical)"}};
}

std::vector<SensorLimit> complianceLimits(const CompliancePairProfile& probe,
                                          const std::vector<ChannelDescriptor>& channels,
                                          const straingauge::AdcSettings& adc)
{
    const auto stiff =
        std::ranges::find_if(channels, [](const ChannelDescriptor& c) { return c.role == ChannelRole::StiffBeam; });
    if (stiff == channels.end() || !isCounts(stiff->unit)) return {};
    // The profile's declared range for a board's counts, else the probe's converter's.
    const auto found = probe.channels.find(stiff->name);
    const ChannelScale* declared = found != probe.channels.end() ? &found->second : nullptr;
    if (declared && !declared->fullScale_counts) return {};
    const double fullScale =
        declared ? *declared->fullScale_counts : straingauge::StrainGaugeChain(adc, {}).fullScaleCounts();
    const std::string basis = "the stiff beam's ADC: 90 % of full scale (warning), clipped at 99 % (critical)";
    // A bipolar ADC clips at either end: one window the counts must stay
    // in; so does a declared range, judged on |counts| as a probe's is.
    const double warning = std::floor(kAdcWarningFraction * fullScale);
    const double critical = std::floor(kAdcCriticalFraction * fullScale);
    trigger::LimitSpec counts;
    counts.quantity = stiff->name;
    if (adc.bipolar || declared) {
        const double offset = declared ? declared->offset_counts : 0.0;  // the window's centre
        counts.side = trigger::LimitSide::Outside;
        counts.warning = trigger::LimitLevel(offset - warning, offset + warning);
        counts.critical = trigger::LimitLevel(offset - critical, offset + critical);
    } else {
        counts.warning = warning;
        counts.critical = critical;
    }
    return {{counts, basis}};
}

}  // namespace

std::vector<SensorLimit> modelLimits(const SensorProfile& profile, const std::vector<ChannelDescriptor>& channels,
                                     const straingauge::AdcSettings& adc)
{
    if (const auto* capacitive = std::get_if<CapacitiveBeamProfile>(&profile)) return capacitiveLimits(*capacitive);
    if (const auto* pair = std::get_if<CompliancePairProfile>(&profile)) return complianceLimits(*pair, channels, adc);
    return {};
}

std::vector<SensorLimit> profileLimits(const SensorProfile& profile, const std::vector<ChannelDescriptor>& channels,
                                       const straingauge::AdcSettings& adc)
{
    const auto* own = std::visit(
        [](const auto& p) -> const ProfileLimits* {
            if constexpr (requires { p.limits; })
                return &p.limits;
            else
                return nullptr;
        },
        profile);
    if (!own || !*own) return modelLimits(profile, channels, adc);
    std::vector<SensorLimit> limits;
    for (const auto& limit : **own) limits.push_back({limit, "the sensor profile's"});
    return limits;
}

}  // namespace tactiscope::core::sensors
