// ClockMappingText: the stored mapping read back and put in words.
#include "core/timing/ClockMappingText.h"

#include "core/timing/ClockMappingJson.h"

#include <cmath>
#include <cstdio>

namespace tactiscope::core::timing {

std::string clockMappingText(const std::string& clockJson)
{
    if (clockJson.empty()) return "not mapped (no frames with the device's times were seen)";
    const auto clock = clockMappingFromJson(clockJson);
    if (!clock) return "not mapped (the stored mapping does not read as one: damaged, or written by another program)";
    const auto u_s = clock->uncertainty_s(0.0);
    char text[384];
    int n = std::snprintf(text, sizeof text, "%+.6f s at the start", clock->host_s(0.0));
    // Too few frames: a drift figure would be noise, so none is given.
    if (!u_s) {
        std::snprintf(text + n, sizeof text - static_cast<std::size_t>(n), "; its drift not known (%s)",
                      describe(clock->basis));
        return text;
    }
    n += std::snprintf(text + n, sizeof text - static_cast<std::size_t>(n), " ± %.3f ms", *u_s * 1e3);
    n += std::snprintf(text + n, sizeof text - static_cast<std::size_t>(n), ", %.1f", std::abs(clock->drift) * 1e6);
    n += std::snprintf(text + n, sizeof text - static_cast<std::size_t>(n), " ± %.1f", clock->drift_u * 1e6);
    n += std::snprintf(text + n, sizeof text - static_cast<std::size_t>(n), " ppm %s (± %s",
                       clock->drift >= 0.0 ? "slow" : "fast", describe(clock->basis));
    // Where within its period a sample is taken: often the larger part.
    if (clock->samplePeriod_s > 0.0)
        std::snprintf(text + n, sizeof text - static_cast<std::size_t>(n),
                      "; in the time's ±, ± %.3f ms for where within its %.3g ms sample period a sample is taken)",
                      clock->samplePeriodUncertainty_s() * 1e3, clock->samplePeriod_s * 1e3);
    else
        std::snprintf(text + n, sizeof text - static_cast<std::size_t>(n), ")");
    return text;
}

}  // namespace tactiscope::core::timing
