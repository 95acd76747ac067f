// A filter set in review (issue 57): a stored channel filtered as the
// reviewer asks — zero-phase by default, as review may be, or causal as
// live — shown as a lane of its own beside the channel ("a.review"). The
// stored samples are never changed: each window is read with the samples
// the filter needs before it (and after it, zero-phase) to have forgotten
// its start (its impulse response decayed to 1e-12 of its peak), so the
// lane shows what the filter run over the whole session shows, within a
// billionth of the channel's scale, however the view is zoomed. Gaps
// restart the filter as everywhere else.
#pragma once

#include "core/dsp/FilterSettings.h"
#include "core/storage/SessionSource.h"
#include "core/storage/TraceWindow.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tactiscope::core::signal {

struct ReviewFilter {
    std::string channel;  // the stored channel's name (DEVICE/NAME in a session of several devices)
    dsp::FilterSettings settings;

    friend bool operator==(const ReviewFilter&, const ReviewFilter&) = default;
};

// Each filter's lane name, in order: "a.review", then "a.review2", … for
// the second on the same channel (DEVICE/a.review in a session of several).
std::vector<std::string> reviewFilterLaneNames(const std::vector<ReviewFilter>& filters);

class ReviewFilterLane final : public storage::LaneSource {
public:
    static constexpr std::uint64_t kExactLimit = 200'000;  // samples per overview
    // Throws std::invalid_argument (filterRefusal's words) for settings
    // that cannot filter the channel at its rate.
    ReviewFilterLane(storage::SessionSource& store, std::int64_t session, std::size_t channel, ChannelDescriptor stored,
                     double sampleRate_hz, dsp::FilterSettings settings, std::string name);

    ChannelDescriptor descriptor() const override { return m_descriptor; }
    std::vector<double> exact(std::uint64_t first, std::uint64_t count) override;
    // Empty for a range longer than kExactLimit: zoom in to see it.
    std::vector<storage::OverviewPoint> overview(std::uint64_t first, std::uint64_t count, std::size_t points) override;
    // The samples read on either side of a window.
    std::uint64_t settling() const { return m_settling; }

private:
    storage::SessionSource& m_store;
    std::int64_t m_session;
    std::size_t m_channel;
    ChannelDescriptor m_descriptor;
    double m_rate_hz;
    dsp::FilterSettings m_settings;
    std::uint64_t m_settling;
};

// Samples until the filter's impulse response stays below 1e-12 of its
// peak (at most 2^22): how far back a window must start to be the whole
// run's.
std::uint64_t settlingSamples(const dsp::FilterSettings& settings, double sampleRate_hz);

}  // namespace tactiscope::core::signal
