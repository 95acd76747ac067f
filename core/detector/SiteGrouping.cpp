// SiteGrouping: placed crossings grouped into sites, each with its place
// and standard uncertainty, a span or why it has none; unplaced crossings
// grouped by speed and passes; the sites as people read them
// (core/detector/DefectSites.h).
#include "core/detector/DefectSites.h"
#include "core/detector/SiteArithmetic.h"
#include "core/text/UncertaintyFormat.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace tactiscope::core::detector {
namespace {

using sites::byRank;
using sites::crossingTime;
using sites::meanDifference;
using sites::median;
using sites::placedGroups;
using sites::speedOf;

// A single stroke out and back (a panel line's one stroke per panel): the
// crossings, in time order, change direction once and are as many each way.
// Each dent on the way out lies on the way back too, so the last crossing
// out and the first back are one dent, and so on outwards from the
// reversal: those pairs are the sites. Each pair must be one the probe
// could make: both crossings with a speed, and no further apart than going
// kMaxStroke_m to the turn and back at the slower of them. Anything else
// (a dent missed one way, more reversals, crossings minutes apart): none.
std::optional<std::vector<std::vector<std::size_t>>> outAndBack(std::span<const DefectEvent> events,
                                                                const std::vector<std::size_t>& inTimeOrder)
{
    if (inTimeOrder.size() < 2 || inTimeOrder.size() % 2 != 0) return std::nullopt;
    const std::size_t k = inTimeOrder.size() / 2;
    const int out = events[inTimeOrder.front()].direction;
    for (std::size_t j = 0; j < inTimeOrder.size(); ++j)
        if (events[inTimeOrder[j]].direction != (j < k ? out : -out) || out == 0) return std::nullopt;
    std::vector<std::vector<std::size_t>> pairs;
    for (std::size_t j = 0; j < k; ++j) {
        const DefectEvent& there = events[inTimeOrder[k - 1 - j]];
        const DefectEvent& back = events[inTimeOrder[k + j]];
        const auto v1 = speedOf(there), v2 = speedOf(back);
        if (!v1 || !v2 || crossingTime(back) - crossingTime(there) > 2.0 * kMaxStroke_m / std::min(*v1, *v2))
            return std::nullopt;
        pairs.push_back({inTimeOrder[k - 1 - j], inTimeOrder[k + j]});
    }
    return pairs;
}

// Why a site's crossings one way cannot be one dent with those the other
// way, if they cannot: one dent's crossings agree both ways in place (once
// the detector's delay is taken out) and in speed. Apart by more than
// kMinSiteSeparation_m, or speeds differing by more than kSameDentSpeeds,
// and either by more than three standard errors.
std::optional<std::string> directionsDisagree(std::span<const DefectEvent> events, const CrossingPlaces& places,
                                              const std::vector<std::size_t>& members)
{
    struct Way {
        std::vector<double> places, speeds;
    };
    std::array<Way, 2> ways;  // forward, backward
    for (const std::size_t i : members)
        if (events[i].direction != 0) {
            Way& way = ways[events[i].direction > 0 ? 0 : 1];
            way.places.push_back(*places.position_m[i]);
            way.speeds.push_back(*speedOf(events[i]));
        }
    if (ways[0].places.size() < 2 || ways[1].places.size() < 2) return std::nullopt;
    char why[128];
    const auto [apart, placeError] = meanDifference(ways[0].places, ways[1].places);
    if (std::abs(apart) > std::max(kMinSiteSeparation_m, 3.0 * placeError)) {
        std::snprintf(why, sizeof why, "its crossings each way lie %.0f mm apart (two dents each seen one way?)",
                      std::abs(apart) * 1e3);
        return why;
    }
    const auto [faster, speedError] = meanDifference(ways[0].speeds, ways[1].speeds);
    const double mean = 0.5 * (std::accumulate(ways[0].speeds.begin(), ways[0].speeds.end(), 0.0) /
                                   static_cast<double>(ways[0].speeds.size()) +
                               std::accumulate(ways[1].speeds.begin(), ways[1].speeds.end(), 0.0) /
                                   static_cast<double>(ways[1].speeds.size()));
    if (std::abs(faster) > std::max(kSameDentSpeeds * mean, 3.0 * speedError)) {
        std::snprintf(why, sizeof why,
                      "its crossings each way differ in speed by %.0f %% (two dents each seen one way?)",
                      100.0 * std::abs(faster) / mean);
        return why;
    }
    return std::nullopt;
}

// The variance of a site's mean place, from the scatter of its cycles'
// means (a cycle: a stroke out and the stroke back, numbered 2j and
// 2j + 1): a hand's stroke moves every crossing in it the same way, two
// strokes in a row share the reversal between them, and a crossing out
// and one back lie either side of the dent by the detector's delay, so the
// crossings' own scatter would count what cancels and miss what does not.
// Widened for few cycles to the spread of Student's t (×(m−1)/(m−3)); from
// the crossings themselves when there are fewer than kMinPlacedCrossings
// cycles.
double meanScatter(const DefectSite& site, const CrossingPlaces& places, double mean)
{
    std::map<std::size_t, std::pair<double, double>> cycles;  // cycle → (sum, count)
    for (const std::size_t i : site.crossings) {
        auto& [sum, count] = cycles[*places.stroke[i] / 2];
        sum += *places.position_m[i];
        count += 1.0;
    }
    std::vector<double> values;
    if (cycles.size() >= kMinPlacedCrossings)
        for (const auto& [cycle, entry] : cycles) values.push_back(entry.first / entry.second);
    else
        for (const std::size_t i : site.crossings) values.push_back(*places.position_m[i]);
    const auto m = static_cast<double>(values.size());
    double squares = 0.0;
    for (const double x : values) squares += (x - mean) * (x - mean);
    return squares / (m - 1.0) / m * (m - 1.0) / (m - 3.0);
}

// Half the difference between a site's crossings one way and the other,
// when it is more than twice its standard error: the detector's delay is
// not the same both ways beside another dent (measured on the simulator at
// 1 Hz with dents 30 mm apart: 4 mm apart, the site 1.6 mm off), and the
// truth lies about within it. 0 when the ways agree within their scatter.
double directionDoubt(std::span<const DefectEvent> events, const CrossingPlaces& places, const DefectSite& site)
{
    std::array<std::vector<double>, 2> ways;
    for (const std::size_t i : site.crossings)
        if (events[i].direction != 0) ways[events[i].direction > 0 ? 0 : 1].push_back(*places.position_m[i]);
    const auto [difference, standardError] = meanDifference(ways[0], ways[1]);
    return ways[0].size() >= 2 && ways[1].size() >= 2 && std::abs(difference) > 2.0 * standardError
               ? std::abs(difference) / 2.0
               : 0.0;
}

// A site's place and its standard uncertainty from its crossings (at
// least kMinPlacedCrossings of them): their mean, their standard deviation
// over √n widened to the spread of Student's t for few crossings, the
// detector's speed scale (kSpeedScaleUncertainty of the place), and,
// where the stroke's shape is not told, the whole difference Δ between
// the harmonic and the constant-speed places.
// A site whose crossings each cover more than kSpanExtent_m is a span.
void placeSite(DefectSite& site, std::span<const DefectEvent> events, const CrossingPlaces& places)
{
    const auto n = static_cast<double>(site.crossings.size());
    double sum = 0.0, shapeDoubt = 0.0;
    std::vector<double> extents;
    for (const std::size_t i : site.crossings) {
        const double x = *places.position_m[i];
        sum += x;
        if (places.constantSpeed_m[i]) shapeDoubt += (x - *places.constantSpeed_m[i]) / n;
        if (const auto v = speedOf(events[i])) extents.push_back((events[i].end_s - events[i].start_s) * *v);
    }
    const double mean = sum / n;
    // Too few crossings to show their own scatter, by a position channel:
    // each lies within its run (its extent along the stroke) and all within
    // their range, uniformly as far as can be told.
    double scatter = 0.0;
    if (site.crossings.size() >= kMinPlacedCrossings) {
        scatter = meanScatter(site, places, mean);
    } else {
        double lowest = *places.position_m[site.crossings.front()], highest = lowest;
        for (const std::size_t i : site.crossings) {
            lowest = std::min(lowest, *places.position_m[i]);
            highest = std::max(highest, *places.position_m[i]);
        }
        const double halfRun = extents.empty() ? 0.0 : median(extents) / 2.0;
        scatter = (std::pow((highest - lowest) / 2.0, 2) + halfRun * halfRun) / 3.0;
    }
    const double shape = places.shape == StrokeShape::Unknown ? shapeDoubt * shapeDoubt : 0.0;
    // The place's scale: the detector's speed by phase; by a position
    // channel, the detector's delay (the travel in a lag is the spacing).
    double scale = std::pow(kSpeedScaleUncertainty * mean, 2);
    if (places.fromPosition) {
        double travel = 0.0;
        for (const std::size_t i : site.crossings) travel += speedOf(events[i]).value_or(0.0) * events[i].peakLag_s / n;
        scale = std::pow(kDetectionDelayUncertainty * travel, 2) / 3.0;
    }
    site.kind = SiteKind::Site;
    site.position_m = mean;
    site.position_u_m = std::sqrt(scatter + shape + scale + std::pow(directionDoubt(events, places, site), 2));
    for (const std::size_t i : site.crossings)
        site.spread_m = std::max(site.spread_m, std::abs(*places.position_m[i] - mean));
    if (!extents.empty() && median(extents) > kSpanExtent_m) {
        const double half = places.halfStroke_m.value_or(kMaxStroke_m);
        site.kind = SiteKind::Span;
        site.from_m = std::max(-half, mean - median(extents) / 2.0);
        site.to_m = std::min(half, mean + median(extents) / 2.0);
    }
}

// Unplaced crossings as sites: one pass's are different sites, by their
// time from the pass's start (passes split at the long gaps). Passes are
// told from a rhythm: fewer than kMinPasses crossings show none, and each
// is a site of its own (never fewer sites than there may be).
std::vector<std::vector<std::size_t>> byPasses(std::span<const DefectEvent> events,
                                               const std::vector<std::size_t>& inTimeOrder)
{
    std::vector<std::vector<std::size_t>> passes, sites;
    if (inTimeOrder.size() < kMinPasses) {
        for (const std::size_t i : inTimeOrder) sites.push_back({i});
        return sites;
    }
    std::vector<double> gaps;
    for (std::size_t k = 1; k < inTimeOrder.size(); ++k)
        gaps.push_back(crossingTime(events[inTimeOrder[k]]) - crossingTime(events[inTimeOrder[k - 1]]));
    // Passes show as gaps of two kinds, the short ones within a pass more
    // than kPassGapRatio shorter than those between passes (a missed
    // crossing only makes a gap a whole number of cycles long): split at
    // the widest jump in the sorted gaps, if one is that wide.
    std::vector<double> sorted = gaps;
    std::ranges::sort(sorted);
    double between = 0.0, widest = kPassGapRatio;  // no jump: every crossing a pass of its own
    for (std::size_t k = 1; k < sorted.size(); ++k)
        if (sorted[k - 1] > 0.0 && sorted[k] / sorted[k - 1] > widest) {
            widest = sorted[k] / sorted[k - 1];
            between = std::sqrt(sorted[k] * sorted[k - 1]);
        }
    passes.push_back({inTimeOrder.front()});
    for (std::size_t k = 1; k < inTimeOrder.size(); ++k) {
        if (!(gaps[k - 1] < between)) passes.emplace_back();
        passes.back().push_back(inTimeOrder[k]);
    }
    std::map<std::size_t, double> offset;
    for (const auto& pass : passes)
        for (const std::size_t i : pass) offset[i] = crossingTime(events[i]) - crossingTime(events[pass.front()]);
    sites = byRank(passes, [&](std::size_t i) { return offset.at(i); });
    std::erase_if(sites, [](const auto& s) { return s.empty(); });
    return sites;
}

// Unplaced crossings with speeds as sites: one dent is crossed at one
// speed each way (a hand's jitter aside), so each way's crossings are
// split where their sorted speeds jump by more than half kSameDentSpeeds,
// and each such band by passes (dents at one speed crossed in turn). A band
// that is one site one way joins the band the other way at its speed, if
// that is one site too (one dent seen both ways).
std::vector<std::vector<std::size_t>> bySpeed(std::span<const DefectEvent> events, std::vector<std::size_t> crossings)
{
    struct Group {
        int direction;
        double speed;
        bool wholeBand;  // the only site of its speed band
        std::vector<std::size_t> members;
    };
    std::ranges::sort(crossings, {}, [&](std::size_t i) { return *speedOf(events[i]); });
    std::vector<std::vector<std::size_t>> bands;
    std::vector<int> bandDirection;
    for (const int direction : {1, -1, 0}) {
        std::optional<double> last;
        for (const std::size_t i : crossings) {
            if (events[i].direction != direction) continue;
            const double v = *speedOf(events[i]);
            if (!last || v > *last * (1.0 + kSameDentSpeeds / 2.0)) {
                bands.emplace_back();
                bandDirection.push_back(direction);
            }
            bands.back().push_back(i);
            last = v;
        }
    }
    std::vector<Group> groups;
    for (std::size_t b = 0; b < bands.size(); ++b) {
        std::ranges::sort(bands[b], {}, [&](std::size_t i) { return crossingTime(events[i]); });
        const auto sites = byPasses(events, bands[b]);
        for (const auto& members : sites) {
            std::vector<double> speeds;
            for (const std::size_t i : members) speeds.push_back(*speedOf(events[i]));
            groups.push_back({bandDirection[b], median(speeds), sites.size() == 1, members});
        }
    }
    std::vector<std::vector<std::size_t>> sites;
    std::vector<bool> joined(groups.size(), false);
    for (std::size_t a = 0; a < groups.size(); ++a) {
        if (joined[a]) continue;
        std::vector<std::size_t> site = groups[a].members;
        std::optional<std::size_t> other;
        for (std::size_t b = a + 1; b < groups.size() && groups[a].wholeBand && groups[a].direction != 0; ++b) {
            const double difference =
                2.0 * std::abs(groups[a].speed - groups[b].speed) / (groups[a].speed + groups[b].speed);
            if (!joined[b] && groups[b].wholeBand && groups[b].direction == -groups[a].direction &&
                difference <= kSameDentSpeeds &&
                (!other ||
                 std::abs(groups[b].speed - groups[a].speed) < std::abs(groups[*other].speed - groups[a].speed)))
                other = b;
        }
        if (other) {
            joined[*other] = true;
            site.insert(site.end(), groups[*other].members.begin(), groups[*other].members.end());
        }
        sites.push_back(std::move(site));
    }
    return sites;
}

// The placed site whose crossings the same way go at the speed of crossing
// i (within kSameDentSpeeds of their median, the nearest such): one dent
// is crossed at one speed each way.
std::optional<std::size_t> siteBySpeed(std::span<const DefectEvent> events, std::span<const DefectSite> sites,
                                       std::size_t i)
{
    const auto v = speedOf(events[i]);
    if (!v) return std::nullopt;
    std::optional<std::size_t> best;
    double bestDifference = kSameDentSpeeds;
    for (std::size_t k = 0; k < sites.size(); ++k) {
        std::vector<double> speeds;
        for (const std::size_t j : sites[k].crossings)
            if (events[j].direction == events[i].direction && speedOf(events[j])) speeds.push_back(*speedOf(events[j]));
        if (speeds.empty()) continue;
        const double typical = median(speeds);
        if (const double difference = 2.0 * std::abs(*v - typical) / (*v + typical); difference <= bestDifference)
            best = k, bestDifference = difference;
    }
    return best;
}

}  // namespace

