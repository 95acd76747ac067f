// Defect sites from crossings computed independently from the probe's
// motion (a harmonic or a constant-speed stroke, bumps at known places,
// the detector's 2 ms lag steps and its short opposite runs): where each
// site is, how many there are, and what cannot be placed.
#include "core/detector/DefectSites.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

using tactiscope::core::detector::DefectEvent;
using tactiscope::core::detector::placeCrossings;
using tactiscope::core::detector::scanSites;
using tactiscope::core::detector::siteText;

namespace {

constexpr double kSpacing_m = 0.015;

struct Stroke {
    std::function<double(double)> x;  // the probe's centre, m from the stroke's centre
    double halfStroke_m;
};

Stroke harmonic(double frequency_hz, double half_m = 0.1)
{
    return {[=](double t) { return half_m * std::sin(2.0 * std::numbers::pi * frequency_hz * t); }, half_m};
}

// A machine's stroke: constant speed, turning at the ends.
Stroke constantSpeed(double frequency_hz, double half_m = 0.1)
{
    return {[=](double t) {
                const double phase = std::fmod(t * frequency_hz + 0.25, 1.0);  // starts at the centre
                return half_m * (phase < 0.5 ? 4.0 * phase - 1.0 : 3.0 - 4.0 * phase);
            },
            half_m};
}

struct Scan {
    bool quantiseLags = true;  // the detector's lags are 2 ms steps
    int onlyDirection = 0;     // a dent seen one way only: +1 or −1
};

// Every crossing of each bump by the probe's centre in [0, seconds), found
// on a 0.1 ms grid: the event's middle the detector's delay after the
// crossing, the speed there (spacing / lag), the direction of motion.
std::vector<DefectEvent> crossings(const Stroke& stroke, std::initializer_list<double> bumps_m, double seconds,
                                   Scan scan = {})
{
    constexpr double dt = 1e-4;
    std::vector<DefectEvent> events;
    for (double t = dt; t < seconds; t += dt) {
        const double x0 = stroke.x(t - dt), x1 = stroke.x(t);
        for (const double bump : bumps_m) {
            if ((x0 - bump) * (x1 - bump) > 0.0 || x0 == x1) continue;
            const double at = t - dt + dt * (bump - x0) / (x1 - x0);
            const double speed = std::abs(x1 - x0) / dt;
            const int direction = x1 > x0 ? 1 : -1;
            if (scan.onlyDirection != 0 && direction != scan.onlyDirection) continue;
            double lag = kSpacing_m / speed;
            if (scan.quantiseLags) lag = std::max(0.002, std::round(lag / 0.002) * 0.002);
            // As the detector gives it: 10 ms long, its middle the
            // detector's delay after the centre was over the bump (0.80–0.89
            // of the lag measured through the detector on generated scans).
            const double middle = at + 0.85 * lag;
            events.push_back({middle - 0.005, middle + 0.005, direction, 0.95, lag, kSpacing_m / lag, std::nullopt});
        }
    }
    std::ranges::sort(events, {}, &DefectEvent::start_s);
    return events;
}

// The detector's short opposite runs (1–3 ms beside its 10 ms crossings): after every third event and
// just before each reversal.
std::vector<DefectEvent> withShortRuns(std::vector<DefectEvent> events)
{
    const auto original = events;
    for (std::size_t i = 0; i < original.size(); ++i) {
        const auto& e = original[i];
        if (i % 3 == 0)
            events.push_back({e.end_s + 0.01, e.end_s + 0.01 + 0.001 * static_cast<double>(1 + i % 3), -e.direction,
                              0.9, 0.05, 0.3, std::nullopt});
        if (i + 1 < original.size() && original[i + 1].direction != e.direction)
            events.push_back({e.end_s + 0.05, e.end_s + 0.053, -e.direction, 0.88, 0.01, 1.5, std::nullopt});
    }
    std::ranges::sort(events, {}, &DefectEvent::start_s);
    return events;
}

void expectSitesAt(const std::vector<DefectEvent>& events, std::vector<double> truth_m, double tolerance_m,
                   double halfStroke_m)
{
    const auto grouping = scanSites(events);
    ASSERT_EQ(grouping.sites.size(), truth_m.size()) << grouping.method;
    std::ranges::sort(truth_m);
    for (std::size_t k = 0; k < truth_m.size(); ++k) {
        ASSERT_TRUE(grouping.sites[k].position_m) << k;
        EXPECT_NEAR(*grouping.sites[k].position_m, truth_m[k], tolerance_m) << "site " << k << ", " << grouping.method;
    }
    const auto places = placeCrossings(events);
    for (const auto& x : places.position_m)
        if (x) {
            EXPECT_LE(std::abs(*x), halfStroke_m * 1.02) << "placed outside the stroke";
        }
}

}  // namespace

