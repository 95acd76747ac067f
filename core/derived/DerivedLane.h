// One derived channel of a session as a review lane; the lanes of one
// computation (a mode's ComputedColumns) share it.
#pragma once

#include "core/storage/TraceWindow.h"

#include <memory>
#include <optional>

namespace tactiscope::core::derived {

template <typename Channels>
class DerivedLane final : public storage::LaneSource {
public:
    DerivedLane(std::shared_ptr<Channels> channels, std::size_t index, std::optional<double> threshold = {})
        : m_channels(std::move(channels)),
          m_index(index),
          m_threshold(threshold)
    {
    }
    ChannelDescriptor descriptor() const override { return m_channels->channels()[m_index]; }
    std::vector<double> exact(std::uint64_t first, std::uint64_t count) override
    {
        return std::move(m_channels->read(first, count)[m_index]);
    }
    std::vector<storage::OverviewPoint> overview(std::uint64_t first, std::uint64_t count, std::size_t points) override
    {
        return m_channels->overview(m_index, first, count, points);
    }
    std::optional<double> threshold() const override { return m_threshold; }

private:
    std::shared_ptr<Channels> m_channels;
    std::size_t m_index;
    std::optional<double> m_threshold;
};

}  // namespace tactiscope::core::derived
