// CapacitanceInput: a channel's scale to farads, or the refusal of counts
// without one.
#include "core/capacitive/CapacitanceInput.h"

#include "core/UnitScale.h"

#include <stdexcept>

namespace tactiscope::core::capacitive {

CapacitanceInput capacitanceInput(const ChannelDescriptor& channel, const sensors::ChannelScales& scales)
{
    if (!isCounts(channel.unit)) return {};
    const auto scale = scales.find(channel.name);
    const auto unit = scale != scales.end() ? physicalUnit(scale->second.unit) : std::nullopt;
    if (!unit || unit->kind != ChannelKind::Capacitance)
        throw std::invalid_argument("the capacitance " + channel.name +
                                    " is in counts and the sensor profile gives it no capacitance scale "
                                    "(\"channels\": {\"" +
                                    channel.name + "\": {\"unit\": \"pF\", \"counts_per_unit\": …, \"offset\": …}})");
    return {unit->factor / scale->second.countsPerUnit, scale->second.offset_counts};
}

}  // namespace tactiscope::core::capacitive
