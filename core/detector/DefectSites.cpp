// DefectSites: short runs folded into crossings, reversals from direction
// changes kept only where they make plausible strokes, each crossing placed
// by its phase in its stroke (harmonic or constant-speed strokes), then
// grouped by the rule that one stroke crosses each defect once.
#include "core/detector/DefectSites.h"

#include "core/text/UncertaintyFormat.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace tactiscope::core::detector {
namespace {

// When the probe's centre was over the dent: the event's middle less the
// detector's delay (kDetectionDelay of its lag).
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

// The reversal between two crossings of opposite direction: near a reversal
// the speed grows linearly with the time from it, so the times to it are in
// the ratio of the speeds (half way without them).
double reversalBetween(const DefectEvent& before, const DefectEvent& after)
{
    const double gap_s = crossingTime(after) - crossingTime(before);
    const auto v1 = speedOf(before);
    const auto v2 = speedOf(after);
    const double share = v1 && v2 ? *v1 / (*v1 + *v2) : 0.5;
    return crossingTime(before) + share * gap_s;
}

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

// The placed crossings as sites: one stroke's crossings are different
// sites (byRank over the strokes), sites closer than the detector's own
// scatter are one (a crossing it split), and a crossing out of reach of its
// site (kSiteReach_m, or three standard deviations of the scan's scatter)
// starts another.
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

// The difference of two samples' means and its standard error (each of
// at least two values; 0 and infinity otherwise).
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

class Placer {
    // A crossing inside a stroke: τ from the reversal behind, T the
    // stroke's duration, φ = π·τ/T, v the detector's speed.
    struct Phased {
        std::size_t event;
        double tau_s, stroke_s, phase, speed;
    };

public:
    explicit Placer(std::span<const DefectEvent> events)
        : m_events(events),
          m_order(events.size()),
          m_rank(events.size())
    {
        m_places.position_m.resize(events.size());
        m_places.constantSpeed_m.resize(events.size());
        m_places.stroke.resize(events.size());
        m_places.partOf.resize(events.size());
        std::iota(m_order.begin(), m_order.end(), std::size_t{0});
        std::ranges::stable_sort(m_order, {}, [&](std::size_t i) { return crossingTime(events[i]); });
        for (std::size_t k = 0; k < m_order.size(); ++k) m_rank[m_order[k]] = k;
    }