SiteGrouping groupSites(std::span<const DefectEvent> events, const CrossingPlaces& places)
{
    if (places.position_m.size() != events.size() || places.partOf.size() != events.size() ||
        places.stroke.size() != events.size() || places.constantSpeed_m.size() != events.size())
        throw std::invalid_argument("defect sites: one place per event is needed");
    SiteGrouping grouping;
    std::map<std::size_t, std::size_t> siteOf;  // crossing → site
    const auto addSite = [&](std::vector<std::size_t> members) -> DefectSite& {
        DefectSite& site = grouping.sites.emplace_back();
        std::ranges::sort(members, {}, [&](std::size_t i) { return events[i].start_s; });
        site.crossings = std::move(members);
        for (const std::size_t i : site.crossings) {
            siteOf[i] = grouping.sites.size() - 1;
            if (events[i].direction != 0) ++(events[i].direction > 0 ? site.forward : site.backward);
        }
        site.first_s = events[site.crossings.front()].start_s;
        site.last_s = events[site.crossings.back()].end_s;
        return site;
    };
    const auto countWith = [&](std::size_t siteIndex, std::size_t i) {
        DefectSite& site = grouping.sites[siteIndex];
        siteOf.try_emplace(i, siteIndex);
        site.parts.push_back(i);
        site.first_s = std::min(site.first_s, events[i].start_s);
        site.last_s = std::max(site.last_s, events[i].end_s);
    };

    // Placed sites. A few crossings apart from every site (fewer than can
    // show their scatter) were placed off by a reversal the detector's
    // misses moved: they are counted with the site nearest them. With no
    // site to join, they are sites whose crossings are too few to place.
    std::vector<std::vector<std::size_t>> tooFew;
    std::vector<std::size_t> strays;
    std::map<std::size_t, std::string> disagreeing;  // crossing → why its site was not one dent
    // A position channel places even one crossing: its place is read, not
    // inferred from a stroke's other crossings.
    const std::size_t fewest = places.fromPosition ? 1 : kMinPlacedCrossings;
    for (auto& members : placedGroups(places.position_m, places.stroke, places.partOf)) {
        if (members.size() < fewest)
            tooFew.push_back(std::move(members));
        else if (const auto why = directionsDisagree(events, places, members))
            for (const std::size_t i : members) disagreeing[i] = *why;
        else
            placeSite(addSite(std::move(members)), events, places);
    }
    const std::size_t placedSites = grouping.sites.size();
    if (placedSites > 0) {
        for (const auto& members : tooFew) strays.insert(strays.end(), members.begin(), members.end());
        tooFew.clear();
    }
    for (const std::size_t i : strays) {
        const auto nearest = std::ranges::min_element(grouping.sites, {}, [&](const DefectSite& site) {
            return std::abs(*site.position_m - *places.position_m[i]);
        });
        countWith(static_cast<std::size_t>(nearest - grouping.sites.begin()), i);
    }

    // Crossings not placed (no speed, no known reversal around them, beyond
    // a typical stroke at either end): beside placed sites, each goes with
    // the site crossed at its speed the same way; the rest are grouped by
    // their speeds (by passes without speeds), unless they are a single
    // stroke out and back.
    std::vector<std::size_t> unplaced;
    for (std::size_t i = 0; i < events.size(); ++i) {
        if (places.partOf[i] || (places.position_m[i] && places.stroke[i] && !disagreeing.contains(i))) continue;
        if (const auto site = siteBySpeed(events, std::span(grouping.sites).first(placedSites), i))
            countWith(*site, i);
        else
            unplaced.push_back(i);
    }
    for (const auto& members : tooFew) unplaced.insert(unplaced.end(), members.begin(), members.end());
    std::ranges::sort(unplaced, {}, [&](std::size_t i) { return crossingTime(events[i]); });
    const bool speeds = !unplaced.empty() &&
                        std::ranges::all_of(unplaced, [&](std::size_t i) { return speedOf(events[i]).has_value(); });
    const auto mirrored = placedSites == 0 && tooFew.empty() ? outAndBack(events, unplaced) : std::nullopt;
    // Fewer than kMinPasses crossings show no rhythm and no speed of a
    // dent: each is a site of its own (never fewer sites than there may be).
    std::vector<std::vector<std::size_t>> unplacedSites = mirrored ? *mirrored
                                                          : speeds && unplaced.size() >= kMinPasses
                                                              ? bySpeed(events, unplaced)
                                                              : byPasses(events, unplaced);
    std::ranges::sort(unplacedSites, {}, [&](const auto& s) { return crossingTime(events[s.front()]); });
    for (auto& members : unplacedSites) {
        std::string why;
        for (const std::size_t i : members)
            if (disagreeing.contains(i))
                why = disagreeing.at(i);
            else if (why.empty() && places.position_m[i] && places.stroke[i])
                why = "too few crossings to place";
        addSite(std::move(members)).unplacedWhy = std::move(why);
    }

    // Each short run, ghost or crossing beyond the stroke with the site of
    // the crossing it is part of.
    for (std::size_t i = 0; i < events.size(); ++i) {
        std::optional<std::size_t> owner = places.partOf[i];
        for (std::size_t hops = 0; owner && places.partOf[*owner] && hops < events.size(); ++hops)
            owner = places.partOf[*owner];
        if (owner && siteOf.contains(*owner)) countWith(siteOf.at(*owner), i);
    }
    const auto explained = std::ranges::find_if(grouping.sites, [](const auto& s) { return !s.unplacedWhy.empty(); });
    grouping.method =
        events.empty()    ? "no defects"
        : placedSites > 0 ? places.model
        : explained != grouping.sites.end()
            ? (places.fromPosition ? places.model + ", " : std::string()) + "not placed: " + explained->unplacedWhy
        : mirrored ? "not placed: one stroke out and back, each dent crossed once each way"
        : places.model.rfind("not placed", 0) == 0 ? places.model
                                                   : "not placed";
    return grouping;
}

