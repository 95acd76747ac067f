// The min/max pyramid on a real store: every overview point equals the min
// and max computed directly from the samples it covers (gaps included),
// whatever the range, the number of points, the block sizes and the
// commits the session was written in; an overview reads few samples; and a
// version-1 store gets its pyramid when it is migrated.
#include "core/storage/SessionStore.h"

#include "core/SampleBlock.h"
#include "core/storage/ChunkCodec.h"
#include "core/storage/Schema.h"

#include "support/TempDirectory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace tactiscope::core;
using namespace tactiscope::core::storage;

namespace {

using LodOverviewTest = tactiscope::testing::TempDirectoryTest;

const std::vector<ChannelDescriptor> kChannels{{"a", "", ChannelKind::Strain}, {"b", "", ChannelKind::Strain}};

SessionMetadata panelScan()
{
    SessionMetadata metadata;
    metadata.mode = tactiscope::core::Mode::PanelScan;
    return metadata;
}

// Writes `total` samples per channel (a random walk, different per
// channel) in blocks of 1–700 samples, committed in batches of 1–40
// blocks, losing a random stretch now and then; ends with lost samples.
std::int64_t writeSession(SessionStore& store, std::uint64_t total, std::uint32_t seed)
{
    const auto id = store.beginSession(panelScan(), kChannels, 2000.0);
    std::mt19937 random(seed);
    std::uniform_int_distribution<std::size_t> blockSize(1, 700), batchSize(1, 40);
    std::uniform_real_distribution<double> step(-1.0, 1.0);
    std::bernoulli_distribution lose(0.01);
    std::uniform_int_distribution<std::uint64_t> lossSize(1, 5000);
    double walk[2] = {0.0, 100.0};
    std::uint64_t next = 0;
    while (next < total) {
        std::vector<SampleBlock> batch;
        for (std::size_t b = batchSize(random); b > 0 && next < total; --b) {
            if (lose(random)) next += lossSize(random);
            const std::size_t n = std::min<std::uint64_t>(blockSize(random), total - next);
            SampleBlock block(2, n, static_cast<double>(next) / 2000.0, 1.0 / 2000.0, next);
            for (std::size_t c = 0; c < 2; ++c)
                for (double& v : block.channel(c)) v = walk[c] += step(random);
            batch.push_back(std::move(block));
            next += n;
        }
        store.appendBlocks(id, batch);
    }
    store.markLostUntil(id, next + 777);
    return id;
}

// The reference: min and max straight from the samples, NaN-aware.
std::pair<double, double> directMinMax(const std::vector<double>& samples, std::uint64_t first, std::uint64_t count)
{
    double lo = NAN, hi = NAN;
    for (std::uint64_t i = first; i < first + count; ++i) {
        const double v = samples[i];
        if (std::isnan(v)) continue;
        lo = std::isnan(lo) || v < lo ? v : lo;
        hi = std::isnan(hi) || v > hi ? v : hi;
    }
    return {lo, hi};
}

void expectSameValue(double actual, double expected, const std::string& where)
{
    if (std::isnan(expected))
        EXPECT_TRUE(std::isnan(actual)) << where;
    else
        EXPECT_EQ(actual, expected) << where;
}

// Checks one overview against the samples: points tile the range in order,
// there are about as many as asked, and each is exact.
void checkOverview(SessionStore& store, std::int64_t id, std::size_t channel, const std::vector<double>& samples,
                   std::uint64_t first, std::uint64_t count, std::size_t points)
{
    const std::uint64_t end = std::min<std::uint64_t>(samples.size(), first + count);
    const auto overview = store.overview(id, channel, first, count, points);
    const std::string query =
        "range " + std::to_string(first) + "+" + std::to_string(count) + " at " + std::to_string(points) + " points";
    ASSERT_EQ(overview.size(), std::min<std::uint64_t>(points, end - first)) << query;
    std::uint64_t next = first;
    for (std::size_t p = 0; p < overview.size(); ++p) {
        const auto& point = overview[p];
        ASSERT_EQ(point.firstIndex, next) << query << ", point " << p;
        ASSERT_GT(point.count, 0u) << query << ", point " << p;
        const auto [lo, hi] = directMinMax(samples, point.firstIndex, point.count);
        expectSameValue(point.min, lo, query + ", min of point " + std::to_string(p));
        expectSameValue(point.max, hi, query + ", max of point " + std::to_string(p));
        next += point.count;
    }
    EXPECT_EQ(next, end) << query;
}

}  // namespace

