// CrossingPlacement: short runs and ghosts folded into crossings,
// reversals from direction changes kept where they make plausible strokes
// and retaken where they lie between different dents, each crossing placed
// by its phase in its stroke (harmonic or constant-speed), or by a position
// channel (core/detector/DefectSites.h).
#include "core/detector/DefectSites.h"
#include "core/detector/SiteArithmetic.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <utility>

namespace tactiscope::core::detector {
namespace {

using sites::crossingTime;
using sites::meanDifference;
using sites::median;
using sites::placedGroups;
using sites::speedOf;

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

    CrossingPlaces placeByPosition()
    {
        m_places.fromPosition = true;
        m_places.shape = StrokeShape::Harmonic;  // no shape: nothing to doubt
        m_places.model = "from the position channel";
        if (m_events.empty()) return std::move(m_places);
        foldShortRuns();
        std::size_t stroke = 0;
        std::optional<int> lastDirection;
        double farthest = 0.0;
        double lowest = std::numeric_limits<double>::infinity();
        double highest = -lowest;
        for (const std::size_t i : m_order) {
            if (!isCrossing(i)) continue;
            if (lastDirection && m_events[i].direction != 0 && m_events[i].direction != *lastDirection) ++stroke;
            if (m_events[i].direction != 0) lastDirection = m_events[i].direction;
            const auto& x = m_events[i].position_m;
            if (!x || !std::isfinite(*x)) continue;
            m_places.position_m[i] = *x;
            m_places.stroke[i] = stroke;
            farthest = std::max(farthest, std::abs(*x));
            lowest = std::min(lowest, *x);
            highest = std::max(highest, *x);
        }
        m_places.halfStroke_m = farthest;
        // An encoder read in the wrong unit (mm taken for m) spreads the
        // crossings over more than any panel probe strokes: placed as it
        // says, with the doubt said.
        if (highest - lowest > kMaxStroke_m) {
            char text[160];
            std::snprintf(text, sizeof text,
                          " (its crossings lie %.3g m apart, more than a panel probe's stroke of %.0f m: is the "
                          "channel in m?)",
                          highest - lowest, kMaxStroke_m);
            m_places.model += text;
        }
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
            m_places.model = "not placed: no crossing with a speed inside a stroke (a speed needs the cantilever "
                             "spacing)";
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
        // Places by phase count from the stroke's centre: said, as an
        // encoder's count from its own zero.
        m_places.model = m_places.shape == StrokeShape::ConstantSpeed
                             ? "scan speed, constant-speed strokes, from the stroke's centre"
                         : m_places.shape == StrokeShape::Harmonic
                             ? "scan speed, harmonic strokes, from the stroke's centre"
                             : "scan speed, harmonic strokes assumed, from the stroke's centre (the crossings' speeds "
                               "do not tell the stroke's shape: one dent, or speeds that fit either); a machine's "
                               "constant-speed stroke would put each site nearer the centre, and its ± counts that";
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

}  // namespace

CrossingPlaces placeCrossings(std::span<const DefectEvent> events)
{
    return Placer(events).place();
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

std::vector<DefectEvent> withPositions(std::span<const DefectEvent> events, const PositionAt& positionAt)
{
    std::vector<DefectEvent> stamped(events.begin(), events.end());
    for (auto& e : stamped) e.position_m = positionAt(crossingTime(e));
    return stamped;
}

CrossingPlaces placeByPosition(std::span<const DefectEvent> events)
{
    return Placer(events).placeByPosition();
}

}  // namespace tactiscope::core::detector
