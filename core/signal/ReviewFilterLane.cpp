// ReviewFilterLane: the window widened by the filter's memory, filtered,
// and cut back to what was asked.
#include "core/signal/ReviewFilterLane.h"

#include "core/derived/ExactOverview.h"
#include "core/dsp/ChannelFilter.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace tactiscope::core::signal {
namespace {

constexpr double kForgotten = 1e-12;
constexpr std::uint64_t kLongestSettling = std::uint64_t{1} << 22;

}  // namespace

std::vector<std::string> reviewFilterLaneNames(const std::vector<ReviewFilter>& filters)
{
    std::map<std::string, int> filtersOn;
    std::vector<std::string> names;
    for (const auto& filter : filters) {
        const int nth = ++filtersOn[filter.channel];
        names.push_back(filter.channel + ".review" + (nth > 1 ? std::to_string(nth) : std::string()));
    }
    return names;
}

std::uint64_t settlingSamples(const dsp::FilterSettings& settings, double sampleRate_hz)
{
    dsp::FilterSettings causal = settings;
    causal.zeroPhase = false;
    dsp::ChannelFilter filter(causal, sampleRate_hz);
    // The impulse response: quiet for as long again as it took to fall
    // below the mark (at least a second) before it is taken as forgotten.
    double peak = 0.0;
    std::uint64_t lastLoud = 0;
    const auto quiet = static_cast<std::uint64_t>(std::ceil(sampleRate_hz));
    for (std::uint64_t n = 0; n < kLongestSettling; ++n) {
        const double y = std::fabs(filter.process(n == 0 ? 1.0 : 0.0));
        peak = std::max(peak, y);
        if (y > kForgotten * peak) lastLoud = n;
        if (n > 2 * lastLoud + quiet) break;
    }
    return std::min(lastLoud + 1, kLongestSettling);
}

ReviewFilterLane::ReviewFilterLane(storage::SessionSource& store, std::int64_t session, std::size_t channel,
                                   ChannelDescriptor stored, double sampleRate_hz, dsp::FilterSettings settings,
                                   std::string name)
    : m_store(store),
      m_session(session),
      m_channel(channel),
      m_descriptor(std::move(stored)),
      m_rate_hz(sampleRate_hz),
      m_settings(std::move(settings)),
      m_settling(0)
{
    if (const auto refusal = dsp::filterRefusal(m_settings, m_rate_hz)) throw std::invalid_argument(*refusal);
    m_settling = settlingSamples(m_settings, m_rate_hz);
    m_descriptor.name = std::move(name);
    m_descriptor.role.reset();  // a view of the channel, not the sensor's part it plays
}

std::vector<double> ReviewFilterLane::exact(std::uint64_t first, std::uint64_t count)
{
    const std::uint64_t total = m_store.sampleCount(m_session);
    if (first >= total || count == 0) return {};
    const std::uint64_t end = std::min(total, first + count);
    const std::uint64_t from = first - std::min(first, m_settling);
    const std::uint64_t to = m_settings.zeroPhase ? std::min(total, end + m_settling) : end;
    const std::vector<double> read = m_store.readChannel(m_session, m_channel, from, to - from);
    std::vector<double> filtered = dsp::filterSeries(m_settings, m_rate_hz, read);
    const auto skip = static_cast<std::ptrdiff_t>(first - from);
    return {filtered.begin() + skip, filtered.begin() + skip + static_cast<std::ptrdiff_t>(end - first)};
}

std::vector<storage::OverviewPoint> ReviewFilterLane::overview(std::uint64_t first, std::uint64_t count,
                                                               std::size_t points)
{
    const std::uint64_t total = m_store.sampleCount(m_session);
    const std::uint64_t end = std::min(total, first + std::min(count, total));
    if (end <= first || points == 0 || end - first > kExactLimit) return {};
    std::vector<storage::OverviewPoint> result;
    derived::appendExactOverview(exact(first, end - first), first, points, result);
    return result;
}

}  // namespace tactiscope::core::signal
