// Event segmentation: runs, hold-time bridging, direction changes, peaks, speed.
#include "core/detector/EventSegmenter.h"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace tactiscope::core::detector;

namespace {

constexpr double kDt = 0.002;

// Feeds decisions (one per sample, from t = 0) with R = 0.9 + 0.001·i and
// lag i % 7 + 1 samples, so peaks are at the last sample of each run.
std::vector<DefectEvent> segment(const std::vector<int>& decisions, double hold_s, std::optional<double> spacing_m = {})
{
    EventSegmenter segmenter(hold_s, spacing_m);
    std::vector<DefectEvent> events;
    for (std::size_t i = 0; i < decisions.size(); ++i) {
        DetectorOutput o;
        o.decision = static_cast<std::int8_t>(decisions[i]);
        o.rab = o.rba = 0.9 + 0.001 * static_cast<double>(i);
        o.lagAb = o.lagBa = static_cast<std::uint32_t>(i % 7 + 1);
        segmenter.push(static_cast<double>(i) * kDt, o, kDt, events);
    }
    segmenter.finish(events);
    return events;
}

}  // namespace

TEST(EventSegmenter, ARunOfEqualDecisionsIsOneEvent)
{
    const auto events = segment({0, 0, 1, 1, 1, 0, 0}, 0.0);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_DOUBLE_EQ(events[0].start_s, 0.004);
    EXPECT_DOUBLE_EQ(events[0].end_s, 0.008);
    EXPECT_EQ(events[0].direction, 1);
    EXPECT_DOUBLE_EQ(events[0].peakR, 0.904);        // sample 4
    EXPECT_DOUBLE_EQ(events[0].peakLag_s, 5 * kDt);  // 4 % 7 + 1 samples
    EXPECT_FALSE(events[0].speed_m_per_s.has_value());
}

TEST(EventSegmenter, GapsWithinTheHoldAreBridgedLongerOnesSplit)
{
    // Gap of 3 zero samples (6 ms) and then of 6 (12 ms), hold 10 ms.
    const std::vector<int> d{-1, -1, 0, 0, 0, -1, 0, 0, 0, 0, 0, 0, -1};
    const auto events = segment(d, 0.010);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_DOUBLE_EQ(events[0].start_s, 0.0);
    EXPECT_DOUBLE_EQ(events[0].end_s, 0.010);
    EXPECT_DOUBLE_EQ(events[1].start_s, 0.024);
    EXPECT_EQ(segment(d, 0.0).size(), 3u);  // no hold: every run stands alone
}

TEST(EventSegmenter, ADirectionChangeEndsTheEventEvenWithinTheHold)
{
    const auto events = segment({1, 1, 0, -1, -1}, 1.0);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].direction, 1);
    EXPECT_EQ(events[1].direction, -1);
    EXPECT_DOUBLE_EQ(events[1].start_s, 0.006);
}

TEST(EventSegmenter, SpeedIsSpacingOverTheLagAtThePeak)
{
    // Peak at sample 2: lag 3 samples = 6 ms; 15 mm / 6 ms = 2.5 m/s.
    const auto events = segment({1, 1, 1}, 0.0, 0.015);
    ASSERT_EQ(events.size(), 1u);
    ASSERT_TRUE(events[0].speed_m_per_s.has_value());
    EXPECT_DOUBLE_EQ(*events[0].speed_m_per_s, 2.5);
}

TEST(EventSegmenter, RejectsBadSettings)
{
    EXPECT_THROW(EventSegmenter(-0.001), std::invalid_argument);
    EXPECT_THROW(EventSegmenter(0.0, 0.0), std::invalid_argument);
}
