// Defect sites from events computed by hand from a harmonic stroke: where
// each crossing is, how crossings group, and what cannot be placed.
#include "core/detector/DefectSites.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

using tactiscope::core::detector::DefectEvent;
using tactiscope::core::detector::groupSites;
using tactiscope::core::detector::scanSites;
using tactiscope::core::detector::strokePositions;

namespace {

// x(t) = X·sin(ωt) with X = 0.1 m, ω = π rad/s (a 200 mm stroke at 0.5 Hz):
// every crossing of each dent in [0, seconds), as the detector reports it
// (the event's middle at the crossing, the speed there, the direction of
// motion).
std::vector<DefectEvent> crossings(std::initializer_list<double> dents_m, double seconds)
{
    constexpr double X = 0.1, omega = std::numbers::pi;
    std::vector<DefectEvent> events;
    for (int stroke = 0; stroke < static_cast<int>(seconds); ++stroke) {
        for (const double dent : dents_m) {
            const double phase = std::asin(dent / X);
            // Rising through the dent at phase, falling at π − phase, each cycle.
            for (const double angle : {phase, std::numbers::pi - phase}) {
                const double t = (angle + 2.0 * std::numbers::pi * stroke) / omega;
                if (t <= 0.0 || t >= seconds) continue;
                const double velocity = X * omega * std::cos(angle);
                events.push_back({t - 0.01, t + 0.01, velocity > 0 ? 1 : -1, 0.95, 0.05, std::abs(velocity)});
            }
        }
    }
    std::ranges::sort(events, {}, &DefectEvent::start_s);
    return events;
}

}  // namespace

TEST(DefectSites, EachCrossingOfAHarmonicStrokeIsPlacedWhereItsDentIs)
{
    const auto events = crossings({-0.040, 0.050}, 10.0);
    ASSERT_EQ(events.size(), 20u);
    const auto positions = strokePositions(events);
    for (std::size_t i = 0; i < events.size(); ++i) {
        ASSERT_TRUE(positions[i]) << i;
        const double t = 0.5 * (events[i].start_s + events[i].end_s);
        EXPECT_NEAR(*positions[i], 0.1 * std::sin(std::numbers::pi * t), 1e-9) << "crossing at " << t << " s";
    }
}

TEST(DefectSites, CrossingsOfOneDentAreOneSiteWithTheirCountsDirectionsAndTimes)
{
    const auto events = crossings({-0.040, 0.050}, 10.0);
    const auto grouping = scanSites(events);
    EXPECT_EQ(grouping.method, "scan speed");
    ASSERT_EQ(grouping.sites.size(), 2u);
    const auto& low = grouping.sites[0];
    const auto& high = grouping.sites[1];
    EXPECT_NEAR(*low.position_m, -0.040, 1e-9);
    EXPECT_NEAR(*high.position_m, 0.050, 1e-9);
    EXPECT_EQ(low.crossings.size(), 10u);
    EXPECT_EQ(low.forward, 5u);
    EXPECT_EQ(low.backward, 5u);
    EXPECT_LT(low.spread_m, 1e-9);
    // The low dent is first crossed falling, at (π + asin 0.4)/π s.
    EXPECT_NEAR(low.first_s + 0.01, (std::numbers::pi + std::asin(0.4)) / std::numbers::pi, 1e-12);
    EXPECT_NEAR(high.first_s + 0.01, std::asin(0.5) / std::numbers::pi, 1e-12);
}

TEST(DefectSites, NeighboursWithinTheToleranceMergeAndFartherOnesDoNot)
{
    std::vector<DefectEvent> events(4);
    for (std::size_t i = 0; i < events.size(); ++i) events[i].start_s = events[i].end_s = static_cast<double>(i);
    const std::vector<std::optional<double>> places{0.000, 0.015, 0.030, 0.060};
    // 0 → 15 → 30 mm: each within 20 mm of the next, a chain; 60 mm is apart.
    const auto merged = groupSites(events, places, 0.020);
    ASSERT_EQ(merged.sites.size(), 2u);
    EXPECT_EQ(merged.sites[0].crossings.size(), 3u);
    EXPECT_NEAR(*merged.sites[0].position_m, 0.015, 1e-12);
    EXPECT_NEAR(merged.sites[0].spread_m, 0.015, 1e-12);
    EXPECT_EQ(groupSites(events, places, 0.010).sites.size(), 4u);
}

TEST(DefectSites, EventsWithoutSpeedOrWithoutAWholeStrokeAreSitesOfTheirOwn)
{
    auto events = crossings({0.030}, 10.0);
    for (auto& event : events) event.speed_m_per_s.reset();  // no spacing known
    auto grouping = scanSites(events);
    EXPECT_EQ(grouping.method, "not placed");
    EXPECT_EQ(grouping.sites.size(), events.size());
    EXPECT_FALSE(grouping.sites.front().position_m);

    // Two crossings, one reversal: no stroke's length to place them by.
    const auto two = crossings({0.030}, 1.0);
    ASSERT_EQ(two.size(), 2u);
    EXPECT_EQ(scanSites(two).sites.size(), 2u);
    EXPECT_THROW(groupSites(two, std::vector<std::optional<double>>(1)), std::invalid_argument);
}
