// LiveBuffer: reads by cursor, overrun accounting, and a real writer thread.
#include "core/LiveBuffer.h"

#include "core/SampleBlock.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <thread>

using tactiscope::core::LiveBuffer;
using tactiscope::core::LiveChunk;
using tactiscope::core::LiveCursor;
using tactiscope::core::SampleBlock;

namespace {

// A two-channel block whose channel 0 holds the sample index and channel 1
// its negative, so any misplaced sample is visible.
SampleBlock indexedBlock(std::uint64_t first, std::size_t count, double dt_s = 0.002)
{
    SampleBlock block(2, count, static_cast<double>(first) * dt_s, dt_s, first);
    for (std::size_t i = 0; i < count; ++i) {
        block.channel(0)[i] = static_cast<double>(first + i);
        block.channel(1)[i] = -static_cast<double>(first + i);
    }
    return block;
}

}  // namespace

TEST(LiveBuffer, RejectsEmptyShapes)
{
    EXPECT_THROW(LiveBuffer(0, 10), std::invalid_argument);
    EXPECT_THROW(LiveBuffer(2, 0), std::invalid_argument);
}

TEST(LiveBuffer, HandsEachSampleToAReaderOnce)
{
    LiveBuffer buffer(2, 100);
    buffer.consume(indexedBlock(0, 10));
    LiveCursor cursor;
    LiveChunk chunk;
    ASSERT_EQ(buffer.readNew(cursor, chunk), 10u);
    EXPECT_EQ(chunk.firstIndex, 0u);
    EXPECT_DOUBLE_EQ(chunk.time_s[3], 0.006);
    EXPECT_EQ(chunk.values[0][9], 9.0);
    EXPECT_EQ(chunk.values[1][9], -9.0);
    EXPECT_EQ(buffer.readNew(cursor, chunk), 0u);
    EXPECT_EQ(chunk.sampleCount(), 0u);

    buffer.consume(indexedBlock(10, 5));
    ASSERT_EQ(buffer.readNew(cursor, chunk), 5u);
    EXPECT_EQ(chunk.firstIndex, 10u);
    EXPECT_EQ(chunk.values[0][0], 10.0);
    EXPECT_EQ(cursor.overrun, 0u);
}

TEST(LiveBuffer, CountsWhatASlowReaderMissed)
{
    LiveBuffer buffer(2, 10);
    for (std::uint64_t first = 0; first < 25; first += 5) buffer.consume(indexedBlock(first, 5));
    LiveCursor cursor;
    LiveChunk chunk;
    ASSERT_EQ(buffer.readNew(cursor, chunk), 10u);
    EXPECT_EQ(cursor.overrun, 15u);
    EXPECT_EQ(chunk.values[0].front(), 15.0);
    EXPECT_EQ(chunk.values[0].back(), 24.0);
    EXPECT_EQ(buffer.samplesWritten(), 25u);
}

TEST(LiveBuffer, LimitsOneReadToMaxSamples)
{
    LiveBuffer buffer(2, 100);
    buffer.consume(indexedBlock(0, 30));
    LiveCursor cursor;
    LiveChunk chunk;
    EXPECT_EQ(buffer.readNew(cursor, chunk, 12), 12u);
    EXPECT_EQ(buffer.readNew(cursor, chunk, 100), 18u);
    EXPECT_EQ(chunk.values[0].front(), 12.0);
}

TEST(LiveBuffer, RejectsABlockWithOtherChannels)
{
    LiveBuffer buffer(3, 10);
    EXPECT_THROW(buffer.consume(indexedBlock(0, 4)), std::invalid_argument);
}

TEST(LiveBuffer, AConcurrentReaderSeesEverySampleInOrderOrCountsItAsOverrun)
{
    constexpr std::uint64_t kBlocks = 2000;
    constexpr std::size_t kBlockSize = 10;
    LiveBuffer buffer(2, 64);
    std::thread writer([&] {
        for (std::uint64_t b = 0; b < kBlocks; ++b) buffer.consume(indexedBlock(b * kBlockSize, kBlockSize));
    });

    LiveCursor cursor;
    LiveChunk chunk;
    std::uint64_t received = 0;
    double lastValue = -1.0;
    bool inOrder = true;
    while (cursor.next < kBlocks * kBlockSize) {
        buffer.readNew(cursor, chunk);
        for (std::size_t i = 0; i < chunk.sampleCount(); ++i) {
            const double expected = static_cast<double>(chunk.firstIndex + i);
            inOrder = inOrder && chunk.values[0][i] == expected && chunk.values[1][i] == -expected &&
                      chunk.values[0][i] > lastValue;
            lastValue = chunk.values[0][i];
        }
        received += chunk.sampleCount();
    }
    writer.join();
    EXPECT_TRUE(inOrder);
    EXPECT_EQ(received + cursor.overrun, kBlocks * kBlockSize);
}