TEST(DefectSites, EachCrossingOfAHarmonicStrokeIsPlacedWhereItsDentIs)
{
    const Stroke stroke = harmonic(0.5);
    const auto events = crossings(stroke, {-0.040, 0.050}, 10.0, {.quantiseLags = false});
    ASSERT_EQ(events.size(), 20u);
    const auto places = placeCrossings(events);
    EXPECT_EQ(places.model, "scan speed, harmonic strokes, from the stroke's centre");
    ASSERT_TRUE(places.halfStroke_m);
    EXPECT_NEAR(*places.halfStroke_m, 0.1, 1e-4);
    for (std::size_t i = 0; i < events.size(); ++i) {
        const double t = 0.5 * (events[i].start_s + events[i].end_s) - 0.85 * events[i].peakLag_s;
        if (places.position_m[i]) {
            EXPECT_NEAR(*places.position_m[i], stroke.x(t), 1e-4) << "crossing at " << t;
        }
    }
}

TEST(DefectSites, CrossingsOfOneDentAreOneSiteWithTheirCountsDirectionsAndTimes)
{
    const auto events = crossings(harmonic(0.5), {-0.040, 0.050}, 10.0, {.quantiseLags = false});
    const auto grouping = scanSites(events);
    ASSERT_EQ(grouping.sites.size(), 2u);
    const auto& low = grouping.sites[0];
    EXPECT_NEAR(*low.position_m, -0.040, 1e-4);
    EXPECT_EQ(low.crossings.size() + grouping.sites[1].crossings.size(), 20u);
    EXPECT_EQ(low.forward + low.backward, low.crossings.size());
    EXPECT_GE(low.forward, 4u);
    EXPECT_GE(low.backward, 4u);
    // The low dent is first crossed falling, at (π + asin 0.4)/π s, and
    // seen the detector's delay later.
    const auto& first = events[low.crossings.front()];
    EXPECT_NEAR(low.first_s + 0.005 - 0.85 * first.peakLag_s, (std::numbers::pi + std::asin(0.4)) / std::numbers::pi,
                1e-3);
}

// Bumps 30 mm apart or more stay apart on harmonic strokes at 0.5–1 Hz,
// with the detector's lag steps.
TEST(DefectSites, BumpsThirtyMillimetresApartAreTwoSites)
{
    for (const double hz : {0.5, 0.75, 1.0})
        for (const auto& [first, second] :
             {std::pair(0.010, 0.040), std::pair(-0.060, -0.030), std::pair(0.0, 0.080)}) {
            SCOPED_TRACE(std::to_string(hz) + " Hz, bumps at " + std::to_string(first) + ", " + std::to_string(second));
            expectSitesAt(crossings(harmonic(hz), {first, second}, 20.0), {first, second}, 0.006, 0.1);
        }
    expectSitesAt(crossings(harmonic(0.5), {-0.050, 0.0, 0.050}, 20.0), {-0.050, 0.0, 0.050}, 0.006, 0.1);
}

// The detector's short opposite runs make no reversal and no site: the
// scan keeps its true strokes and no crossing is placed outside them.
TEST(DefectSites, ShortOppositeRunsArePartsOfTheirCrossings)
{
    const auto clean = crossings(harmonic(0.5), {0.010, 0.040}, 20.0);
    const auto events = withShortRuns(clean);
    ASSERT_GT(events.size(), clean.size() + 5);
    expectSitesAt(events, {0.010, 0.040}, 0.006, 0.1);
    const auto grouping = scanSites(events);
    std::size_t crossingsCounted = 0, parts = 0;
    for (const auto& site : grouping.sites) {
        crossingsCounted += site.crossings.size();
        parts += site.parts.size();
    }
    EXPECT_EQ(crossingsCounted, clean.size());
    EXPECT_EQ(parts, events.size() - clean.size());
}

// A machine's constant-speed strokes, told from the crossings' speeds.
TEST(DefectSites, ConstantSpeedStrokesArePlacedByTheirOwnShape)
{
    const auto events = crossings(constantSpeed(0.5), {-0.050, 0.030, 0.080}, 20.0);
    EXPECT_EQ(placeCrossings(events).model, "scan speed, constant-speed strokes, from the stroke's centre");
    expectSitesAt(events, {-0.050, 0.030, 0.080}, 0.006, 0.1);
}

TEST(DefectSites, OneDentAtOnePhaseSaysItsStrokeShapeIsAssumed)
{
    const auto events = crossings(harmonic(0.5), {0.0}, 10.0);
    EXPECT_NE(placeCrossings(events).model.find("assumed"), std::string::npos);
    expectSitesAt(events, {0.0}, 0.003, 0.1);
    const auto site = scanSites(events).sites.front();
    EXPECT_EQ(siteText(site), "0.0 mm (" + std::to_string(site.crossings.size()) + " crossings, no scatter)");
}

