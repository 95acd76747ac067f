// CompleteSamples: a processor gets the runs of samples whose watched
// channels hold a value, each as a block at its own index and time (a gap
// to it where a hole was), and a block without holes as it came.
#include "core/CompleteSamples.h"

#include "core/SampleBlock.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

using tactiscope::core::BlockSink;
using tactiscope::core::CompleteSamples;
using tactiscope::core::SampleBlock;

namespace {

constexpr double kHole = std::numeric_limits<double>::quiet_NaN();

class Blocks final : public BlockSink {
public:
    void consume(const SampleBlock& block) override { got.push_back(block); }
    std::vector<SampleBlock> got;
};

// Three channels, ten samples from index 100 at 1 ms; sample s of channel c is 10·c + s.
SampleBlock tenSamples()
{
    SampleBlock block(3, 10, 2.0, 1e-3, 100, 7);
    for (std::size_t c = 0; c < 3; ++c)
        for (std::size_t s = 0; s < 10; ++s)
            block.channel(c)[s] = 10.0 * static_cast<double>(c) + static_cast<double>(s);
    return block;
}

}  // namespace

TEST(CompleteSamples, AHoleInAWatchedChannelIsAGapToTheProcessor)
{
    auto inner = std::make_shared<Blocks>();
    CompleteSamples complete(inner, {0, 1});
    auto block = tenSamples();
    block.channel(1)[0] = kHole;
    block.channel(0)[4] = kHole;
    block.channel(1)[5] = kHole;
    block.channel(2)[7] = kHole;  // not watched: nothing
    complete.consume(block);
    ASSERT_EQ(inner->got.size(), 2u);
    const auto& first = inner->got[0];
    EXPECT_EQ(first.firstSampleIndex(), 101u);
    EXPECT_EQ(first.sampleCount(), 3u);
    EXPECT_DOUBLE_EQ(first.t0_s(), 2.001);
    EXPECT_EQ(first.value(1, 0), 11.0);
    const auto& second = inner->got[1];
    EXPECT_EQ(second.firstSampleIndex(), 106u);
    EXPECT_EQ(second.sampleCount(), 4u);
    EXPECT_EQ(second.value(0, 0), 6.0);
    EXPECT_TRUE(std::isnan(second.value(2, 1)));  // the unwatched hole goes through
}

TEST(CompleteSamples, ABlockWithoutHolesOrAllHolesGoesAsItCameOrNotAtAll)
{
    auto inner = std::make_shared<Blocks>();
    CompleteSamples complete(inner, {2});
    complete.consume(tenSamples());
    ASSERT_EQ(inner->got.size(), 1u);
    EXPECT_EQ(inner->got[0].sampleCount(), 10u);
    EXPECT_EQ(inner->got[0].sequence(), 7u);
    auto holes = tenSamples();
    for (auto& v : holes.channel(2)) v = kHole;
    complete.consume(holes);
    EXPECT_EQ(inner->got.size(), 1u);
    CompleteSamples watchingNothing(inner, {});
    watchingNothing.consume(holes);
    EXPECT_EQ(inner->got.size(), 2u);
}
