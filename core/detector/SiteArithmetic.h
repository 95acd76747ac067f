// The small arithmetic the placing of crossings and the grouping of sites
// share (core/detector/DefectSites.h): each crossing's time, its speed, a
// median, the grouping of placed crossings into sites by stroke and rank,
// and the difference of two samples' means. Internal to core/detector.
#pragma once

#include "core/detector/DefectEvent.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace tactiscope::core::detector::sites {

// When the probe's centre was over the dent: the event's middle less the
// detector's delay (kDetectionDelay of its lag).
double crossingTime(const DefectEvent& event);
// The detector's speed, when it has a usable one.
std::optional<double> speedOf(const DefectEvent& event);
// The median of a non-empty sample.
double median(std::vector<double> values);

// Groups the members of `groups` (event indices) into sites: each group's
// j-th member is site j, with k the typical group size, at the median key of
// the groups of k; every member goes to the site nearest by its key.
std::vector<std::vector<std::size_t>> byRank(const std::vector<std::vector<std::size_t>>& groups,
                                             const std::function<double(std::size_t)>& key);

// The placed crossings as sites: one stroke's crossings are different
// sites (byRank over the strokes), sites closer than the detector's own
// scatter are one (a crossing it split), and a crossing out of reach of its
// site (kSiteReach_m, or three standard deviations of the scan's scatter)
// starts another. Sorted by place.
std::vector<std::vector<std::size_t>> placedGroups(std::span<const std::optional<double>> places,
                                                   std::span<const std::optional<std::size_t>> strokeOf,
                                                   std::span<const std::optional<std::size_t>> partOf);

// The difference of two samples' means and its standard error (each of
// at least two values; 0 and infinity otherwise).
std::pair<double, double> meanDifference(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace tactiscope::core::detector::sites