// A dent seen in one direction only has no reversal to place it by: one
// site, "position unknown", not one per crossing; two such dents, two.
TEST(DefectSites, ADentSeenOneWayIsOneUnplacedSite)
{
    const auto one = crossings(harmonic(0.5), {0.030}, 20.0, {.onlyDirection = 1});
    ASSERT_EQ(one.size(), 10u);
    const auto grouping = scanSites(one);
    EXPECT_EQ(grouping.method, "not placed: no whole stroke between two reversals");
    ASSERT_EQ(grouping.sites.size(), 1u);
    EXPECT_FALSE(grouping.sites.front().position_m);
    EXPECT_EQ(grouping.sites.front().crossings.size(), 10u);
    EXPECT_EQ(siteText(grouping.sites.front()), "position unknown (10 crossings)");

    EXPECT_EQ(scanSites(crossings(harmonic(0.5), {-0.040, 0.030}, 20.0, {.onlyDirection = -1})).sites.size(), 2u);
}

// One stroke out and back (x = 0.1·sin πt over 1 s: out to the end at
// 0.5 s, back by 1 s), as a panel line strokes each panel: no whole stroke
// lies between two reversals, so nothing is placed, but every dent passed
// on the way out is passed on the way back: one site per dent, its two
// crossings mirrored about the reversal.
TEST(DefectSites, ASingleStrokeOutAndBackPairsItsCrossingsIntoOneSitePerDent)
{
    const auto one = crossings(harmonic(0.5), {0.030}, 1.0);
    ASSERT_EQ(one.size(), 2u);
    const auto single = scanSites(one);
    ASSERT_EQ(single.sites.size(), 1u) << single.method;
    EXPECT_FALSE(single.sites.front().position_m);
    EXPECT_EQ(single.sites.front().forward, 1u);
    EXPECT_EQ(single.sites.front().backward, 1u);
    EXPECT_EQ(single.method, "not placed: one stroke out and back, each dent crossed once each way");

    // Two dents: out over 30 then 60 mm, back over 60 then 30 mm.
    const auto two = crossings(harmonic(0.5), {0.030, 0.060}, 1.0);
    ASSERT_EQ(two.size(), 4u);
    const auto pairs = scanSites(two);
    ASSERT_EQ(pairs.sites.size(), 2u);
    for (const auto& site : pairs.sites) {
        ASSERT_EQ(site.crossings.size(), 2u);
        // Its crossings lie symmetric about the reversal at 0.5 s: one dent.
        const auto crossed = [&](std::size_t i) { return two[i].start_s + 0.005 - 0.85 * two[i].peakLag_s; };
        EXPECT_NEAR(0.5 * (crossed(site.crossings[0]) + crossed(site.crossings[1])), 0.5, 0.001);
    }

    // Without their speeds, or minutes apart, two crossings could be two
    // dents each seen one way: not paired.
    auto noSpeed = one;
    noSpeed[1].speed_m_per_s.reset();
    EXPECT_EQ(scanSites(noSpeed).sites.size(), 2u);
    auto apart = one;
    apart[1].start_s += 180.0;
    apart[1].end_s += 180.0;
    EXPECT_EQ(scanSites(apart).sites.size(), 2u);

    // Seen one way only: two crossings the same way are two dents.
    EXPECT_EQ(scanSites(crossings(harmonic(0.5), {0.030, 0.060}, 1.0, {.onlyDirection = 1})).sites.size(), 2u);
    // A crossing missed on the way back: no mirror, so the pairing is not
    // taken (the pass rule groups them; never fewer sites than dents).
    auto missed = two;
    missed.erase(missed.begin() + 2);
    const auto unpaired = scanSites(missed);
    EXPECT_EQ(unpaired.method, "not placed: no whole stroke between two reversals");
    EXPECT_GE(unpaired.sites.size(), 2u);
}

TEST(DefectSites, EventsWithoutSpeedAreUnplacedButStillGrouped)
{
    auto events = crossings(harmonic(0.5), {0.030}, 10.0);
    for (auto& event : events) event.speed_m_per_s.reset();  // no spacing known
    const auto grouping = scanSites(events);
    EXPECT_EQ(grouping.method,
              "not placed: no crossing with a speed inside a stroke (a speed needs the cantilever spacing)");
    EXPECT_LE(grouping.sites.size(), 2u);  // at most one per direction: nothing tells them apart
    for (const auto& site : grouping.sites) EXPECT_FALSE(site.position_m);
    EXPECT_THROW(tactiscope::core::detector::groupSites(events, {}), std::invalid_argument);
}

