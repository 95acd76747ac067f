// A profile's channel scale in words, for where a session's channels are
// listed: its samples are the counts the board printed, read through this.
#include "core/sensors/ChannelScale.h"

#include <sstream>

namespace tactiscope::core::sensors {

std::string scaleText(const ChannelScale& scale)
{
    std::ostringstream text;
    if (scale.countsPerUnit == 1.0 && scale.offset_counts == 0.0) {
        text << "read as " << scale.unit;
    } else {
        text << scale.countsPerUnit << " a " << scale.unit;
        if (scale.offset_counts != 0.0) text << " from " << scale.offset_counts;
    }
    return text.str();
}

}  // namespace tactiscope::core::sensors
