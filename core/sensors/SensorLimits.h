// The limit alarms a probe comes with: its profile's own ("limits"), or
// else what its sensor model says it can take, so every reading past
// where the model holds is flagged:
// - a capacitive beam (seed 002): its force, warning where the
//   small-deflection model its readings rest on overstates the tip
//   deflection by 2 %, critical at 5 % (LargeDeflection.h);
// - a compliance probe (seed 001) whose beams' channels are in ADC
//   counts: the stiff beam (which clips first, being the stiffer at the
//   same press depth) at 90 % of the ADC's full scale (warning) and at the
//   level where its force is called clipped (critical, 99 %); with a
//   bipolar ADC, a window of either sign the counts must stay within.
// Each limit comes with the sentence that says where it comes from.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/sensors/SensorProfile.h"
#include "core/straingauge/StrainGaugeChain.h"
#include "core/trigger/LimitWatch.h"

#include <string>
#include <vector>

namespace tactiscope::core::sensors {

struct SensorLimit {
    trigger::LimitSpec limit;
    std::string basis;  // "the profile's", "small-deflection model off by 2 % / 5 %", …
};

inline constexpr double kWarningModelError = 0.02;
inline constexpr double kCriticalModelError = 0.05;
inline constexpr double kAdcWarningFraction = 0.90;
inline constexpr double kAdcCriticalFraction = 0.99;  // PalpationForces::kNearLimit's clipping

// The sensor model's limits for `profile` on `channels` (with their roles).
std::vector<SensorLimit> modelLimits(const SensorProfile& profile, const std::vector<ChannelDescriptor>& channels,
                                     const straingauge::AdcSettings& adc = {});

// The profile's own limits when it lists any (an empty list: none), else
// the model's.
std::vector<SensorLimit> profileLimits(const SensorProfile& profile, const std::vector<ChannelDescriptor>& channels,
                                       const straingauge::AdcSettings& adc = {});

}  // namespace tactiscope::core::sensors
