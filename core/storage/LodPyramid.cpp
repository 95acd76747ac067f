// LodPyramid: bucket encoding and the builder's cascade from samples up.
#include "core/storage/LodPyramid.h"

#include "core/storage/ChunkCodec.h"
#include "core/storage/Database.h"

#include <algorithm>
#include <string>

namespace tactiscope::core::storage::lod {

std::vector<std::uint8_t> encodeBuckets(std::span<const MinMax> buckets)
{
    std::vector<std::uint8_t> bytes(buckets.size() * 8);
    std::uint8_t* out = bytes.data();
    for (const MinMax& bucket : buckets) {
        putBinary32(bucket.min, out);
        putBinary32(bucket.max, out + 4);
        out += 8;
    }
    return bytes;
}

std::vector<MinMax> decodeBuckets(std::span<const std::uint8_t> bytes, std::size_t count)
{
    if (bytes.size() != count * 8)
        throw StoreInputError("a min/max row has " + std::to_string(bytes.size()) + " bytes, not the " +
                              std::to_string(count * 8) + " its header promises; the store is damaged");
    std::vector<MinMax> buckets(count);
    const std::uint8_t* in = bytes.data();
    for (MinMax& bucket : buckets) {
        bucket.min = getBinary32(in);
        bucket.max = getBinary32(in + 4);
        in += 8;
    }
    return buckets;
}

void LodBuilder::add(std::span<const float> samples)
{
    constexpr std::uint64_t size = kBaseBucket;
    LodLevelState& base = m_levels[0];
    while (!samples.empty()) {
        const auto take = static_cast<std::size_t>(std::min<std::uint64_t>(samples.size(), size - base.partialSamples));
        for (const float value : samples.first(take)) base.partial.add(value);
        base.partialSamples += take;
        samples = samples.subspan(take);
        if (base.partialSamples == size) {
            completeBucket(0, base.partial);
            base.partial = {};
            base.partialSamples = 0;
        }
    }
}

void LodBuilder::addMissing(std::uint64_t count)
{
    constexpr std::uint64_t size = kBaseBucket;
    LodLevelState& base = m_levels[0];
    while (count > 0) {
        const std::uint64_t take = std::min(count, size - base.partialSamples);
        base.partialSamples += take;
        count -= take;
        if (base.partialSamples == size) {
            completeBucket(0, base.partial);
            base.partial = {};
            base.partialSamples = 0;
        }
    }
}

void LodBuilder::completeBucket(int level, MinMax bucket)
{
    LodLevelState& state = m_levels[static_cast<std::size_t>(level)];
    state.row.push_back(bucket);
    m_rowChanged[static_cast<std::size_t>(level)] = true;
    if (state.row.size() == kBucketsPerRow) {
        m_completedRows.push_back({level, state.rowFirstBucket, std::move(state.row)});
        state.rowFirstBucket += kBucketsPerRow;
        state.row.clear();
        m_rowChanged[static_cast<std::size_t>(level)] = false;
    }
    if (level + 1 == kLevels) return;
    LodLevelState& up = m_levels[static_cast<std::size_t>(level + 1)];
    up.partial.add(bucket);
    up.partialSamples += bucketSize(level);
    if (up.partialSamples == bucketSize(level + 1)) {
        const MinMax complete = up.partial;
        up.partial = {};
        up.partialSamples = 0;
        completeBucket(level + 1, complete);
    }
}

std::vector<LodRow> LodBuilder::takeChangedRows()
{
    std::vector<LodRow> rows = std::move(m_completedRows);
    m_completedRows.clear();
    for (int level = 0; level < kLevels; ++level) {
        const auto l = static_cast<std::size_t>(level);
        if (m_rowChanged[l]) rows.push_back({level, m_levels[l].rowFirstBucket, m_levels[l].row});
        m_rowChanged[l] = false;
    }
    return rows;
}

}  // namespace tactiscope::core::storage::lod
