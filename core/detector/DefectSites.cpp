// DefectSites: short runs folded into crossings, reversals from direction
// changes kept only where they make plausible strokes, each crossing placed
// by its phase in its stroke (harmonic or constant-speed strokes), then
// grouped by the rule that one stroke crosses each defect once.
#include "core/detector/DefectSites.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
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

double median(std::vector<double> values)
{
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

// The reversal between two crossings of opposite direction: near a reversal
// the speed grows linearly with the time from it, so the times to it are in
// the ratio of the speeds (half way without them).
double reversalBetween(const DefectEvent& before, const DefectEvent& after)
{
    const double gap_s = midTime(after) - midTime(before);
    const auto v1 = speedOf(before);
    const auto v2 = speedOf(after);
    const double share = v1 && v2 ? *v1 / (*v1 + *v2) : 0.5;
    return midTime(before) + share * gap_s;
}

class Placer {
public:
    explicit Placer(std::span<const DefectEvent> events)
        : m_events(events),
          m_order(events.size()),
          m_rank(events.size())
    {
        m_places.position_m.resize(events.size());
        m_places.stroke.resize(events.size());
        m_places.partOf.resize(events.size());
        std::iota(m_order.begin(), m_order.end(), std::size_t{0});
        std::ranges::stable_sort(m_order, {}, [&](std::size_t i) { return midTime(events[i]); });
        for (std::size_t k = 0; k < m_order.size(); ++k) m_rank[m_order[k]] = k;
    }

    CrossingPlaces place()
    {
        if (m_events.empty()) return std::move(m_places);
        foldShortRuns();
        const auto reversals = plausibleReversals();
        if (reversals.size() < 2) {
            m_places.model = "not placed: no whole stroke between two reversals";
            return std::move(m_places);
        }
        placeByPhase(reversals);
        return std::move(m_places);
    }

private:
    bool isCrossing(std::size_t i) const { return !m_places.partOf[i]; }

    // The crossing nearest in time to event i, among those that are crossings.
    std::optional<std::size_t> nearestCrossing(std::size_t i) const
    {
        return nearest(i, [this](std::size_t j) { return isCrossing(j); });
    }

    // The event nearest in time to event i among those `eligible` takes,
    // walking out from i in time order (the earlier one on a tie).
    template <typename Eligible>
    std::optional<std::size_t> nearest(std::size_t i, const Eligible& eligible) const
    {
        std::optional<std::size_t> before, after;
        for (std::size_t k = m_rank[i]; k-- > 0;)
            if (eligible(m_order[k])) {
                before = m_order[k];
                break;
            }
        for (std::size_t k = m_rank[i] + 1; k < m_order.size(); ++k)
            if (eligible(m_order[k])) {
                after = m_order[k];
                break;
            }
        if (!before || !after) return before ? before : after;
        const double t = midTime(m_events[i]);
        return t - midTime(m_events[*before]) <= midTime(m_events[*after]) - t ? before : after;
    }

    // Marks `runs` as parts of their nearest crossings, all at once, so each
    // joins a crossing and not another of them.
    void fold(const std::vector<std::size_t>& runs)
    {
        for (const std::size_t i : runs) m_places.partOf[i] = i;
        for (const std::size_t i : runs) m_places.partOf[i] = nearestCrossing(i);
    }

    // A short run against the direction of the crossing nearest to it, and
    // within that crossing's echo (kEchoReach of its lag, the detector's
    // memory there), is the detector's flicker, not a crossing. A short one
    // along it is a crossing (a fast crossing is short), and so is one beyond
    // the echo: a weak crossing of the other direction (a dent near another,
    // or near the stroke's end) is short too, and folding it would merge
    // strokes.
    void foldShortRuns()
    {
        std::vector<double> durations;
        for (const auto& e : m_events) durations.push_back(e.end_s - e.start_s);
        const double typical = median(durations);
        const auto isShort = [&](std::size_t i) { return durations[i] < kShortRunFraction * typical; };
        const auto withinEcho = [&](std::size_t run, std::size_t crossing) {
            const DefectEvent& r = m_events[run];
            const DefectEvent& c = m_events[crossing];
            const double gap_s = std::max({0.0, r.start_s - c.end_s, c.start_s - r.end_s});
            return gap_s <= kEchoReach * c.peakLag_s;
        };
        std::vector<std::size_t> flicker;
        for (std::size_t i = 0; i < m_events.size(); ++i) {
            if (!isShort(i)) continue;
            const auto full = nearest(i, [&](std::size_t j) { return !isShort(j); });
            if (full && m_events[*full].direction != m_events[i].direction && withinEcho(i, *full))
                flicker.push_back(i);
        }
        fold(flicker);
    }

    // Reversal times between successive crossings of opposite direction,
    // with each implausibly short stroke's crossings folded into their
    // neighbours until none is left.
    std::vector<double> plausibleReversals()
    {
        for (;;) {
            std::vector<double> reversals;
            std::vector<std::pair<std::size_t, std::size_t>> between;  // the crossings each reversal lies between
            std::optional<std::size_t> previous;
            for (const std::size_t i : m_order) {
                if (!isCrossing(i) || m_events[i].direction == 0) continue;
                if (previous && m_events[*previous].direction != m_events[i].direction) {
                    reversals.push_back(reversalBetween(m_events[*previous], m_events[i]));
                    between.emplace_back(*previous, i);
                }
                previous = i;
            }
            if (reversals.size() < 3) return reversals;  // one whole stroke at most: nothing to compare
            std::vector<double> strokes;
            for (std::size_t k = 1; k < reversals.size(); ++k) strokes.push_back(reversals[k] - reversals[k - 1]);
            const double typical = median(strokes);
            const auto shortest = std::ranges::min_element(strokes);
            if (*shortest >= kMinStrokeFraction * typical) return reversals;
            // The crossings inside the short stroke: from the one after its
            // first reversal to the one before its second.
            const auto k = static_cast<std::size_t>(shortest - strokes.begin());
            const double from = midTime(m_events[between[k].second]);
            const double to = midTime(m_events[between[k + 1].first]);
            std::vector<std::size_t> inside;
            for (const std::size_t i : m_order)
                if (isCrossing(i) && midTime(m_events[i]) >= from && midTime(m_events[i]) <= to) inside.push_back(i);
            fold(inside);
        }
    }

    void placeByPhase(const std::vector<double>& reversals)
    {
        std::vector<double> strokes;
        for (std::size_t k = 1; k < reversals.size(); ++k) strokes.push_back(reversals[k] - reversals[k - 1]);
        const double typicalStroke_s = median(strokes);
        // A stroke much longer than the typical one hides strokes in which
        // no crossing was seen (a reversal is only told from a change of
        // direction): it spans about L/T of them. firstStroke[k] numbers the
        // strokes as the probe made them, for the stroke between reversals
        // k − 1 and k (k = 0 before the first).
        const auto hiddenSpan = [&](std::size_t k) -> std::size_t {
            if (k == 0 || k >= reversals.size()) return 1;
            const double ratio = strokes[k - 1] / typicalStroke_s;
            // An odd number: it starts and ends going the same way.
            return ratio > kLongStrokeFactor ? 2 * static_cast<std::size_t>(std::lround((ratio - 1.0) / 2.0)) + 1 : 1;
        };
        std::vector<std::size_t> firstStroke{0};
        for (std::size_t k = 1; k <= reversals.size(); ++k)
            firstStroke.push_back(firstStroke.back() + hiddenSpan(k - 1));

        struct Phased {
            std::size_t event;
            double tau_s, stroke_s, phase, speed;
        };
        std::vector<Phased> phased;
        for (const std::size_t i : m_order) {
            const DefectEvent& event = m_events[i];
            const auto speed = speedOf(event);
            if (!isCrossing(i) || !speed || event.direction == 0) continue;
            const double t_s = midTime(event);
            const auto next = std::ranges::upper_bound(reversals, t_s);
            const std::optional<double> behind =
                next == reversals.begin() ? std::nullopt : std::optional<double>(t_s - *std::prev(next));
            const std::optional<double> ahead = next == reversals.end() ? std::nullopt : std::optional(*next - t_s);
            const auto k = static_cast<std::size_t>(next - reversals.begin());
            double stroke_s = behind && ahead ? *behind + *ahead : typicalStroke_s;
            double tau_s = behind.value_or(stroke_s - ahead.value_or(0.0));
            std::size_t made = firstStroke[k];
            if (const std::size_t span = hiddenSpan(k); span > 1) {
                // The strokes it spans alternate in direction, starting with
                // its crossings' (the first after a reversal): a crossing lies
                // in one of its own direction, or cannot be placed. (Such a
                // stroke lies between two reversals: both are known.)
                const double fromStart_s = behind.value_or(0.0);
                stroke_s = strokes[k - 1] / static_cast<double>(span);
                const auto j = std::min(span - 1, static_cast<std::size_t>(fromStart_s / stroke_s));
                if (j % 2 != 0) continue;
                tau_s = fromStart_s - static_cast<double>(j) * stroke_s;
                made = firstStroke[k] + j;
            }
            if (!(tau_s > 0.0 && tau_s < stroke_s)) continue;  // beyond the typical stroke: cannot be placed
            m_places.stroke[i] = made;
            phased.push_back({i, tau_s, stroke_s, std::numbers::pi * tau_s / stroke_s, *speed});
        }
        if (phased.empty()) {
            m_places.model = "not placed: no crossing with a speed inside a stroke";
            return;
        }
        // Away from the reversals (sin φ ≥ 0.3), where both shapes are well
        // conditioned; all of them when none is.
        std::vector<const Phased*> used;
        for (const bool conditionedOnly : {true, false}) {
            for (const Phased& p : phased)
                if (!conditionedOnly || std::sin(p.phase) >= 0.3) used.push_back(&p);
            if (!used.empty()) break;
        }
        // The shapes differ in how the speed goes with sin φ (harmonic:
        // v = A·ω·sin φ; constant: v = V). Crossings at one |x| (one dent,
        // both directions) share sin φ and cannot tell them apart.
        double sumVS = 0.0, sumSS = 0.0, sumV = 0.0, lowest = 1.0, highest = 0.0;
        std::vector<double> amplitudes, speeds;
        for (const Phased* p : used) {
            const double sine = std::sin(p->phase);
            sumVS += p->speed * sine;
            sumSS += sine * sine;
            sumV += p->speed;
            lowest = std::min(lowest, sine);
            highest = std::max(highest, sine);
            amplitudes.push_back(p->speed * p->stroke_s / (std::numbers::pi * sine));
            speeds.push_back(p->speed);
        }
        const double harmonicScale = sumVS / sumSS, meanSpeed = sumV / static_cast<double>(used.size());
        double harmonicMisfit = 0.0, constantMisfit = 0.0;
        for (const Phased* p : used) {
            harmonicMisfit += std::pow(p->speed - harmonicScale * std::sin(p->phase), 2);
            constantMisfit += std::pow(p->speed - meanSpeed, 2);
        }
        const bool identifiable = highest - lowest >= kMinSineSpread;
        const bool constantSpeed = identifiable && constantMisfit < harmonicMisfit;
        const double amplitude_m = median(amplitudes);
        const double speed = median(speeds);
        for (const Phased& p : phased) {
            const int d = m_events[p.event].direction;
            m_places.position_m[p.event] =
                constantSpeed ? d * speed * (2.0 * p.tau_s - p.stroke_s) / 2.0 : -d * amplitude_m * std::cos(p.phase);
        }
        m_places.halfStroke_m = constantSpeed ? speed * typicalStroke_s / 2.0 : amplitude_m;
        m_places.model = constantSpeed ? "scan speed, constant-speed strokes"
                         : identifiable
                             ? "scan speed, harmonic strokes"
                             : "scan speed, harmonic strokes assumed (every crossing at one phase: the speed "
                               "profile is not known)";
        if (crossingsDifferByDirection(phased.size()))
            m_places.model += "; fewer crossings seen one way than the other (the detector missed some): a "
                              "reversal between crossings of different defects is placed by their speeds "
                              "alone, and places may be off by up to 20 mm";
    }

    // Whether strokes one way typically hold a different number of
    // crossings than strokes the other way: the detector missed a defect in
    // one direction, so some reversal lies between crossings of two
    // different defects (measured on the simulator: their places then
    // scatter by 10–20 mm and can make a site of their own).
    bool crossingsDifferByDirection(std::size_t placed) const
    {
        std::map<std::size_t, std::pair<int, std::size_t>> strokes;  // stroke → (direction, crossings)
        for (std::size_t i = 0; i < m_events.size() && placed > 0; ++i)
            if (m_places.stroke[i]) {
                auto& [direction, count] = strokes[*m_places.stroke[i]];
                direction = m_events[i].direction;
                ++count;
            }
        std::vector<double> forward, backward;
        for (const auto& [stroke, entry] : strokes)
            (entry.first > 0 ? forward : backward).push_back(static_cast<double>(entry.second));
        return !forward.empty() && !backward.empty() && median(forward) != median(backward);
    }

    std::span<const DefectEvent> m_events;
    std::vector<std::size_t> m_order;  // the events in time order
    std::vector<std::size_t> m_rank;   // each event's place in m_order
    CrossingPlaces m_places;
};

// Groups the members of `groups` (event indices) into sites: each group's
// j-th member is site j, with k the typical group size, at the median key of
// the groups of k; every member goes to the site nearest by its key.
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
    std::vector<std::vector<std::size_t>> sites(k);
    for (const auto& g : groups)
        for (const std::size_t i : g) {
            const auto nearest = std::ranges::min_element(centres, {}, [&](double c) { return std::abs(c - key(i)); });
            sites[static_cast<std::size_t>(nearest - centres.begin())].push_back(i);
        }
    return sites;
}

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
        if (!v1 || !v2 || midTime(back) - midTime(there) > 2.0 * kMaxStroke_m / std::min(*v1, *v2)) return std::nullopt;
        pairs.push_back({inTimeOrder[k - 1 - j], inTimeOrder[k + j]});
    }
    return pairs;
}

}  // namespace

