// How a capacitive beam's channel becomes farads, one rule for the live
// readout and a stored session's review: a capacitance channel is in farads
// already; one in counts (a board printing its converter's raw readings)
// goes through the scale its capacitive profile gives it,
//   "channels": {"c": {"unit": "pF", "counts_per_unit": 2048000,
//                      "offset": 8388608}}
// (an AD7746: ±4.096 pF over its 24 bits, zero at mid-scale), a value being
// (count − offset) / counts_per_unit in the unit. The samples stay the
// counts the board sent.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/sensors/ChannelScale.h"

namespace tactiscope::core::capacitive {

struct CapacitanceInput {
    double faradsPerValue = 1.0;
    double offset = 0.0;  // the value of no capacitance

    double farads(double value) const { return (value - offset) * faradsPerValue; }
};

// Throws std::invalid_argument, naming the channel and how to give its
// scale, for a channel in counts the scales give no capacitance unit.
CapacitanceInput capacitanceInput(const ChannelDescriptor& channel, const sensors::ChannelScales& scales);

}  // namespace tactiscope::core::capacitive
