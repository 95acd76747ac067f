// PositionTrail: a bounded window of (time, position) and its interpolation.
#include "core/detector/PositionTrail.h"

#include "core/detector/SiteArithmetic.h"

#include <algorithm>
#include <cmath>

namespace tactiscope::core::detector {

std::optional<std::size_t> positionChannel(std::span<const ChannelDescriptor> channels)
{
    for (std::size_t i = 0; i < channels.size(); ++i)
        if (channels[i].role == ChannelRole::Position) return i;
    for (std::size_t i = 0; i < channels.size(); ++i)
        if (!channels[i].role && channels[i].kind == ChannelKind::Position) return i;
    return std::nullopt;
}

PositionTrail::PositionTrail(std::size_t keepSamples, double period_s)
    : m_keep(std::max<std::size_t>(keepSamples, 2)),
      m_period_s(period_s)
{
}

void PositionTrail::push(double t_s, double position_m)
{
    m_samples.emplace_back(t_s, position_m);
    if (m_samples.size() > m_keep) m_samples.pop_front();
}

std::optional<double> PositionTrail::at(double t_s) const
{
    const auto after = std::ranges::lower_bound(m_samples, t_s, {}, &std::pair<double, double>::first);
    if (after == m_samples.end() || (after == m_samples.begin() && after->first != t_s)) return std::nullopt;
    if (after->first == t_s) return std::isfinite(after->second) ? std::optional(after->second) : std::nullopt;
    const auto& [t1, x1] = *after;
    const auto& [t0, x0] = *(after - 1);
    if (t1 - t0 > 1.5 * m_period_s || !std::isfinite(x0) || !std::isfinite(x1)) return std::nullopt;
    return x0 + (t_s - t0) / (t1 - t0) * (x1 - x0);
}

void PositionTrail::stamp(std::span<DefectEvent> events) const
{
    for (auto& e : events) e.position_m = at(sites::crossingTime(e));
}

}  // namespace tactiscope::core::detector
