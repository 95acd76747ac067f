// StoredSites: the position channel found by its role (or kind) and read
// sample by sample around each crossing.
#include "core/storage/StoredSites.h"

#include "core/detector/PositionTrail.h"

#include <cmath>

namespace tactiscope::core::storage {

std::optional<detector::PositionAt> storedPositionAt(SessionSource& store, std::int64_t session)
{
    if (!store.parts(session).empty()) return std::nullopt;
    const auto channels = store.channels(session);
    std::vector<ChannelDescriptor> descriptors;
    for (const auto& c : channels) descriptors.push_back(c.descriptor);
    const auto found = detector::positionChannel(descriptors);
    if (!found || !(channels[*found].sampleRate_hz > 0.0)) return std::nullopt;
    const double rate_hz = channels[*found].sampleRate_hz;
    const std::size_t channel = *found;
    return [&store, session, channel, rate_hz](double t_s) -> std::optional<double> {
        const double at = t_s * rate_hz;
        if (!(at >= 0.0)) return std::nullopt;
        const auto below = static_cast<std::uint64_t>(std::floor(at));
        const auto samples = store.readChannel(session, channel, below, 2);
        if (samples.empty() || !std::isfinite(samples[0])) return std::nullopt;
        if (samples.size() < 2 || !std::isfinite(samples[1])) return samples[0];
        return samples[0] + (at - static_cast<double>(below)) * (samples[1] - samples[0]);
    };
}

detector::SiteGrouping storedSites(SessionSource& store, std::int64_t session,
                                   std::span<const detector::DefectEvent> defects)
{
    if (const auto positionAt = storedPositionAt(store, session)) return detector::scanSites(defects, *positionAt);
    return detector::scanSites(defects);
}

}  // namespace tactiscope::core::storage
