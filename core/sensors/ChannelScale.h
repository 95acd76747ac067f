// A profile's scale for a channel in ADC counts: a board that prints raw
// readings (a text board's plain numbers) is read as a probe whose
// converter the profile describes. The stored samples stay the counts the
// board sent; the mode reads them through the scale, and judges clipping
// from the declared full scale by the same rule as a TSP/1 probe's ADC
// (PalpationForces::atLimit). A displacement's scale is a length's ("d":
// {"unit": "mm"}: plain numbers in millimetres, counts_per_unit 1).
//   "channels": {"stiff": {"unit": "mN", "counts_per_unit": 20.48,
//                          "full_scale": 32767},
//                "d": {"unit": "mm", "counts_per_unit": 400, "offset": 2048}}
// The offset is the count of zero (a unipolar converter's mid-scale): a
// value is (count − offset) / counts_per_unit in the unit. A beam's force
// is measured from the zero taken with nothing pressed, as for a probe's
// bridge, so a beam's offset changes no force: it centres its clipping.
#pragma once

#include <map>
#include <optional>
#include <string>

namespace tactiscope::core::sensors {

struct ChannelScale {
    std::string unit;            // a strain, force or length unit (core/UnitScale.h): "mN", "µε", "mm"
    double countsPerUnit = 1.0;  // positive; 1 when the values are in the unit
    // The ADC's largest |count − offset|: a reading within 1 % of it is
    // clipped. None: the board's range is not known, and nothing is judged
    // clipped.
    std::optional<double> fullScale_counts;
    double offset_counts = 0.0;  // the count of zero

    friend bool operator==(const ChannelScale&, const ChannelScale&) = default;
};

// By the channel's name.
using ChannelScales = std::map<std::string, ChannelScale>;

// How its counts are read: "read as mm" (values in the unit), "215.3 a N",
// "400 a mm from 2048" (counts a unit, from the count of zero).
std::string scaleText(const ChannelScale& scale);

}  // namespace tactiscope::core::sensors
