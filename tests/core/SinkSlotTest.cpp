// SinkSlot: blocks reach the current occupant only, and a swap while blocks
// flow hands over at one block boundary.
#include "core/SinkSlot.h"

#include "core/SampleBlock.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <thread>
#include <vector>

using tactiscope::core::BlockSink;
using tactiscope::core::SampleBlock;
using tactiscope::core::SinkSlot;

namespace {

// Remembers the first sample index of every block it gets.
class IndexLog final : public BlockSink {
public:
    void consume(const SampleBlock& block) override { indices.push_back(block.firstSampleIndex()); }
    std::vector<std::uint64_t> indices;
};

SampleBlock blockAt(std::uint64_t index)
{
    return SampleBlock(1, 1, static_cast<double>(index) * 0.002, 0.002, index);
}

}  // namespace

TEST(SinkSlot, AnEmptySlotTakesBlocksAndDropsThem)
{
    SinkSlot slot;
    EXPECT_NO_THROW(slot.consume(blockAt(0)));
}

TEST(SinkSlot, BlocksGoToTheCurrentOccupantOnly)
{
    SinkSlot slot;
    auto first = std::make_shared<IndexLog>();
    auto second = std::make_shared<IndexLog>();
    slot.set(first);
    slot.consume(blockAt(0));
    slot.consume(blockAt(1));
    slot.set(second);
    slot.consume(blockAt(2));
    slot.set(nullptr);
    slot.consume(blockAt(3));
    EXPECT_EQ(first->indices, (std::vector<std::uint64_t>{0, 1}));
    EXPECT_EQ(second->indices, (std::vector<std::uint64_t>{2}));
}

TEST(SinkSlot, ASwapWhileBlocksFlowHandsOverAtOneBlockBoundary)
{
    SinkSlot slot;
    auto before = std::make_shared<IndexLog>();
    auto after = std::make_shared<IndexLog>();
    slot.set(before);
    // The device streams until the new occupant has had its share, however
    // the two threads are scheduled.
    std::atomic<std::uint64_t> sent = 0;
    std::atomic<bool> stop = false;
    std::thread acquisition([&] {
        for (std::uint64_t i = 0; !stop; ++i) {
            slot.consume(blockAt(i));
            sent = i + 1;
        }
    });
    while (sent < 1000) std::this_thread::yield();
    slot.set(after);
    const std::uint64_t handedOver = sent;
    while (sent < handedOver + 1000) std::this_thread::yield();
    stop = true;
    acquisition.join();
    // Every block exactly once: 0…n−1 to the old occupant, n… to the new one.
    ASSERT_GE(before->indices.size(), 1000u);
    ASSERT_GE(after->indices.size(), 999u);
    EXPECT_EQ(before->indices.size() + after->indices.size(), sent.load());
    for (std::size_t i = 0; i < before->indices.size(); ++i) ASSERT_EQ(before->indices[i], i);
    for (std::size_t i = 0; i < after->indices.size(); ++i) ASSERT_EQ(after->indices[i], before->indices.size() + i);
}