// A dent near the stroke's end at 1 Hz, whose backward crossings the
// detector sees only as short runs (4 ms where the forward ones last
// 100 ms): they are crossings, a third of a second from the forward ones,
// far beyond any echo of them. Folding them into the forward crossings
// merged strokes and placed that dent half a metre away.
TEST(DefectSites, AWeakCrossingBeyondTheDetectorsEchoIsACrossing)
{
    auto events = crossings(harmonic(1.0), {-0.060}, 20.0);
    for (auto& event : events)
        if (event.direction < 0) {
            const double middle = 0.5 * (event.start_s + event.end_s);
            event.start_s = middle - 0.002;
            event.end_s = middle + 0.002;
        }
    expectSitesAt(events, {-0.060}, 0.006, 0.1);
    const auto site = scanSites(events).sites.front();
    EXPECT_EQ(site.crossings.size(), events.size());
    EXPECT_TRUE(site.parts.empty());
}

// The detector misses a dent in a stroke now and then: with nothing seen
// in a backward stroke, two forward crossings lie in one "stroke" three
// strokes long. It is split into three, each crossing placed in its own,
// so the site keeps its place and every crossing.
TEST(DefectSites, AStrokeWithNothingSeenHidesItsReversals)
{
    auto events = crossings(harmonic(0.5), {0.030}, 30.0);
    ASSERT_EQ(events.size(), 30u);
    for (const std::size_t missed : {21u, 13u, 5u}) {
        ASSERT_LT(events[missed].direction, 0);
        events.erase(events.begin() + static_cast<std::ptrdiff_t>(missed));
    }
    expectSitesAt(events, {0.030}, 0.006, 0.1);
    const auto places = placeCrossings(events);
    for (std::size_t i = 0; i < events.size(); ++i) EXPECT_TRUE(places.position_m[i]) << "crossing " << i;
    EXPECT_EQ(places.model.find("fewer crossings"), std::string::npos) << places.model;
}

// A dent the detector never sees backwards, beside one it sees both ways:
// the reversal at that end lies between crossings of the two dents, whose
// speeds differ every time. Those reversals are retaken midway between the
// paired ones beside them (were placed by the two dents' speeds: places
// off by up to 20 mm), and the method says so.
TEST(DefectSites, ReversalsBetweenDifferentDentsAreRetakenFromThoseBeside)
{
    auto events = crossings(harmonic(0.5), {-0.070, 0.0}, 20.0);
    EXPECT_EQ(placeCrossings(events).model, "scan speed, harmonic strokes, from the stroke's centre");
    std::erase_if(events, [](const DefectEvent& e) {
        const double middle = 0.5 * (e.start_s + e.end_s);
        return e.direction < 0 && std::sin(std::numbers::pi * middle) < -0.5;  // the −70 mm dent, falling
    });
    const auto grouping = scanSites(events);
    EXPECT_NE(grouping.method.find("reversals lay between crossings of different dents"), std::string::npos)
        << grouping.method;
    ASSERT_EQ(grouping.sites.size(), 2u) << grouping.method;
    EXPECT_NEAR(*grouping.sites[0].position_m, -0.070, 0.003);
    EXPECT_NEAR(*grouping.sites[1].position_m, 0.0, 0.003);
    for (const auto& x : placeCrossings(events).position_m)
        if (x) {
            EXPECT_LE(std::abs(*x), 0.1 * 1.02);
        }
}

// A triggered panel on a line with an encoder holds one stroke out and
// back: one crossing each way. The encoder reads their places, so they
// are one site, placed (not "too few crossings", two sites, as by phase),
// its ± a uniform doubt over the crossings' range and half a run: 10 ms
// at 300 mm/s, 3 mm, gives 1.5/√3 mm with the delay's (0.05 of the 15 mm
// travel in a lag, over √3).
TEST(DefectSites, AnEncoderPlacesOneCrossingEachWayAsOneSite)
{
    const double run_s = 0.010, speed = 0.3, lag_s = kSpacing_m / speed;
    const std::vector<DefectEvent> events{{1.0, 1.0 + run_s, 1, 0.9, lag_s, speed, 0.030},
                                          {2.0, 2.0 + run_s, -1, 0.9, lag_s, speed, 0.031}};
    const auto grouping = scanSites(events, true);
    EXPECT_EQ(grouping.method, "from the position channel");
    ASSERT_EQ(grouping.sites.size(), 1u);
    const auto& site = grouping.sites[0];
    ASSERT_EQ(site.kind, tactiscope::core::detector::SiteKind::Site) << siteText(site);
    EXPECT_NEAR(*site.position_m, 0.0305, 1e-12);
    const double halfRun = run_s * speed / 2.0, halfRange = 0.0005, delay = 0.05 * kSpacing_m;
    EXPECT_NEAR(site.position_u_m, std::sqrt((halfRun * halfRun + halfRange * halfRange + delay * delay) / 3.0), 1e-12);
}