CrossingPlaces placeCrossings(std::span<const DefectEvent> events)
{
    return Placer(events).place();
}

SiteGrouping groupSites(std::span<const DefectEvent> events, const CrossingPlaces& places)
{
    if (places.position_m.size() != events.size() || places.partOf.size() != events.size() ||
        places.stroke.size() != events.size())
        throw std::invalid_argument("defect sites: one place per event is needed");
    SiteGrouping grouping;
    const auto position = [&](std::size_t i) { return *places.position_m[i]; };
    const auto centreOf = [&](const std::vector<std::size_t>& site) {
        std::vector<double> xs;
        for (const std::size_t i : site) xs.push_back(position(i));
        return median(xs);
    };

    // Placed crossings: one stroke's are different sites.
    std::map<std::size_t, std::vector<std::size_t>> strokes;
    std::vector<std::size_t> unplaced;
    for (std::size_t i = 0; i < events.size(); ++i) {
        if (places.partOf[i]) continue;
        if (places.position_m[i] && places.stroke[i])
            strokes[*places.stroke[i]].push_back(i);
        else
            unplaced.push_back(i);
    }
    std::vector<std::vector<std::size_t>> byStroke;
    for (auto& [stroke, members] : strokes) {
        std::ranges::sort(members, {}, position);
        byStroke.push_back(members);
    }
    std::vector<std::vector<std::size_t>> ranked = byRank(byStroke, position);
    std::erase_if(ranked, [](const auto& s) { return s.empty(); });
    std::ranges::sort(ranked, {}, centreOf);
    // Sites closer than the detector's own scatter are one (a crossing it
    // split); a crossing out of reach of its site starts another.
    std::vector<std::vector<std::size_t>> placed;
    for (auto& site : ranked) {
        if (!placed.empty() && std::abs(centreOf(site) - centreOf(placed.back())) < kMinSiteSeparation_m)
            placed.back().insert(placed.back().end(), site.begin(), site.end());
        else
            placed.push_back(std::move(site));
    }
    std::vector<std::size_t> strays;
    for (auto& site : placed) {
        const double centre = centreOf(site);
        std::erase_if(site, [&](std::size_t i) {
            const bool far = std::abs(position(i) - centre) > kSiteReach_m;
            if (far) strays.push_back(i);
            return far;
        });
    }
    std::ranges::sort(strays, {}, position);
    for (std::size_t k = 0; k < strays.size(); ++k) {
        if (k == 0 || position(strays[k]) - position(strays[k - 1]) > kSiteReach_m) placed.emplace_back();
        placed.back().push_back(strays[k]);
    }
    std::erase_if(placed, [](const auto& s) { return s.empty(); });

    // Unplaced crossings: one pass's are different sites, by their time
    // from the pass's start (passes split at the long gaps).
    std::ranges::sort(unplaced, {}, [&](std::size_t i) { return midTime(events[i]); });
    // Passes are told from a rhythm: fewer than kMinPasses crossings show
    // none, and each is a site of its own (never fewer sites than there may
    // be), unless they are a single stroke out and back.
    std::vector<std::vector<std::size_t>> passes, unplacedSites;
    const auto mirrored = placed.empty() ? outAndBack(events, unplaced) : std::nullopt;
    if (mirrored) {
        unplacedSites = *mirrored;
    } else if (unplaced.size() < kMinPasses) {
        for (const std::size_t i : unplaced) unplacedSites.push_back({i});
    } else {
        std::vector<double> gaps;
        for (std::size_t k = 1; k < unplaced.size(); ++k)
            gaps.push_back(midTime(events[unplaced[k]]) - midTime(events[unplaced[k - 1]]));
        const auto [shortest, longest] = std::ranges::minmax(gaps);
        const bool even = longest < 1.5 * shortest;  // every crossing a pass of its own
        passes.push_back({unplaced.front()});
        for (std::size_t k = 1; k < unplaced.size(); ++k) {
            if (even || gaps[k - 1] > 0.5 * (shortest + longest)) passes.emplace_back();
            passes.back().push_back(unplaced[k]);
        }
    }
    std::map<std::size_t, double> offset;
    for (const auto& pass : passes)
        for (const std::size_t i : pass) offset[i] = midTime(events[i]) - midTime(events[pass.front()]);
    for (auto& site : byRank(passes, [&](std::size_t i) { return offset.at(i); })) unplacedSites.push_back(site);
    std::erase_if(unplacedSites, [](const auto& s) { return s.empty(); });

    std::map<std::size_t, std::size_t> siteOf;  // crossing → site
    const auto addSite = [&](std::vector<std::size_t> members, bool isPlaced) {
        DefectSite& site = grouping.sites.emplace_back();
        std::ranges::sort(members, {}, [&](std::size_t i) { return events[i].start_s; });
        site.crossings = std::move(members);
        for (const std::size_t i : site.crossings) {
            siteOf[i] = grouping.sites.size() - 1;
            if (events[i].direction != 0) ++(events[i].direction > 0 ? site.forward : site.backward);
        }
        site.first_s = events[site.crossings.front()].start_s;
        site.last_s = events[site.crossings.back()].end_s;
        if (!isPlaced) return;
        site.position_m = centreOf(site.crossings);
        for (const std::size_t i : site.crossings)
            site.spread_m = std::max(site.spread_m, std::abs(position(i) - *site.position_m));
    };
    std::ranges::sort(placed, {}, centreOf);
    for (auto& site : placed) addSite(std::move(site), true);
    std::ranges::sort(unplacedSites, {}, [&](const auto& s) { return midTime(events[s.front()]); });
    for (auto& site : unplacedSites) addSite(std::move(site), false);

    // Each short run with the site of the crossing it is part of.
    for (std::size_t i = 0; i < events.size(); ++i) {
        std::optional<std::size_t> owner = places.partOf[i];
        for (std::size_t hops = 0; owner && places.partOf[*owner] && hops < events.size(); ++hops)
            owner = places.partOf[*owner];
        if (!owner || !siteOf.contains(*owner)) continue;
        DefectSite& site = grouping.sites[siteOf.at(*owner)];
        site.parts.push_back(i);
        site.first_s = std::min(site.first_s, events[i].start_s);
        site.last_s = std::max(site.last_s, events[i].end_s);
    }
    const bool anyPlaced = std::ranges::any_of(grouping.sites, [](const auto& s) { return s.position_m.has_value(); });
    grouping.method = anyPlaced  ? places.model
                      : mirrored ? "not placed: one stroke out and back, each dent crossed once each way"
                                 : "not placed";
    return grouping;
}

SiteGrouping scanSites(std::span<const DefectEvent> events)
{
    return groupSites(events, placeCrossings(events));
}

std::string siteText(const DefectSite& site)
{
    const std::size_t n = site.crossings.size();
    const std::string crossings = std::to_string(n) + (n == 1 ? " crossing" : " crossings");
    if (!site.position_m) return "position unknown (" + crossings + ")";
    char text[96];
    const double mm = std::abs(*site.position_m) < 0.5e-3 ? 0.0 : *site.position_m * 1e3;  // never "-0 mm"
    if (n == 1)
        std::snprintf(text, sizeof text, "%.0f mm (1 crossing)", mm);
    else if (site.spread_m < 0.5e-3)
        std::snprintf(text, sizeof text, "%.0f mm (%s, spread below 1 mm)", mm, crossings.c_str());
    else
        std::snprintf(text, sizeof text, "%.0f mm ± %.0f mm (%s)", mm, site.spread_m * 1e3, crossings.c_str());
    return text;
}

}  // namespace tactiscope::core::detector
