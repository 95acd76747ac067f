// The position trail as the live detector and `detect --position` read it:
// the rig's channel found by role before kind, values between samples on
// the straight line through them, nothing across a gap, beside a NaN or
// beyond what it keeps, and each event stamped at its crossing.
#include "core/detector/PositionTrail.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace tactiscope::core;
using tactiscope::core::detector::PositionTrail;

TEST(PositionTrail, TheChannelIsTheOneWithTheRoleElseTheFirstOfTheKindWithoutOne)
{
    const ChannelDescriptor a{"a", "strain", ChannelKind::Strain};
    const ChannelDescriptor x{"x", "m", ChannelKind::Position};
    const ChannelDescriptor encoder{"enc", "m", ChannelKind::Other, ChannelRole::Position};
    const ChannelDescriptor depth{"d", "m", ChannelKind::Position, ChannelRole::Displacement};
    EXPECT_EQ(detector::positionChannel(std::vector{a, x, encoder}), 2u);
    EXPECT_EQ(detector::positionChannel(std::vector{a, depth, x}), 2u);  // a displacement is not the stroke
    EXPECT_EQ(detector::positionChannel(std::vector{a, depth}), std::nullopt);
}

TEST(PositionTrail, ReadsBetweenSamplesAndNothingWhereItCannotKnow)
{
    PositionTrail trail(4, 0.01);
    for (int i = 0; i < 6; ++i) trail.push(0.01 * i, i == 4 ? std::nan("") : 0.002 * i);
    // Kept: the samples at 20, 30, 40 (NaN) and 50 ms.
    EXPECT_EQ(trail.at(0.015), std::nullopt);  // dropped
    EXPECT_NEAR(*trail.at(0.025), 0.005, 1e-15);
    EXPECT_NEAR(*trail.at(0.020), 0.004, 1e-15);
    EXPECT_EQ(trail.at(0.035), std::nullopt);  // beside the NaN
    EXPECT_NEAR(*trail.at(0.050), 0.010, 1e-15);
    EXPECT_EQ(trail.at(0.051), std::nullopt);  // not yet
    trail.push(0.080, 0.016);                  // two samples lost
    EXPECT_EQ(trail.at(0.070), std::nullopt);
}

TEST(PositionTrail, StampsEachEventWhereItsCentrePassedTheDent)
{
    PositionTrail trail(1000, 0.002);
    for (int i = 0; i < 500; ++i) trail.push(0.002 * i, 0.1 * 0.002 * i);  // 100 mm/s
    // The crossing is the event's middle less 0.85 of its lag
    // (core/detector/SiteArithmetic.cpp): 0.505 − 0.85·0.04 = 0.471 s.
    std::vector<detector::DefectEvent> events{{0.500, 0.510, 1, 0.9, 0.040, 0.375, std::nullopt},
                                              {5.0, 5.01, -1, 0.9, 0.040, 0.375, std::nullopt}};
    trail.stamp(events);
    ASSERT_TRUE(events[0].position_m);
    EXPECT_NEAR(*events[0].position_m, 0.0471, 1e-12);
    EXPECT_EQ(events[1].position_m, std::nullopt);  // beyond the trail
}
