// LodTable: SQL for the pyramid's rows, and range queries that recurse from
// coarse buckets to finer ones at the edges.
#include "core/storage/LodTable.h"

#include <string>

namespace tactiscope::core::storage::lod {
namespace {

std::uint64_t roundUp(std::uint64_t value, std::uint64_t step)
{
    return (value + step - 1) / step * step;
}

MinMax minMaxOf(std::span<const double> samples)
{
    MinMax result;
    for (const double value : samples) result.add(static_cast<float>(value));
    return result;
}

double toDouble(float value)
{
    return static_cast<double>(value);
}

// The rows of table `lod` in a station's store.
class StoreLodRows : public LodRows {
public:
    StoreLodRows(Database& db, std::int64_t session, std::int64_t channel)
        : m_db(db),
          m_session(session),
          m_channel(channel)
    {
    }

    std::uint64_t storedBuckets(int level) override
    {
        auto query = m_db.prepare("SELECT first_bucket + count FROM lod WHERE session_id = ? AND channel = ? AND "
                                  "level = ? ORDER BY first_bucket DESC LIMIT 1");
        query.bind(1, m_session).bind(2, m_channel).bind(3, std::int64_t{level});
        return query.step() ? static_cast<std::uint64_t>(query.int64(0)) : 0;
    }

