// DefectSites: reversals from direction changes, each event placed within
// its stroke by the harmonic model, then neighbours within a tolerance merged.
#include "core/detector/DefectSites.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>

namespace tactiscope::core::detector {
namespace {

double midTime(const DefectEvent& event)
{
    return 0.5 * (event.start_s + event.end_s);
}

std::optional<double> speedOf(const DefectEvent& event)
{
    if (event.speed_m_per_s && std::isfinite(*event.speed_m_per_s) && *event.speed_m_per_s > 0.0)
        return event.speed_m_per_s;
    return std::nullopt;
}

// The reversal between two events of opposite direction: near a reversal
// the speed grows linearly with the time from it, so the times to it are
// in the ratio of the speeds (half way without them).
double reversalBetween(const DefectEvent& before, const DefectEvent& after)
{
    const double gap_s = midTime(after) - midTime(before);
    const auto v1 = speedOf(before);
    const auto v2 = speedOf(after);
    const double share = v1 && v2 ? *v1 / (*v1 + *v2) : 0.5;
    return midTime(before) + share * gap_s;
}

double median(std::vector<double> values)
{
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

}  // namespace

std::vector<std::optional<double>> strokePositions(std::span<const DefectEvent> events)
{
    std::vector<std::optional<double>> positions(events.size());
    std::vector<std::size_t> order(events.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::ranges::stable_sort(order, {}, [&](std::size_t i) { return midTime(events[i]); });

    std::vector<double> reversals_s;
    for (std::size_t k = 1; k < order.size(); ++k) {
        const DefectEvent& before = events[order[k - 1]];
        const DefectEvent& after = events[order[k]];
        if (before.direction != 0 && after.direction != 0 && before.direction != after.direction)
            reversals_s.push_back(reversalBetween(before, after));
    }
    if (reversals_s.size() < 2) return positions;  // no whole stroke: no stroke length to place by
    std::vector<double> strokes_s;
    for (std::size_t k = 1; k < reversals_s.size(); ++k) strokes_s.push_back(reversals_s[k] - reversals_s[k - 1]);
    const double medianStroke_s = median(strokes_s);

    for (std::size_t i = 0; i < events.size(); ++i) {
        const DefectEvent& event = events[i];
        const auto speed = speedOf(event);
        if (!speed || event.direction == 0) continue;
        const double t_s = midTime(event);
        const auto next = std::ranges::upper_bound(reversals_s, t_s);
        const std::optional<double> behind =
            next == reversals_s.begin() ? std::nullopt : std::optional<double>(t_s - *std::prev(next));
        const std::optional<double> ahead =
            next == reversals_s.end() ? std::nullopt : std::optional<double>(*next - t_s);
        const double stroke_s = behind && ahead ? *behind + *ahead : medianStroke_s;
        const double behind_s = behind.value_or(stroke_s - ahead.value_or(0.0));
        const double ahead_s = ahead.value_or(stroke_s - behind_s);
        if (!(behind_s > 0.0 && ahead_s > 0.0)) continue;  // beyond the median stroke: cannot be placed
        const double omega = std::numbers::pi / stroke_s;
        const auto distance = [&](double tau_s) { return *speed * std::tan(0.5 * omega * tau_s) / omega; };
        positions[i] = event.direction * 0.5 * (distance(behind_s) - distance(ahead_s));
    }
    return positions;
}

SiteGrouping groupSites(std::span<const DefectEvent> events, std::span<const std::optional<double>> positions,
                        double tolerance_m, std::string method)
{
    if (positions.size() != events.size())
        throw std::invalid_argument("defect sites: one position per event is needed");
    SiteGrouping grouping;
    grouping.method = std::move(method);
    std::vector<std::size_t> placed, unplaced;
    for (std::size_t i = 0; i < events.size(); ++i) (positions[i] ? placed : unplaced).push_back(i);
    if (placed.empty()) grouping.method = "not placed";
    std::ranges::stable_sort(placed, {}, [&](std::size_t i) { return *positions[i]; });

    const auto addCrossing = [&](DefectSite& site, std::size_t i) {
        site.crossings.push_back(i);
        if (events[i].direction != 0) ++(events[i].direction > 0 ? site.forward : site.backward);
    };
    for (std::size_t k = 0; k < placed.size(); ++k) {
        if (k == 0 || *positions[placed[k]] - *positions[placed[k - 1]] > tolerance_m) grouping.sites.emplace_back();
        addCrossing(grouping.sites.back(), placed[k]);
    }
    for (const std::size_t i : unplaced) addCrossing(grouping.sites.emplace_back(), i);

    for (DefectSite& site : grouping.sites) {
        std::ranges::sort(site.crossings, {}, [&](std::size_t i) { return events[i].start_s; });
        site.first_s = events[site.crossings.front()].start_s;
        site.last_s = events[site.crossings.back()].end_s;
        if (!positions[site.crossings.front()]) continue;
        double sum = 0.0;
        for (const std::size_t i : site.crossings) sum += *positions[i];
        const double mean = sum / static_cast<double>(site.crossings.size());
        site.position_m = mean;
        for (const std::size_t i : site.crossings)
            site.spread_m = std::max(site.spread_m, std::abs(*positions[i] - mean));
    }
    return grouping;
}

SiteGrouping scanSites(std::span<const DefectEvent> events)
{
    return groupSites(events, strokePositions(events));
}

}  // namespace tactiscope::core::detector
