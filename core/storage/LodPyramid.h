// The min/max level-of-detail pyramid of a channel, without SQL: the bucket
// sizes, the min/max of a bucket, its byte encoding and the builder that
// extends a pyramid as samples arrive.
//
// Level L summarises buckets of 64·8^L samples (64, 512, 4096, 32768,
// 262144): bucket b of level L holds the min and max of samples
// [b·size, (b+1)·size). Lost samples (gaps) count as samples without a
// value, so bucket boundaries stay on the sample grid; a bucket with no
// value at all has NaN min and max. Buckets are stored in rows of 64
// consecutive buckets of one level, so an hour at 2 kHz is a few hundred
// rows per level 1 instead of a row per bucket.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace tactiscope::core::storage::lod {

inline constexpr int kLevels = 5;
inline constexpr std::uint64_t kBaseBucket = 64;
inline constexpr std::uint64_t kLevelFactor = 8;
inline constexpr std::uint64_t kBucketsPerRow = 64;

constexpr std::uint64_t bucketSize(int level)
{
    std::uint64_t size = kBaseBucket;
    for (int l = 0; l < level; ++l) size *= kLevelFactor;
    return size;
}

// Min and max of some samples, in binary32 like the stored samples, so the
// pyramid matches what is read back exactly. NaN (a lost sample) is skipped.
struct MinMax {
    float min = std::numeric_limits<float>::quiet_NaN();
    float max = std::numeric_limits<float>::quiet_NaN();

    bool empty() const { return min != min; }  // no value seen
    void add(float value)
    {
        if (value != value) return;
        if (empty()) {
            min = max = value;
            return;
        }
        min = value < min ? value : min;
        max = value > max ? value : max;
    }
    void add(MinMax other)
    {
        if (other.empty()) return;
        add(other.min);
        add(other.max);
    }
};

// Rows as stored: per bucket min then max, binary32 little-endian.
std::vector<std::uint8_t> encodeBuckets(std::span<const MinMax> buckets);
// Throws StorageError when the size does not match `count`.
std::vector<MinMax> decodeBuckets(std::span<const std::uint8_t> bytes, std::size_t count);

// A row of buckets of one level, as written: buckets
// [firstBucket, firstBucket + buckets.size()).
struct LodRow {
    int level = 0;
    std::uint64_t firstBucket = 0;
    std::vector<MinMax> buckets;
};

// Where a pyramid stands at one level: the row being filled and the bucket
// being gathered from the level below (for level 0, from samples).
struct LodLevelState {
    std::uint64_t rowFirstBucket = 0;
    std::vector<MinMax> row;  // completed buckets of the row, fewer than kBucketsPerRow
    MinMax partial;
    std::uint64_t partialSamples = 0;  // samples summarised by `partial`, incl. lost ones
};

// Extends one channel's pyramid. Every completed bucket lands in its row;
// takeChangedRows() returns each row that gained a bucket since the last
// call, to be written over the stored one.
class LodBuilder {
public:
    LodBuilder() = default;
    explicit LodBuilder(std::array<LodLevelState, kLevels> state)
        : m_levels(std::move(state))
    {
    }

    void add(std::span<const float> samples);
    void addMissing(std::uint64_t count);  // lost samples
    std::vector<LodRow> takeChangedRows();

private:
    void completeBucket(int level, MinMax bucket);

    std::array<LodLevelState, kLevels> m_levels{};
    std::vector<LodRow> m_completedRows;
    std::array<bool, kLevels> m_rowChanged{};
};

}  // namespace tactiscope::core::storage::lod
