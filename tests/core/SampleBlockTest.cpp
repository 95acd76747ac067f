// SampleBlock: shape, channel-major layout, timing and gap accounting.
#include "core/SampleBlock.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

using tactiscope::core::SampleBlock;

TEST(SampleBlock, IsZeroFilledWithTheRequestedShape)
{
    const SampleBlock block(3, 4, 1.5, 0.002, 100, 7);
    EXPECT_EQ(block.channelCount(), 3u);
    EXPECT_EQ(block.sampleCount(), 4u);
    EXPECT_EQ(block.values().size(), 12u);
    for (double v : block.values()) EXPECT_EQ(v, 0.0);
    EXPECT_EQ(block.sequence(), 7u);
}

TEST(SampleBlock, StoresValuesChannelMajor)
{
    SampleBlock block(2, 3, 0.0, 1.0);
    block.channel(1)[0] = 5.0;
    block.channel(0)[2] = 3.0;
    // Channel 1 starts right after the 3 samples of channel 0.
    EXPECT_EQ(block.values()[3], 5.0);
    EXPECT_EQ(block.values()[2], 3.0);
    EXPECT_EQ(block.value(1, 0), 5.0);
    EXPECT_EQ(block.channel(1).size(), 3u);
}

TEST(SampleBlock, TimesFollowTheSampleInterval)
{
    const SampleBlock block(1, 10, 2.0, 0.002, 1000);
    EXPECT_DOUBLE_EQ(block.timeAt_s(0), 2.0);
    EXPECT_DOUBLE_EQ(block.timeAt_s(5), 2.010);
    EXPECT_DOUBLE_EQ(block.endTime_s(), 2.020);
    EXPECT_EQ(block.firstSampleIndex(), 1000u);
    EXPECT_EQ(block.endSampleIndex(), 1010u);
}

TEST(SampleBlock, RejectsImpossibleShapesAndTimes)
{
    EXPECT_THROW(SampleBlock(0, 10, 0.0, 0.002), std::invalid_argument);
    EXPECT_THROW(SampleBlock(1, 10, 0.0, 0.0), std::invalid_argument);
    EXPECT_THROW(SampleBlock(1, 10, 0.0, -0.002), std::invalid_argument);
    EXPECT_THROW(SampleBlock(1, 10, 0.0, std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
    EXPECT_THROW(SampleBlock(1, 10, std::numeric_limits<double>::infinity(), 0.002), std::invalid_argument);
}

TEST(SampleBlock, RejectsAChannelIndexOutOfRange)
{
    SampleBlock block(2, 3, 0.0, 1.0);
    EXPECT_THROW(block.channel(2), std::out_of_range);
    EXPECT_THROW(std::as_const(block).channel(2), std::out_of_range);
}

TEST(SampleBlock, CountsSamplesLostBetweenBlocks)
{
    const SampleBlock first(1, 10, 0.0, 0.002, 0);
    const SampleBlock contiguous(1, 10, 0.02, 0.002, 10);
    const SampleBlock afterGap(1, 10, 0.05, 0.002, 25);
    const SampleBlock restarted(1, 10, 0.07, 0.002, 0);
    EXPECT_EQ(contiguous.samplesLostAfter(first.endSampleIndex()), 0u);
    EXPECT_EQ(afterGap.samplesLostAfter(contiguous.endSampleIndex()), 5u);
    EXPECT_EQ(restarted.samplesLostAfter(afterGap.endSampleIndex()), 0u);
}
