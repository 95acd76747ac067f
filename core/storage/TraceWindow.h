// What a review plot of one stored channel shows over a time span at a given
// width: the exact samples when there are few enough to tell apart (a few
// per pixel), otherwise the exact min and max of each pixel's stretch from
// the store's overview pyramid. So zooming reads only what is on screen, and
// the whole of an hour-long session costs about one read per pixel.
#pragma once

#include "core/storage/SessionSource.h"
#include "core/timing/ClockAlignment.h"

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace tactiscope::core::storage {

struct TraceWindow {
    bool exact = false;
    std::uint64_t firstIndex = 0;  // exact: the index of the first sample
    // Exact: each sample's time and value (low == high; NaN where lost).
    // Otherwise: the middle of each stretch and its min and max.
    std::vector<double> t_s;
    std::vector<double> low;
    std::vector<double> high;

    // The point nearest to t, or -1 when the window is empty.
    long long nearest(double t_s) const;
};

// Samples per pixel at or below which the exact samples are read.
inline constexpr double kExactSamplesPerPixel = 4.0;

// A lane on a clock of its own: a device's part of a session of several,
// at the device's rate, its sample times mapped onto the session's clock
// (none stored: its own times as they are).
struct LaneClock {
    double sampleRate_hz = 0.0;
    std::uint64_t sampleCount = 0;
    std::optional<timing::ClockMapping> mapping;

    double sessionTime_s(double own_s) const { return mapping ? mapping->host_s(own_s) : own_s; }
    double ownTime_s(double session_s) const;
};

// What a review lane plots: a stored channel, or a quantity derived from
// the stored ones (core/derived), read exactly or as a min/max overview.
class LaneSource {
public:
    virtual ~LaneSource() = default;
    virtual ChannelDescriptor descriptor() const = 0;
    // Its own rate, count and clock; none for a lane on the session's.
    virtual std::optional<LaneClock> clock() const { return std::nullopt; }
    // Samples [first, first + count), NaN where lost or undefined.
    virtual std::vector<double> exact(std::uint64_t first, std::uint64_t count) = 0;
    // About `points` min/max stretches of [first, first + count).
    virtual std::vector<OverviewPoint> overview(std::uint64_t first, std::uint64_t count, std::size_t points) = 0;
    // The level the lane is read against (the detector's threshold on R), if any.
    virtual std::optional<double> threshold() const { return std::nullopt; }
};

// A stored channel as a lane.
class StoredLane final : public LaneSource {
public:
    StoredLane(SessionSource& store, std::int64_t session, std::size_t channel, ChannelDescriptor descriptor)
        : m_store(store),
          m_session(session),
          m_channel(channel),
          m_descriptor(std::move(descriptor))
    {
    }
    // A part's channel is on its device's clock (`clock`).
    StoredLane(SessionSource& store, std::int64_t session, std::size_t channel, ChannelDescriptor descriptor,
               LaneClock clock)
        : StoredLane(store, session, channel, std::move(descriptor))
    {
        m_clock = std::move(clock);
    }
    ChannelDescriptor descriptor() const override { return m_descriptor; }
    std::optional<LaneClock> clock() const override { return m_clock; }
    std::vector<double> exact(std::uint64_t first, std::uint64_t count) override
    {
        return m_store.readChannel(m_session, m_channel, first, count);
    }
    std::vector<OverviewPoint> overview(std::uint64_t first, std::uint64_t count, std::size_t points) override
    {
        return m_store.overview(m_session, m_channel, first, count, points);
    }

private:
    SessionSource& m_store;
    std::int64_t m_session;
    std::size_t m_channel;
    ChannelDescriptor m_descriptor;
    std::optional<LaneClock> m_clock;
};

// The window of a lane over [from_s, to_s] (session seconds, clipped to
// the recording) for a plot `pixels` wide. One sample beyond each end is
// included when exact, so a line reaches the plot's edges. A lane with a
// clock of its own is read at its rate and count, over its own times of
// the span, and its points placed at their session times.
TraceWindow readTraceWindow(LaneSource& lane, double sampleRate_hz, std::uint64_t sampleCount, double from_s,
                            double to_s, std::size_t pixels);
// The same for stored channel `channel`.
TraceWindow readTraceWindow(SessionSource& store, std::int64_t session, std::size_t channel, double sampleRate_hz,
                            std::uint64_t sampleCount, double from_s, double to_s, std::size_t pixels);

}  // namespace tactiscope::core::storage
