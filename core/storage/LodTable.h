// The min/max pyramid of one channel in the store (table `lod`): where it
// stands, so recording can extend it; its rows, written over as they fill;
// and min/max over any sample range from the coarsest buckets inside the
// range, with finer ones (down to the samples) only at its edges.
#pragma once

#include "core/storage/Database.h"
#include "core/storage/LodPyramid.h"

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>

namespace tactiscope::core::storage::lod {

// Samples [first, first + count) of the channel, NaN where lost.
using SampleReader = std::function<std::vector<double>(std::uint64_t first, std::uint64_t count)>;

// One point of an overview: the min and max of samples
// [firstIndex, firstIndex + count); NaN when all of them were lost.
struct OverviewPoint {
    std::uint64_t firstIndex = 0;
    std::uint64_t count = 0;
    double min = 0.0;
    double max = 0.0;
};

// Rows of decoded buckets, by level and first bucket.
using LodRowMap = std::map<std::pair<int, std::uint64_t>, std::vector<MinMax>>;

// Where a pyramid's rows are read from: a station's store or the central one.
class LodRows {
public:
    virtual ~LodRows() = default;
    // One past the last bucket stored at `level`.
    virtual std::uint64_t storedBuckets(int level) = 0;
    // Adds to `rows` every row at `level` whose first bucket is in
    // [firstBucket, endBucket).
    virtual void read(int level, std::uint64_t firstBucket, std::uint64_t endBucket, LodRowMap& rows) = 0;
};

class LodTable {
public:
    // The pyramid in a station's store, which recording extends.
    LodTable(Database& db, std::int64_t session, std::size_t channel, SampleReader samples);
    // A pyramid read from elsewhere, for overviews only.
    LodTable(std::unique_ptr<LodRows> rows, std::int64_t session, SampleReader samples);

    // A builder that continues the pyramid after the first `sampleEnd`
    // samples. Throws StorageError when the stored pyramid does not end there.
    LodBuilder builderAt(std::uint64_t sampleEnd);
    void write(const std::vector<LodRow>& rows);  // only to a station's store

    // Exact min and max of samples [first, end).
    MinMax range(std::uint64_t first, std::uint64_t end) { return range(first, end, kLevels - 1); }

    // About `points` points covering samples [first, end) (fewer when the
    // range has fewer samples). Point boundaries fall on the bucket grid of
    // the coarsest level at most one point wide, so each point is read from
    // whole buckets and is still exact.
    std::vector<OverviewPoint> overview(std::uint64_t first, std::uint64_t end, std::size_t points);

private:
    MinMax range(std::uint64_t first, std::uint64_t end, int level);
    MinMax buckets(int level, std::uint64_t first, std::uint64_t end);
    std::uint64_t storedBuckets(int level);
    const std::vector<MinMax>& row(int level, std::uint64_t rowFirstBucket);
    void prefetch(int level, std::uint64_t firstBucket, std::uint64_t endBucket);

    Database* m_db;  // none when read from elsewhere
    std::unique_ptr<LodRows> m_source;
    std::int64_t m_session;
    std::int64_t m_channel;
    SampleReader m_samples;
    LodRowMap m_rows;  // read so far
    std::array<std::optional<std::uint64_t>, kLevels> m_stored{};
};

}  // namespace tactiscope::core::storage::lod
