// What the review plot reads for a span: the min/max overview when there
// are more than four samples per pixel, the exact samples otherwise, NaN
// where samples were lost, and the nearest point to a time. Values are the
// sample index, so every expectation is worked by hand.
#include "core/storage/TraceWindow.h"

#include "core/SampleBlock.h"
#include "core/storage/SessionStore.h"

#include "support/TempDirectory.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace tactiscope::core;
using namespace tactiscope::core::storage;

namespace {

using TraceWindowTest = tactiscope::testing::TempDirectoryTest;

SampleBlock blockAt(std::uint64_t first, std::size_t count)
{
    SampleBlock block(1, count, static_cast<double>(first) / 100.0, 0.01, first);
    for (std::size_t s = 0; s < count; ++s) block.channel(0)[s] = static_cast<double>(first + s);
    return block;
}

// 1000 samples at 100 Hz with 400…499 lost.
std::int64_t writeSession(SessionStore& store)
{
    SessionMetadata metadata;
    metadata.mode = tactiscope::core::Mode::Palpation;
    const std::vector<ChannelDescriptor> channels{{"f", "N", ChannelKind::Force}};
    const auto id = store.beginSession(metadata, channels, 100.0);
    store.appendBlocks(id, std::vector{blockAt(0, 400)});
    store.appendBlocks(id, std::vector{blockAt(500, 500)});
    store.endSession(id, tactiscope::core::SessionStatus::Complete);
    return id;
}

}  // namespace

TEST_F(TraceWindowTest, AWideSpanIsTheMinAndMaxOfEachStretch)
{
    SessionStore store(file("s.tactiscope"));
    const auto id = writeSession(store);
    const auto window = readTraceWindow(store, id, 0, 100.0, 1000, 0.0, 10.0, 100);  // 10 samples per pixel
    ASSERT_FALSE(window.exact);
    ASSERT_FALSE(window.t_s.empty());
    std::uint64_t covered = 0;
    for (std::size_t i = 0; i < window.t_s.size(); ++i) {
        // Values rise with the index: each stretch's min is its first
        // stored sample, its max its last, unless it lies wholly in the gap.
        if (std::isnan(window.low[i])) {
            EXPECT_GE(window.t_s[i], 4.0);
            EXPECT_LE(window.t_s[i], 5.0);
            continue;
        }
        EXPECT_LE(window.low[i], window.high[i]);
        EXPECT_NEAR(window.t_s[i], (window.low[i] + window.high[i] + 1.0) / 200.0, 0.5) << i;
        covered += 1;
    }
    EXPECT_LE(window.t_s.size(), 110u);
    EXPECT_EQ(window.low.front(), 0.0);
    EXPECT_EQ(window.high.back(), 999.0);
    EXPECT_GT(covered, 50u);
}

TEST_F(TraceWindowTest, ANarrowSpanIsTheExactSamplesWithAMarginAndNanWhereLost)
{
    SessionStore store(file("s.tactiscope"));
    const auto id = writeSession(store);
    // 3.5 s to 5.5 s: samples 350…550, plus one each side; 4 per pixel at most.
    const auto window = readTraceWindow(store, id, 0, 100.0, 1000, 3.5, 5.5, 60);
    ASSERT_TRUE(window.exact);
    EXPECT_EQ(window.firstIndex, 349u);
    ASSERT_EQ(window.t_s.size(), 203u);  // 349 … 551
    for (std::size_t i = 0; i < window.t_s.size(); ++i) {
        const std::uint64_t index = 349 + i;
        EXPECT_DOUBLE_EQ(window.t_s[i], static_cast<double>(index) / 100.0);
        if (index >= 400 && index < 500)
            EXPECT_TRUE(std::isnan(window.low[i])) << index;
        else
            EXPECT_EQ(window.low[i], static_cast<double>(index)) << index;
    }
    EXPECT_EQ(window.nearest(3.494), 0);  // 3.49 s: sample 349, the margin
    EXPECT_EQ(window.nearest(3.496), 1);  // 3.50 s
    EXPECT_EQ(window.nearest(-1.0), 0);
    EXPECT_EQ(window.nearest(99.0), 202);

    // A span past the end is clipped to the recording.
    const auto tail = readTraceWindow(store, id, 0, 100.0, 1000, 9.9, 12.0, 100);
    ASSERT_TRUE(tail.exact);
    EXPECT_EQ(tail.firstIndex, 989u);
    EXPECT_EQ(tail.low.back(), 999.0);
}