    CrossingPlaces placeByPosition(const PositionAt& positionAt)
    {
        m_places.fromPosition = true;
        m_places.shape = StrokeShape::Harmonic;  // no shape: nothing to doubt
        m_places.model = "from the position channel";
        if (m_events.empty()) return std::move(m_places);
        foldShortRuns();
        std::size_t stroke = 0;
        std::optional<int> lastDirection;
        double farthest = 0.0;
        for (const std::size_t i : m_order) {
            if (!isCrossing(i)) continue;
            if (lastDirection && m_events[i].direction != 0 && m_events[i].direction != *lastDirection) ++stroke;
            if (m_events[i].direction != 0) lastDirection = m_events[i].direction;
            const auto x = positionAt(crossingTime(m_events[i]));
            if (!x || !std::isfinite(*x)) continue;
            m_places.position_m[i] = *x;
            m_places.stroke[i] = stroke;
            farthest = std::max(farthest, std::abs(*x));
        }
        m_places.halfStroke_m = farthest;
        return std::move(m_places);
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
        foldGhosts(reversals);
        const auto pairing = pairedReversals(reversals);
        if (std::ranges::none_of(pairing.paired, std::identity{})) {
            m_places.model = "not placed: no dent was seen both ways at a reversal (the detector saw each in one "
                             "direction only there), so no reversal is known";
            return std::move(m_places);
        }
        placeByPhase(pairing.repaired, pairing.known);
        if (pairing.repairedCount > 0)
            m_places.model += "; " + std::to_string(pairing.repairedCount) + " of " + std::to_string(reversals.size()) +
                              " reversals lay between crossings of different dents (the detector missed some): each "
                              "is taken from the reversals beside it";
        if (twoWayShare() < kTwoWayShare)
            unplaceAll("not placed: most crossings meet none of their site the other way (the detector saw dents "
                       "one way only), so the reversals between them cannot be told");
        else if (m_places.halfStroke_m && *m_places.halfStroke_m > kMaxStroke_m / 2.0)
            unplaceAll("not placed: the crossings' times and speeds imply strokes longer than a panel probe's "
                       "(1 m): a probe that rests between strokes, as on a panel line, or reversals the detector's "
                       "misses hid");
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
        const double t = crossingTime(m_events[i]);
        return t - crossingTime(m_events[*before]) <= crossingTime(m_events[*after]) - t ? before : after;
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

    // A crossing slower than both its neighbours in its stroke (by more
    // than kGhostSpeedShare) breaks the rise and fall of a stroke's speed:
    // the detector pairing one dent's view by one cantilever with the
    // next's by the other. Only within strokes of typical length, whose
    // crossings are one stroke's.
    void foldGhosts(const std::vector<double>& reversals)
    {
        std::vector<double> strokes;
        for (std::size_t k = 1; k < reversals.size(); ++k) strokes.push_back(reversals[k] - reversals[k - 1]);
        const double typical = median(strokes);
        std::map<std::size_t, std::vector<std::size_t>> byStroke;
        for (const std::size_t i : m_order) {
            const double t = crossingTime(m_events[i]);
            const auto k = static_cast<std::size_t>(std::ranges::upper_bound(reversals, t) - reversals.begin());
            if (isCrossing(i) && speedOf(m_events[i]) && k > 0 && k < reversals.size() &&
                strokes[k - 1] <= kLongStrokeFactor * typical)
                byStroke[k].push_back(i);
        }
        std::vector<std::size_t> ghosts;
        for (const auto& [stroke, members] : byStroke)
            for (std::size_t j = 1; j + 1 < members.size(); ++j) {
                const double slower = std::min(*speedOf(m_events[members[j - 1]]), *speedOf(m_events[members[j + 1]]));
                if (*speedOf(m_events[members[j]]) < kGhostSpeedShare * slower) ghosts.push_back(members[j]);
            }
        fold(ghosts);
    }

    // Reversal times between successive crossings of opposite direction,
    // and the crossings each lies between.
    std::pair<std::vector<double>, std::vector<std::pair<std::size_t, std::size_t>>> directionChanges() const
    {
        std::vector<double> reversals;
        std::vector<std::pair<std::size_t, std::size_t>> between;
        std::optional<std::size_t> previous;
        for (const std::size_t i : m_order) {
            if (!isCrossing(i) || m_events[i].direction == 0) continue;
            if (previous && m_events[*previous].direction != m_events[i].direction) {
                reversals.push_back(reversalBetween(m_events[*previous], m_events[i]));
                between.emplace_back(*previous, i);
            }
            previous = i;
        }
        return {reversals, between};
    }

    // Reversal times between successive crossings of opposite direction,
    // with each implausibly short stroke's crossings folded into their
    // neighbours until none is left.
    std::vector<double> plausibleReversals()
    {
        for (;;) {
            auto [reversals, between] = directionChanges();
            m_between = between;
            if (reversals.size() < 3) return reversals;  // one whole stroke at most: nothing to compare
            std::vector<double> strokes;
            for (std::size_t k = 1; k < reversals.size(); ++k) strokes.push_back(reversals[k] - reversals[k - 1]);
            const double typical = median(strokes);
            const auto shortest = std::ranges::min_element(strokes);
            if (*shortest >= kMinStrokeFraction * typical) return reversals;
            // The crossings inside the short stroke: from the one after its
            // first reversal to the one before its second.
            const auto k = static_cast<std::size_t>(shortest - strokes.begin());
            const double from = crossingTime(m_events[between[k].second]);
            const double to = crossingTime(m_events[between[k + 1].first]);
            std::vector<std::size_t> inside;
            for (const std::size_t i : m_order)
                if (isCrossing(i) && crossingTime(m_events[i]) >= from && crossingTime(m_events[i]) <= to)
                    inside.push_back(i);
            fold(inside);
        }
    }

    // Places the crossings between known reversals (or beyond a known one
    // at either end of the scan).
    void placeByPhase(const std::vector<double>& reversals, const std::vector<bool>& known)
    {
        std::ranges::fill(m_places.position_m, std::nullopt);
        std::ranges::fill(m_places.constantSpeed_m, std::nullopt);
        std::ranges::fill(m_places.stroke, std::nullopt);
        m_places.halfStroke_m.reset();
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

        std::vector<Phased> phased;
        for (const std::size_t i : m_order) {
            const DefectEvent& event = m_events[i];
            const auto speed = speedOf(event);
            if (!isCrossing(i) || !speed || event.direction == 0) continue;
            const double t_s = crossingTime(event);
            const auto next = std::ranges::upper_bound(reversals, t_s);
            const auto k = static_cast<std::size_t>(next - reversals.begin());
            const bool hasBehind = k > 0, hasAhead = k < reversals.size();
            if ((hasBehind && !known[k - 1]) || (hasAhead && !known[k])) continue;
            const double behind_s = hasBehind ? t_s - reversals[k - 1] : 0.0;
            const double ahead_s = hasAhead ? reversals[k] - t_s : 0.0;
            double stroke_s = hasBehind && hasAhead ? behind_s + ahead_s : typicalStroke_s;
            double tau_s = hasBehind ? behind_s : stroke_s - ahead_s;
            std::size_t made = firstStroke[k];
            if (const std::size_t span = hiddenSpan(k); span > 1) {
                // The strokes it spans alternate in direction, starting with
                // its crossings' (the first after a reversal): a crossing lies
                // in one of its own direction, or cannot be placed. (Such a
                // stroke lies between two reversals: both are known.)
                const double fromStart_s = behind_s;
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
        // Each crossing's own stroke length where it lies away from the
        // reversals (a crossing near one gives v/sin φ as 0/0); the scan's
        // median for the others, and as the stroke no place lies beyond.
        const auto conditioned = [](const Phased& p) { return std::sin(p.phase) >= kConditionedSine; };
        const auto ownAmplitude = [](const Phased& p) {
            return p.speed * p.stroke_s / (std::numbers::pi * std::sin(p.phase));
        };
        std::vector<double> amplitudes, lengths;
        for (const bool conditionedOnly : {true, false}) {
            for (const Phased& p : phased)
                if (!conditionedOnly || conditioned(p)) {
                    amplitudes.push_back(ownAmplitude(p));
                    lengths.push_back(p.speed * p.stroke_s);
                }
            if (!amplitudes.empty()) break;
        }
        const double amplitude_m = median(amplitudes);
        const double constantHalf_m = median(lengths) / 2.0;
        for (const Phased& p : phased) {
            const int d = m_events[p.event].direction;
            const double own = conditioned(p) ? ownAmplitude(p) : amplitude_m;
            m_places.position_m[p.event] = -d * own * std::cos(p.phase);
            m_places.constantSpeed_m[p.event] = d * p.speed * (p.tau_s - p.stroke_s / 2.0);
        }
        // No stroke goes farther than either shape makes it (a machine's
        // farther than a hand's at the same speeds in its middle), and a
        // crossing's constant-speed place is the nearer of its two: one
        // beyond even that is in a stroke whose reversals were inferred
        // wrongly.
        const double longest_m = std::max(amplitude_m, constantHalf_m);
        foldBeyond(longest_m, m_places.constantSpeed_m);
        m_places.shape = strokeShape(phased);
        switch (m_places.shape) {
        case StrokeShape::ConstantSpeed:
            m_places.position_m = m_places.constantSpeed_m;
            m_places.halfStroke_m = constantHalf_m;
            break;
        case StrokeShape::Harmonic:
            m_places.halfStroke_m = amplitude_m;
            foldBeyond(amplitude_m, m_places.position_m);
            break;
        case StrokeShape::Unknown:
            // The truth lies between the two places and within the stroke.
            m_places.halfStroke_m = longest_m;
            for (auto& x : m_places.position_m)
                if (x) x = std::clamp(*x, -longest_m, longest_m);
            break;
        }
        m_places.model = m_places.shape == StrokeShape::ConstantSpeed ? "scan speed, constant-speed strokes"
                         : m_places.shape == StrokeShape::Harmonic
                             ? "scan speed, harmonic strokes"
                             : "scan speed, harmonic strokes assumed (the crossings' speeds do not tell the "
                               "stroke's shape: one dent, or speeds that fit either); a machine's constant-speed "
                               "stroke would put each site nearer the centre, and its ± counts that";
    }

    struct Pairing {
        std::vector<bool> paired;      // each reversal between one dent's crossings out and back
        std::vector<double> repaired;  // the reversals, the unpaired ones retaken where they can be
        std::vector<bool> known;       // paired or retaken: crossings beside any other are not placed
        std::size_t repairedCount = 0;
    };

    // Which reversals lie between one dent's crossings out and back. At
    // each end of the stroke the outermost dent seen both ways is crossed
    // out and back within a typical gap, at one speed. A reversal whose gap
    // is longer than the typical one by kPairedGapFactor (or three standard
    // deviations there), or every reversal at an end where the speeds out
    // and back differ systematically (kSameDentSpeeds), lies between two
    // different dents (the detector missed the outer one there) and was
    // placed by speeds that are not one dent's: it is retaken midway
    // between the paired reversals beside it (strokes out and back take
    // equal times), or a cycle from a paired one at its own end.
    Pairing pairedReversals(const std::vector<double>& reversals) const
    {
        Pairing pairing;
        pairing.repaired = reversals;
        // Per end of the stroke (even and odd reversals): the gaps out and
        // back, and the signed speed differences across them.
        std::array<std::vector<double>, 2> gaps, differences;
        for (std::size_t k = 0; k < m_between.size(); ++k) {
            const auto& [before, after] = m_between[k];
            gaps[k % 2].push_back(crossingTime(m_events[after]) - crossingTime(m_events[before]));
            const auto v1 = speedOf(m_events[before]), v2 = speedOf(m_events[after]);
            if (v1 && v2) differences[k % 2].push_back(2.0 * (*v1 - *v2) / (*v1 + *v2));
        }
        std::array<double, 2> longestPaired{};
        std::array<bool, 2> differentDents{};
        for (const std::size_t end : {0u, 1u}) {
            if (gaps[end].empty()) continue;
            const double typical = median(gaps[end]);
            std::vector<double> deviations;
            for (const double gap : gaps[end]) deviations.push_back(std::abs(gap - typical));
            const double spread = kMadToSigma * median(deviations);
            longestPaired[end] = typical + std::max(3.0 * spread, (kPairedGapFactor - 1.0) * typical);
            const auto n = static_cast<double>(differences[end].size());
            if (n < 2) continue;
            const double mean = std::accumulate(differences[end].begin(), differences[end].end(), 0.0) / n;
            double squares = 0.0;
            for (const double d : differences[end]) squares += (d - mean) * (d - mean);
            const double standardError = std::sqrt(squares / (n - 1.0) / n);
            differentDents[end] = std::abs(mean) > std::max(3.0 * standardError, kSameDentSpeeds);
        }
        for (std::size_t k = 0; k < m_between.size(); ++k)
            pairing.paired.push_back(!differentDents[k % 2] && gaps[k % 2][k / 2] <= longestPaired[k % 2]);
        const auto& paired = pairing.paired;
        pairing.known = paired;
        std::vector<double> strokes, cycles;
        for (std::size_t k = 1; k < reversals.size(); ++k) strokes.push_back(reversals[k] - reversals[k - 1]);
        for (std::size_t k = 2; k < reversals.size(); ++k)
            if (paired[k] && paired[k - 2]) cycles.push_back(reversals[k] - reversals[k - 2]);
        const double typical = median(strokes);
        const double cycle = cycles.empty() ? 2.0 * typical : median(cycles);
        const auto typicalCycle = [&](double span_s) { return span_s <= kLongStrokeFactor * cycle; };
        for (std::size_t k = 0; k < reversals.size(); ++k) {
            if (paired[k]) continue;
            std::optional<double> retaken;
            if (k >= 1 && k + 1 < reversals.size() && paired[k - 1] && paired[k + 1] &&
                typicalCycle(reversals[k + 1] - reversals[k - 1]))
                retaken = 0.5 * (reversals[k - 1] + reversals[k + 1]);
            else if (k >= 2 && paired[k - 2] && typicalCycle(reversals[k] - reversals[k - 2]))
                retaken = reversals[k - 2] + cycle;
            else if (k + 2 < reversals.size() && paired[k + 2] && typicalCycle(reversals[k + 2] - reversals[k]))
                retaken = reversals[k + 2] - cycle;
            if (!retaken) continue;
            // Still between the two crossings it separates.
            const auto& [before, after] = m_between[k];
            pairing.repaired[k] = std::clamp(*retaken, crossingTime(m_events[before]), crossingTime(m_events[after]));
            pairing.known[k] = true;
            ++pairing.repairedCount;
        }
        return pairing;
    }

    // The share of placed crossings that meet a crossing of their site the
    // other way: one dent seen both ways has as many each way. Sites seen
    // one way only are a sign that the reversals at one end lie between
    // crossings of different dents, at speeds too alike to tell (a dent
    // seen one way beside one seen both ways: its reversals at one end are
    // then out over one dent and back over the other, and either dent's
    // crossings each way are placed apart).
    double twoWayShare() const
    {
        double placed = 0.0, paired = 0.0;
        for (const auto& site : placedGroups(m_places.position_m, m_places.stroke, m_places.partOf)) {
            std::size_t forward = 0, backward = 0;
            for (const std::size_t i : site) (m_events[i].direction > 0 ? forward : backward) += 1;
            placed += static_cast<double>(site.size());
            paired += 2.0 * static_cast<double>(std::min(forward, backward));
        }
        return placed > 0.0 ? paired / placed : 1.0;
    }

    void unplaceAll(std::string why)
    {
        std::ranges::fill(m_places.position_m, std::nullopt);
        std::ranges::fill(m_places.constantSpeed_m, std::nullopt);
        std::ranges::fill(m_places.stroke, std::nullopt);
        m_places.halfStroke_m.reset();
        m_places.model = std::move(why);
    }

    std::optional<double> relativeSpeedDifference(std::size_t i, std::size_t j) const
    {
        const auto v1 = speedOf(m_events[i]), v2 = speedOf(m_events[j]);
        if (!v1 || !v2) return std::nullopt;
        return 2.0 * std::abs(*v1 - *v2) / (*v1 + *v2);
    }

    // A crossing whose place (in `places`) lies beyond the stroke's
    // half-length is in a stroke whose reversals were inferred wrongly (the
    // detector missed crossings around it): it is not placed, and is
    // counted as a part of the placed crossing nearest it (the outermost
    // site on its side).
    void foldBeyond(double half_m, std::vector<std::optional<double>> places)
    {
        std::vector<std::size_t> beyond, within;
        for (std::size_t i = 0; i < m_events.size(); ++i) {
            if (!places[i] || m_places.partOf[i]) continue;
            (std::abs(*places[i]) > half_m ? beyond : within).push_back(i);
        }
        for (const std::size_t i : beyond) {
            m_places.position_m[i].reset();
            m_places.constantSpeed_m[i].reset();
            m_places.stroke[i].reset();
            if (!within.empty())
                m_places.partOf[i] = *std::ranges::min_element(
                    within, {}, [&](std::size_t j) { return std::abs(*places[j] - *places[i]); });
        }
    }

    // The stroke's shape from the speeds at the sites (grouped by their
    // harmonic places): each site's mean w = v·T against its mean sin φ,
    // weighted by the standard error its own crossings show, fitted as
    // w ∝ sin φ (harmonic) and as w constant; a shape only when its χ² is
    // lower by kShapeEvidence.
    StrokeShape strokeShape(const std::vector<Phased>& phased) const
    {
        std::map<std::size_t, const Phased*> byEvent;
        for (const Phased& p : phased) byEvent[p.event] = &p;
        struct SiteSpeeds {
            double w, sine, variance;
        };
        std::vector<SiteSpeeds> sites;
        for (const auto& members : placedGroups(m_places.position_m, m_places.stroke, m_places.partOf)) {
            if (members.size() < kMinPlacedCrossings) continue;
            double sumW = 0.0, sumWW = 0.0, sumSine = 0.0;
            for (const std::size_t i : members) {
                const auto& p = *byEvent.at(i);
                const double w = p.speed * p.stroke_s;
                sumW += w, sumWW += w * w, sumSine += std::sin(p.phase);
            }
            const auto n = static_cast<double>(members.size());
            const double mean = sumW / n;
            // Never below a 1 % scatter per crossing (the detector's lag
            // steps), and the detector's speed scale at the site, the same
            // in all its crossings, on top.
            const double perCrossing = std::max((sumWW - n * mean * mean) / (n - 1.0), std::pow(0.01 * mean, 2));
            sites.push_back({mean, sumSine / n, perCrossing / n + std::pow(kSpeedScaleUncertainty * mean, 2)});
        }
        if (sites.size() < 2) return StrokeShape::Unknown;
        double sws = 0.0, sss = 0.0, sw = 0.0, s1 = 0.0;
        for (const auto& site : sites) {
            sws += site.w * site.sine / site.variance;
            sss += site.sine * site.sine / site.variance;
            sw += site.w / site.variance;
            s1 += 1.0 / site.variance;
        }
        const double scale = sws / sss, length = sw / s1;
        double harmonicChi2 = 0.0, constantChi2 = 0.0;
        for (const auto& site : sites) {
            harmonicChi2 += std::pow(site.w - scale * site.sine, 2) / site.variance;
            constantChi2 += std::pow(site.w - length, 2) / site.variance;
        }
        if (constantChi2 - harmonicChi2 > kShapeEvidence) return StrokeShape::Harmonic;
        if (harmonicChi2 - constantChi2 > kShapeEvidence) return StrokeShape::ConstantSpeed;
        return StrokeShape::Unknown;
    }

    std::span<const DefectEvent> m_events;
    std::vector<std::pair<std::size_t, std::size_t>> m_between;  // the crossings each reversal lies between
    std::vector<std::size_t> m_order;                            // the events in time order
    std::vector<std::size_t> m_rank;                             // each event's place in m_order
    CrossingPlaces m_places;
};

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
    const double scatter = meanScatter(site, places, mean);
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

CrossingPlaces placeCrossings(std::span<const DefectEvent> events)
{
    return Placer(events).place();
}

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
    for (auto& members : placedGroups(places.position_m, places.stroke, places.partOf)) {
        if (members.size() < kMinPlacedCrossings)
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
    grouping.method = placedSites > 0                     ? places.model
                      : explained != grouping.sites.end() ? "not placed: " + explained->unplacedWhy
                      : mirrored ? "not placed: one stroke out and back, each dent crossed once each way"
                      : places.model.rfind("not placed", 0) == 0 ? places.model
                                                                 : "not placed";
    return grouping;
}

SiteGrouping scanSites(std::span<const DefectEvent> events)
{
    return groupSites(events, placeCrossings(events));
}

PositionAt positionFromSamples(std::vector<double> samples, double t0_s, double dt_s)
{
    return [samples = std::move(samples), t0_s, dt_s](double t_s) -> std::optional<double> {
        const double at = (t_s - t0_s) / dt_s;
        if (!(at >= 0.0) || samples.empty() || at > static_cast<double>(samples.size() - 1)) return std::nullopt;
        const auto below = std::min(static_cast<std::size_t>(at), samples.size() - 1);
        const std::size_t above = std::min(below + 1, samples.size() - 1);
        const double share = at - static_cast<double>(below);
        const double x = samples[below] + share * (samples[above] - samples[below]);
        return std::isfinite(x) ? std::optional(x) : std::nullopt;
    };
}

CrossingPlaces placeByPosition(std::span<const DefectEvent> events, const PositionAt& positionAt)
{
    return Placer(events).placeByPosition(positionAt);
}

SiteGrouping scanSites(std::span<const DefectEvent> events, const PositionAt& positionAt)
{
    return groupSites(events, placeByPosition(events, positionAt));
}

std::string siteText(const DefectSite& site)
{
    const std::size_t n = site.crossings.size();
    const std::string crossings = std::to_string(n) + (n == 1 ? " crossing" : " crossings");
    const auto mm = [](double m) { return std::abs(m) < 0.5e-3 ? 0.0 : m * 1e3; };  // never "-0 mm"
    switch (site.kind) {
    case SiteKind::Site: {
        if (site.position_u_m >= 0.05e-3)
            return text::valueWithUncertainty(mm(*site.position_m), site.position_u_m * 1e3, "mm") + " (" + crossings +
                   ")";
        char exact[96];  // crossings that agree exactly: synthetic ones
        std::snprintf(exact, sizeof exact, "%.1f mm (%s, no scatter)", mm(*site.position_m), crossings.c_str());
        return exact;
    }
    case SiteKind::Span: {
        char span[128];
        std::snprintf(span, sizeof span,
                      "span %.0f to %.0f mm: each crossing covers about %.0f mm, two dents or a "
                      "long one (%s)",
                      mm(site.from_m), mm(site.to_m), (site.to_m - site.from_m) * 1e3, crossings.c_str());
        return span;
    }
    case SiteKind::Unplaced:
        break;
    }
    return site.unplacedWhy.empty() ? "position unknown (" + crossings + ")"
                                    : "position unknown: " + site.unplacedWhy + " (" + crossings + ")";
}

}  // namespace tactiscope::core::detector
