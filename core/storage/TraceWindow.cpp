// TraceWindow: exact samples or a min/max overview, by samples per pixel.
#include "core/storage/TraceWindow.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tactiscope::core::storage {

long long TraceWindow::nearest(double time_s) const
{
    if (t_s.empty()) return -1;
    const auto after = std::ranges::lower_bound(t_s, time_s);
    if (after == t_s.begin()) return 0;
    if (after == t_s.end()) return static_cast<long long>(t_s.size()) - 1;
    const auto before = after - 1;
    return (time_s - *before <= *after - time_s) ? before - t_s.begin() : after - t_s.begin();
}

TraceWindow readTraceWindow(SessionSource& store, std::int64_t session, std::size_t channel, double sampleRate_hz,
                            std::uint64_t sampleCount, double from_s, double to_s, std::size_t pixels)
{
    StoredLane lane(store, session, channel, {});
    return readTraceWindow(lane, sampleRate_hz, sampleCount, from_s, to_s, pixels);
}

// The mapping is a line: session = own·(1 + drift) + offset − drift·reference.
double LaneClock::ownTime_s(double session_s) const
{
    if (!mapping) return session_s;
    return (session_s - mapping->offset_s + mapping->drift * mapping->reference_s) / (1.0 + mapping->drift);
}

namespace {

// On the lane's own sample times.
TraceWindow readOwnTimes(LaneSource& lane, double sampleRate_hz, std::uint64_t sampleCount, double from_s, double to_s,
                         std::size_t pixels)
{
    TraceWindow window;
    if (sampleRate_hz <= 0.0 || sampleCount == 0 || !(to_s > from_s)) return window;
    const auto indexAt = [&](double t) {
        const double i = std::clamp(t * sampleRate_hz, 0.0, static_cast<double>(sampleCount));
        return static_cast<std::uint64_t>(i);
    };
    // One sample of margin on each side: the lines run off the plot's edges.
    const std::uint64_t first = indexAt(from_s) > 0 ? indexAt(from_s) - 1 : 0;
    const std::uint64_t end = std::min(sampleCount, indexAt(to_s) + 2);
    if (first >= end) return window;
    const std::uint64_t count = end - first;
    const std::size_t width = std::max<std::size_t>(pixels, 1);
    if (static_cast<double>(count) <= kExactSamplesPerPixel * static_cast<double>(width)) {
        window.exact = true;
        window.firstIndex = first;
        window.low = lane.exact(first, count);
        window.high = window.low;
        window.t_s.resize(window.low.size());
        for (std::size_t i = 0; i < window.t_s.size(); ++i)
            window.t_s[i] = static_cast<double>(first + i) / sampleRate_hz;
        return window;
    }
    for (const OverviewPoint& p : lane.overview(first, count, width)) {
        const bool stored = std::isfinite(p.min) && std::isfinite(p.max);  // a stretch wholly lost has neither
        const double mid = static_cast<double>(p.firstIndex) + static_cast<double>(p.count) / 2.0;
        window.t_s.push_back(mid / sampleRate_hz);
        window.low.push_back(stored ? p.min : std::numeric_limits<double>::quiet_NaN());
        window.high.push_back(stored ? p.max : std::numeric_limits<double>::quiet_NaN());
    }
    return window;
}

}  // namespace

TraceWindow readTraceWindow(LaneSource& lane, double sampleRate_hz, std::uint64_t sampleCount, double from_s,
                            double to_s, std::size_t pixels)
{
    const auto clock = lane.clock();
    if (!clock) return readOwnTimes(lane, sampleRate_hz, sampleCount, from_s, to_s, pixels);
    TraceWindow window = readOwnTimes(lane, clock->sampleRate_hz, clock->sampleCount, clock->ownTime_s(from_s),
                                      clock->ownTime_s(to_s), pixels);
    for (double& t : window.t_s) t = clock->sessionTime_s(t);
    return window;
}

}  // namespace tactiscope::core::storage