TEST_F(LodOverviewTest, EveryOverviewPointEqualsTheMinMaxOfItsSamples)
{
    SessionStore store(file("lod.tactiscope"));
    // Over 4 level-4 buckets (262 144 samples each), so every level is used.
    const auto id = writeSession(store, 1'100'000, 7);
    const std::uint64_t total = store.sampleCount(id);
    ASSERT_GT(store.gaps(id).size(), 5u);
    for (std::size_t channel = 0; channel < 2; ++channel) {
        const auto samples = store.readChannel(id, channel, 0, total);
        ASSERT_EQ(samples.size(), total);
        checkOverview(store, id, channel, samples, 0, total, 2000);
        checkOverview(store, id, channel, samples, 0, total, 3);  // level 4
        checkOverview(store, id, channel, samples, 0, total, 1);
        checkOverview(store, id, channel, samples, 5, 90, 2000);              // fewer samples than points
        checkOverview(store, id, channel, samples, total - 1000, 5000, 100);  // into the lost tail, clipped
        std::mt19937 random(static_cast<std::uint32_t>(11 + channel));
        std::uniform_int_distribution<std::uint64_t> position(0, total - 1);
        std::uniform_int_distribution<std::size_t> points(1, 3000);
        for (int query = 0; query < 40; ++query) {
            const std::uint64_t first = position(random);
            const std::uint64_t count = 1 + position(random) % (total - first);
            checkOverview(store, id, channel, samples, first, count, points(random));
        }
    }
}

TEST_F(LodOverviewTest, AnOverviewReadsFewSamplesAndNoWholeChunks)
{
    SessionStore store(file("lod.tactiscope"));
    const auto id = writeSession(store, 1'000'000, 3);
    const std::uint64_t total = store.sampleCount(id);
    const std::uint64_t before = store.chunksRead();
    const auto overview = store.overview(id, 0, 1234, total - 2468, 2000);
    ASSERT_EQ(overview.size(), 2000u);
    // Only the two unaligned ends of the range come from samples: a few
    // chunks, against the ~250 (4096 samples each) of reading everything.
    EXPECT_LE(store.chunksRead() - before, 4u);
}

TEST_F(LodOverviewTest, ThePyramidContinuesWhenTheStoreIsReopenedMidSession)
{
    std::int64_t id = 0;
    std::vector<double> expected;
    {
        SessionStore store(file("lod.tactiscope"));
        id = writeSession(store, 50'000, 5);
    }
    {
        // Another connection appends more, as after a reconnection.
        SessionStore store(file("lod.tactiscope"));
        const std::uint64_t end = store.sampleCount(id);
        SampleBlock block(2, 70'001, 0.0, 1.0 / 2000.0, end);
        for (std::size_t c = 0; c < 2; ++c)
            for (std::size_t s = 0; s < block.sampleCount(); ++s)
                block.channel(c)[s] = std::sin(static_cast<double>(s) * 1e-3) * static_cast<double>(c + 1);
        store.appendBlocks(id, std::vector{block});
    }
    SessionStore store(file("lod.tactiscope"), Database::Access::ReadOnly);
    const std::uint64_t total = store.sampleCount(id);
    for (std::size_t channel = 0; channel < 2; ++channel) {
        const auto samples = store.readChannel(id, channel, 0, total);
        checkOverview(store, id, channel, samples, 0, total, 700);
        checkOverview(store, id, channel, samples, 49'000, 3000, 10);
    }
}

TEST_F(LodOverviewTest, AVersion1StoreGetsItsPyramidWhenMigrated)
{
    const std::string path = file("v1.tactiscope");
    {
        Database db(path, Database::Access::ReadWrite);
        ASSERT_EQ(prepareSchema(db, 1), 0);
        db.exec("INSERT INTO sessions (id, uuid, mode, started_utc, status, app_version) "
                "VALUES (1, 'u', 'panel-scan', '2026-01-01T00:00:00.000Z', 'complete', '0.1')");
        db.exec("INSERT INTO channels VALUES (1, 0, 'a', '', 'strain', 1000), (1, 1, 'b', '', 'strain', 1000)");
        for (std::uint64_t first = 0; first < 20'000; first += 5000) {
            SampleBlock block(2, 5000, 0.0, 1e-3, first);
            for (std::size_t c = 0; c < 2; ++c)
                for (std::size_t s = 0; s < 5000; ++s)
                    block.channel(c)[s] = static_cast<double>((first + s) % 997) - 300.0 * static_cast<double>(c);
            db.prepare("INSERT INTO chunks VALUES (1, ?, 0, 5000, ?)")
                .bind(1, static_cast<std::int64_t>(first))
                .bindBlob(2, encodeChunk(block))
                .run();
        }
    }
    SessionStore store(path);
    auto version = store.database().prepare("PRAGMA user_version");
    ASSERT_TRUE(version.step());
    EXPECT_EQ(version.int64(0), kSchemaVersion);
    ASSERT_EQ(store.sampleCount(1), 20'000u);
    const auto samples = store.readChannel(1, 1, 0, 20'000);
    const std::uint64_t before = store.chunksRead();
    checkOverview(store, 1, 1, samples, 0, 19'968, 50);  // 312 whole buckets
    EXPECT_EQ(store.chunksRead(), before);               // aligned: all from the pyramid
}