SiteGrouping scanSites(std::span<const DefectEvent> events, bool byPosition)
{
    return groupSites(events, byPosition ? placeByPosition(events) : placeCrossings(events));
}

SiteGrouping scanSites(std::span<const DefectEvent> events, const PositionAt& positionAt)
{
    return scanSites(withPositions(events, positionAt), true);
}

std::string sitePlaceText(const DefectSite& site, bool withUnit)
{
    const auto mm = [](double m) { return std::abs(m) < 0.5e-3 ? 0.0 : m * 1e3; };  // never "-0 mm"
    const std::string unit = withUnit ? " mm" : "";
    char text[96];
    switch (site.kind) {
    case SiteKind::Site:
        if (site.position_u_m >= 0.05e-3)
            return text::valueWithUncertainty(mm(*site.position_m), site.position_u_m * 1e3) + unit;
        std::snprintf(text, sizeof text, "%.1f%s", mm(*site.position_m), unit.c_str());  // synthetic: exact
        return text;
    case SiteKind::Span:
        std::snprintf(text, sizeof text, "span %.0f to %.0f%s", mm(site.from_m), mm(site.to_m), unit.c_str());
        return text;
    case SiteKind::Unplaced:
        break;
    }
    return site.unplacedWhy.empty() ? "unknown" : "unknown: " + site.unplacedWhy;
}

std::string siteText(const DefectSite& site)
{
    const std::size_t n = site.crossings.size();
    const std::string crossings = std::to_string(n) + (n == 1 ? " crossing" : " crossings");
    switch (site.kind) {
    case SiteKind::Site:
        return sitePlaceText(site, true) + " (" + crossings + (site.position_u_m >= 0.05e-3 ? ")" : ", no scatter)");
    case SiteKind::Span: {
        char covers[64];
        std::snprintf(covers, sizeof covers, "%.0f", (site.to_m - site.from_m) * 1e3);
        return sitePlaceText(site, true) + ": each crossing covers about " + covers + " mm, two dents or a long one (" +
               crossings + ")";
    }
    case SiteKind::Unplaced:
        break;
    }
    return "position " + sitePlaceText(site, false) + " (" + crossings + ")";
}

}  // namespace tactiscope::core::detector