    void read(int level, std::uint64_t firstBucket, std::uint64_t endBucket, LodRowMap& rows) override
    {
        auto query = m_db.prepare("SELECT first_bucket, count, buckets FROM lod WHERE session_id = ? AND channel = ? "
                                  "AND level = ? AND first_bucket >= ? AND first_bucket < ?");
        query.bind(1, m_session)
            .bind(2, m_channel)
            .bind(3, std::int64_t{level})
            .bind(4, static_cast<std::int64_t>(firstBucket))
            .bind(5, static_cast<std::int64_t>(endBucket));
        while (query.step()) {
            const auto first = static_cast<std::uint64_t>(query.int64(0));
            rows[{level, first}] = decodeBuckets(query.blob(2), static_cast<std::size_t>(query.int64(1)));
        }
    }

private:
    Database& m_db;
    std::int64_t m_session;
    std::int64_t m_channel;
};

}  // namespace

LodTable::LodTable(Database& db, std::int64_t session, std::size_t channel, SampleReader samples)
    : m_db(&db),
      m_source(std::make_unique<StoreLodRows>(db, session, static_cast<std::int64_t>(channel))),
      m_session(session),
      m_channel(static_cast<std::int64_t>(channel)),
      m_samples(std::move(samples))
{
}

LodTable::LodTable(std::unique_ptr<LodRows> rows, std::int64_t session, SampleReader samples)
    : m_db(nullptr),
      m_source(std::move(rows)),
      m_session(session),
      m_channel(0),
      m_samples(std::move(samples))
{
}

std::uint64_t LodTable::storedBuckets(int level)
{
    auto& stored = m_stored[static_cast<std::size_t>(level)];
    if (!stored) stored = m_source->storedBuckets(level);
    return *stored;
}

void LodTable::prefetch(int level, std::uint64_t firstBucket, std::uint64_t endBucket)
{
    m_source->read(level, firstBucket / kBucketsPerRow * kBucketsPerRow, endBucket, m_rows);
}

const std::vector<MinMax>& LodTable::row(int level, std::uint64_t rowFirstBucket)
{
    const auto key = std::pair(level, rowFirstBucket);
    if (!m_rows.contains(key)) {
        prefetch(level, rowFirstBucket, rowFirstBucket + 1);
        if (!m_rows.contains(key))
            throw StoreInputError("the min/max row at level " + std::to_string(level) + ", bucket " +
                                  std::to_string(rowFirstBucket) + " of session " + std::to_string(m_session) +
                                  " is missing; the store is damaged");
    }
    return m_rows[key];
}

MinMax LodTable::buckets(int level, std::uint64_t first, std::uint64_t end)
{
    MinMax result;
    for (std::uint64_t b = first; b < end;) {
        const std::uint64_t rowFirst = b / kBucketsPerRow * kBucketsPerRow;
        const auto& buckets = row(level, rowFirst);
        const std::uint64_t rowEnd = std::min(end, rowFirst + buckets.size());
        if (rowEnd <= b)
            throw StoreInputError("a min/max row of session " + std::to_string(m_session) +
                                  " is shorter than the pyramid says; the store is damaged");
        for (; b < rowEnd; ++b) result.add(buckets[static_cast<std::size_t>(b - rowFirst)]);
    }
    return result;
}

MinMax LodTable::range(std::uint64_t first, std::uint64_t end, int level)
{
    if (first >= end) return {};
    if (level < 0) {
        return minMaxOf(m_samples(first, end - first));
    }
    const std::uint64_t size = bucketSize(level);
    const std::uint64_t inner = roundUp(first, size);
    const std::uint64_t innerEnd = std::min(end / size, storedBuckets(level)) * size;
    if (inner >= innerEnd) return range(first, end, level - 1);
    MinMax result = range(first, inner, level - 1);
    result.add(buckets(level, inner / size, innerEnd / size));
    result.add(range(innerEnd, end, level - 1));
    return result;
}

std::vector<OverviewPoint> LodTable::overview(std::uint64_t first, std::uint64_t end, std::size_t points)
{
    std::vector<OverviewPoint> result;
    if (first >= end || points == 0) return result;
    const std::uint64_t span = end - first;
    points = static_cast<std::size_t>(std::min<std::uint64_t>(points, span));
    const std::uint64_t width = span / points;
    result.reserve(points);
    const auto addPoint = [&result](std::uint64_t from, std::uint64_t to, MinMax m) {
        result.push_back({from, to - from, toDouble(m.min), toDouble(m.max)});
    };
    if (width < bucketSize(0)) {
        // Finer than any bucket: one read of the samples themselves.
        const std::vector<double> samples = m_samples(first, span);
        for (std::size_t p = 0; p < points; ++p) {
            const std::uint64_t from = p * span / points, to = (p + 1) * span / points;
            addPoint(first + from, first + to, minMaxOf(std::span(samples).subspan(from, to - from)));
        }
        return result;
    }
    int level = 0;
    while (level + 1 < kLevels && bucketSize(level + 1) <= width) ++level;
    const std::uint64_t size = bucketSize(level);
    prefetch(level, first / size, end / size + 1);
    // Boundaries snap to the nearest bucket edge; as points are at least a
    // bucket wide, snapped boundaries stay strictly increasing.
    std::uint64_t from = first;
    for (std::size_t p = 1; p <= points; ++p) {
        const std::uint64_t ideal = first + p * span / points;
        const std::uint64_t to = p == points ? end : (ideal + size / 2) / size * size;
        addPoint(from, to, range(from, to, level));
        from = to;
    }
    return result;
}

LodBuilder LodTable::builderAt(std::uint64_t sampleEnd)
{
    std::array<LodLevelState, kLevels> state;
    for (int level = 0; level < kLevels; ++level) {
        auto& s = state[static_cast<std::size_t>(level)];
        const std::uint64_t stored = storedBuckets(level);
        s.rowFirstBucket = stored / kBucketsPerRow * kBucketsPerRow;
        if (stored > s.rowFirstBucket) s.row = row(level, s.rowFirstBucket);
        // The partial bucket gathers what the level below completed since.
        const std::uint64_t covered = stored * bucketSize(level);
        const std::uint64_t below = level == 0 ? sampleEnd : storedBuckets(level - 1) * bucketSize(level - 1);
        if (below < covered || below - covered >= bucketSize(level))
            throw StoreInputError("the min/max pyramid of session " + std::to_string(m_session) +
                                  " does not match its samples; the store is damaged");
        s.partial = range(covered, below, level - 1);
        s.partialSamples = below - covered;
    }
    return LodBuilder(std::move(state));
}

void LodTable::write(const std::vector<LodRow>& rows)
{
    if (!m_db) throw StorageError("the min/max pyramid of session " + std::to_string(m_session) + " is read-only here");
    auto insert = m_db->prepare("INSERT OR REPLACE INTO lod VALUES (?, ?, ?, ?, ?, ?)");
    for (const LodRow& r : rows) {
        insert.bind(1, m_session)
            .bind(2, m_channel)
            .bind(3, std::int64_t{r.level})
            .bind(4, static_cast<std::int64_t>(r.firstBucket))
            .bind(5, static_cast<std::int64_t>(r.buckets.size()))
            .bindBlob(6, encodeBuckets(r.buckets))
            .run();
    }
    m_rows.clear();
    m_stored.fill(std::nullopt);
}

}  // namespace tactiscope::core::storage::lod
