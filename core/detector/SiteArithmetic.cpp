// SiteArithmetic: the shared arithmetic of placing and grouping crossings.
#include "core/detector/SiteArithmetic.h"

#include "core/detector/DefectSites.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace tactiscope::core::detector::sites {

double crossingTime(const DefectEvent& event)
{
    return 0.5 * (event.start_s + event.end_s) - kDetectionDelay * event.peakLag_s;
}

std::optional<double> speedOf(const DefectEvent& event)
{
    if (event.speed_m_per_s && std::isfinite(*event.speed_m_per_s) && *event.speed_m_per_s > 0.0)
        return event.speed_m_per_s;
    return std::nullopt;
}

double median(std::vector<double> values)
{
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

std::vector<std::vector<std::size_t>> byRank(const std::vector<std::vector<std::size_t>>& groups,
                                             const std::function<double(std::size_t)>& key)
{
    std::vector<double> sizes;
    for (const auto& g : groups)
        if (!g.empty()) sizes.push_back(static_cast<double>(g.size()));
    if (sizes.empty()) return {};
    const auto k = static_cast<std::size_t>(median(sizes));
    std::vector<std::vector<double>> ranked(k);
    for (const auto& g : groups)
        if (g.size() == k)
            for (std::size_t j = 0; j < k; ++j) ranked[j].push_back(key(g[j]));
    std::vector<double> centres;
    for (const auto& values : ranked) centres.push_back(median(values));
    std::vector<std::vector<std::size_t>> grouped(k);
    for (const auto& g : groups)
        for (const std::size_t i : g) {
            const auto nearest = std::ranges::min_element(centres, {}, [&](double c) { return std::abs(c - key(i)); });
            grouped[static_cast<std::size_t>(nearest - centres.begin())].push_back(i);
        }
    return grouped;
}

std::vector<std::vector<std::size_t>> placedGroups(std::span<const std::optional<double>> places,
                                                   std::span<const std::optional<std::size_t>> strokeOf,
                                                   std::span<const std::optional<std::size_t>> partOf)
{
    const auto position = [&](std::size_t i) { return *places[i]; };
    const auto centreOf = [&](const std::vector<std::size_t>& site) {
        std::vector<double> xs;
        for (const std::size_t i : site) xs.push_back(position(i));
        return median(xs);
    };
    std::map<std::size_t, std::vector<std::size_t>> strokes;
    for (std::size_t i = 0; i < places.size(); ++i)
        if (!partOf[i] && places[i] && strokeOf[i]) strokes[*strokeOf[i]].push_back(i);
    std::vector<std::vector<std::size_t>> byStroke;
    for (auto& [stroke, members] : strokes) {
        std::ranges::sort(members, {}, position);
        byStroke.push_back(members);
    }
    std::vector<std::vector<std::size_t>> ranked = byRank(byStroke, position);
    std::erase_if(ranked, [](const auto& s) { return s.empty(); });
    std::ranges::sort(ranked, {}, centreOf);
    std::vector<std::vector<std::size_t>> placed;
    for (auto& site : ranked) {
        if (!placed.empty() && std::abs(centreOf(site) - centreOf(placed.back())) < kMinSiteSeparation_m)
            placed.back().insert(placed.back().end(), site.begin(), site.end());
        else
            placed.push_back(std::move(site));
    }
    // A hand's jitter scatters a site's crossings more widely than the
    // detector does: the reach is three standard deviations of the scan's
    // own scatter about its sites, when that is wider.
    std::vector<double> deviations;
    for (const auto& site : placed)
        for (const std::size_t i : site) deviations.push_back(std::abs(position(i) - centreOf(site)));
    const double reach =
        deviations.empty() ? kSiteReach_m : std::max(kSiteReach_m, 3.0 * kMadToSigma * median(deviations));
    std::vector<std::size_t> strays;
    for (auto& site : placed) {
        const double centre = centreOf(site);
        std::erase_if(site, [&](std::size_t i) {
            const bool far = std::abs(position(i) - centre) > reach;
            if (far) strays.push_back(i);
            return far;
        });
    }
    std::ranges::sort(strays, {}, position);
    for (std::size_t k = 0; k < strays.size(); ++k) {
        if (k == 0 || position(strays[k]) - position(strays[k - 1]) > reach) placed.emplace_back();
        placed.back().push_back(strays[k]);
    }
    std::erase_if(placed, [](const auto& s) { return s.empty(); });
    std::ranges::sort(placed, {}, centreOf);
    return placed;
}

std::pair<double, double> meanDifference(const std::vector<double>& a, const std::vector<double>& b)
{
    if (a.size() < 2 || b.size() < 2) return {0.0, std::numeric_limits<double>::infinity()};
    double variance = 0.0;
    std::array<double, 2> means{};
    for (std::size_t w = 0; w < 2; ++w) {
        const auto& values = w == 0 ? a : b;
        const auto n = static_cast<double>(values.size());
        means[w] = std::accumulate(values.begin(), values.end(), 0.0) / n;
        for (const double x : values) variance += (x - means[w]) * (x - means[w]) / (n - 1.0) / n;
    }
    return {means[0] - means[1], std::sqrt(variance)};
}

}  // namespace tactiscope::core::detector::sites
