// A session that gains a channel while it is recorded (a board printing
// lines that begins to print another value), in a real store: the new
// channel is a hole before its first value, in the samples, the pyramid
// and every read; a block from before the gain is stored with the new
// channel as holes; the old channels are untouched; a recorder counts
// every one of those holes.
#include "core/storage/Recorder.h"
#include "core/storage/SessionStore.h"

#include "core/SampleBlock.h"

#include "support/TempDirectory.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace tactiscope::core;
using namespace tactiscope::core::storage;

namespace {

using SessionGrowthTest = tactiscope::testing::TempDirectoryTest;

// Channel c of sample s holds 100·c + s.
SampleBlock blockOf(std::size_t channels, std::uint64_t first, std::uint64_t count)
{
    SampleBlock block(channels, count, static_cast<double>(first) / 100.0, 0.01, first);
    for (std::size_t c = 0; c < channels; ++c)
        for (std::uint64_t s = 0; s < count; ++s)
            block.channel(c)[s] = 100.0 * static_cast<double>(c) + static_cast<double>(first + s);
    return block;
}

}  // namespace

TEST_F(SessionGrowthTest, ANewChannelIsAHoleBeforeItsFirstValueAndTheOthersAreUntouched)
{
    SessionStore store(file("grow.tactiscope"));
    const std::vector<ChannelDescriptor> board{{"a", "", ChannelKind::Other}, {"b", "", ChannelKind::Other}};
    const auto id = store.beginSession({}, board, 100.0);
    store.appendBlocks(id, std::vector{blockOf(2, 0, 30), blockOf(2, 30, 20)});
    store.addChannels(id, std::vector<ChannelDescriptor>{{"c", "N", ChannelKind::Force}});
    // One more block of the two channels (it was queued before the gain),
    // a lost sample, then blocks of three.
    store.appendBlocks(id, std::vector{blockOf(2, 50, 10), blockOf(3, 61, 39)});

    const auto channels = store.channels(id);
    ASSERT_EQ(channels.size(), 3u);
    EXPECT_EQ(channels[2].descriptor, (ChannelDescriptor{"c", "N", ChannelKind::Force}));
    EXPECT_EQ(channels[2].sampleRate_hz, 100.0);
    EXPECT_EQ(store.sampleCount(id), 100u);
    ASSERT_EQ(store.gaps(id).size(), 1u);
    for (std::size_t c = 0; c < 3; ++c) {
        const auto values = store.readChannel(id, c, 0, 100);
        ASSERT_EQ(values.size(), 100u);
        for (std::uint64_t s = 0; s < 100; ++s) {
            SCOPED_TRACE("channel " + std::to_string(c) + ", sample " + std::to_string(s));
            const bool hole = s == 60 || (c == 2 && s < 61);
            if (hole)
                EXPECT_TRUE(std::isnan(values[s]));
            else
                EXPECT_EQ(values[s], 100.0 * static_cast<double>(c) + static_cast<double>(s));
        }
    }
    // The pyramid, read over the whole session: c's values are those after its first.
    const auto overview = store.overview(id, 2, 0, 100, 1);
    ASSERT_EQ(overview.size(), 1u);
    EXPECT_EQ(overview[0].min, 261.0);
    EXPECT_EQ(overview[0].max, 299.0);
    const auto before = store.overview(id, 2, 0, 50, 1);
    ASSERT_EQ(before.size(), 1u);
    EXPECT_TRUE(std::isnan(before[0].min) || before[0].count == 0) << before[0].min;
    // A block of more channels than the session has is refused.
    EXPECT_THROW(store.appendBlocks(id, std::vector{blockOf(4, 100, 5)}), StorageError);
}

// Before, the recorder counted only the holes of blocks that held the new
// channel: the samples before it came were not in its note.
TEST_F(SessionGrowthTest, ARecorderCountsTheSamplesBeforeAChannelCameAsItsHoles)
{
    const std::vector<ChannelDescriptor> board{{"a", "", ChannelKind::Other}, {"b", "", ChannelKind::Other}};
    Recorder recorder(file("grow.tactiscope"), {}, board, 100.0, 100'000);
    recorder.consume(blockOf(2, 0, 40));
    recorder.consume(blockOf(2, 40, 20));
    recorder.addChannels({board[0], board[1], {"c", "", ChannelKind::Other}});
    recorder.consume(blockOf(2, 60, 5));  // from before the gain
    auto grown = blockOf(3, 65, 35);
    grown.channel(0)[3] = std::nan("");
    recorder.consume(grown);
    const auto stats = recorder.finish(SessionStatus::Complete);
    ASSERT_TRUE(stats.error.empty()) << stats.error;
    EXPECT_EQ(stats.samplesWritten, 100u);
    EXPECT_EQ(stats.holes, (std::vector<std::uint64_t>{1, 0, 65}));
}
