// RingBuffer against a naive model (a deque of (index, value) pairs).
#include "core/RingBuffer.h"

#include <gtest/gtest.h>

#include <deque>
#include <numeric>
#include <random>
#include <stdexcept>
#include <vector>

using tactiscope::core::RingBuffer;

TEST(RingBuffer, RejectsZeroCapacity)
{
    EXPECT_THROW(RingBuffer<int>(0), std::invalid_argument);
}

TEST(RingBuffer, HoldsEverythingBelowCapacity)
{
    RingBuffer<int> ring(5);
    EXPECT_TRUE(ring.empty());
    ring.push(10);
    ring.push(11);
    ring.push(12);
    EXPECT_EQ(ring.size(), 3u);
    EXPECT_EQ(ring.oldestIndex(), 0u);
    EXPECT_EQ(ring.endIndex(), 3u);
    EXPECT_EQ(ring.at(0), 10);
    EXPECT_EQ(ring.at(2), 12);
}

TEST(RingBuffer, WrapsAroundKeepingTheNewestValues)
{
    RingBuffer<int> ring(4);
    for (int i = 0; i < 10; ++i) ring.push(i);
    EXPECT_EQ(ring.size(), 4u);
    EXPECT_EQ(ring.oldestIndex(), 6u);
    EXPECT_EQ(ring.endIndex(), 10u);
    std::vector<int> out(4);
    ring.copy(6, out);  // physically split across the end of the storage
    EXPECT_EQ(out, (std::vector<int>{6, 7, 8, 9}));
    EXPECT_THROW(ring.at(5), std::out_of_range);
    EXPECT_THROW(ring.at(10), std::out_of_range);
}

TEST(RingBuffer, APushLargerThanCapacityKeepsItsTailAndCountsEverything)
{
    RingBuffer<int> ring(3);
    std::vector<int> values(8);
    std::iota(values.begin(), values.end(), 100);
    ring.push(std::span<const int>(values));
    EXPECT_EQ(ring.endIndex(), 8u);
    EXPECT_EQ(ring.oldestIndex(), 5u);
    EXPECT_EQ(ring.at(5), 105);
    EXPECT_EQ(ring.at(7), 107);
}

TEST(RingBuffer, RefusesToCopyARangeItDoesNotHold)
{
    RingBuffer<int> ring(4);
    for (int i = 0; i < 6; ++i) ring.push(i);
    std::vector<int> out(3);
    EXPECT_THROW(ring.copy(1, out), std::out_of_range);  // index 1 was overwritten
    EXPECT_THROW(ring.copy(4, out), std::out_of_range);  // runs past the newest
    EXPECT_NO_THROW(ring.copy(3, out));
}

TEST(RingBuffer, MatchesANaiveModelForRandomPushSizes)
{
    std::mt19937 random(42);
    std::uniform_int_distribution<int> pushSize(0, 23);
    RingBuffer<long> ring(17);
    std::deque<long> model;  // the newest values, oldest first
    long next = 0;
    for (int round = 0; round < 500; ++round) {
        std::vector<long> values(static_cast<std::size_t>(pushSize(random)));
        for (auto& v : values) v = next++;
        if (round % 2 == 0) {
            ring.push(std::span<const long>(values));
        } else {
            for (long v : values) ring.push(v);
        }
        for (long v : values) model.push_back(v);
        while (model.size() > 17) model.pop_front();

        ASSERT_EQ(ring.endIndex(), static_cast<std::uint64_t>(next));
        ASSERT_EQ(ring.size(), model.size());
        std::vector<long> held(ring.size());
        ring.copy(ring.oldestIndex(), held);
        ASSERT_TRUE(std::equal(held.begin(), held.end(), model.begin()));
    }
}
