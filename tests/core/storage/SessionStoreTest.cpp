// The session store on real SQLite files in a temporary folder: a round
// trip of sessions, channels, chunks and gaps; the byte layout of a chunk;
// and the files and folders it must refuse, named, without touching them.
#include "core/storage/SessionStore.h"

#include "core/SampleBlock.h"
#include "core/storage/ChunkCodec.h"
#include "core/storage/Schema.h"

#include "support/FileBytes.h"
#include "support/TempDirectory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace tactiscope::core;
using namespace tactiscope::core::storage;

namespace {

using SessionStoreTest = tactiscope::testing::TempDirectoryTest;

// Values exactly representable in binary32, so the round trip is exact:
// channel c, sample i → 1000 c + i / 4.
double valueAt(std::size_t c, std::uint64_t i)
{
    return 1000.0 * static_cast<double>(c) + static_cast<double>(i) / 4.0;
}

SampleBlock blockAt(std::uint64_t first, std::size_t count)
{
    SampleBlock block(2, count, static_cast<double>(first) / 500.0, 1.0 / 500.0, first);
    for (std::size_t c = 0; c < 2; ++c)
        for (std::size_t s = 0; s < count; ++s) block.channel(c)[s] = valueAt(c, first + s);
    return block;
}

const std::vector<ChannelDescriptor> kChannels{{"a", "", ChannelKind::Strain}, {"force", "N", ChannelKind::Force}};

SessionMetadata modeOnly(tactiscope::core::Mode mode)
{
    SessionMetadata metadata;
    metadata.mode = mode;
    return metadata;
}

}  // namespace

TEST_F(SessionStoreTest, SessionsChannelsSamplesAndGapsRoundTrip)
{
    std::int64_t id = 0;
    {
        SessionStore store(file("s.tactiscope"));
        SessionMetadata metadata{tactiscope::core::Mode::PanelScan,
                                 "door-17",
                                 "Ada",
                                 "press 3",
                                 "first shift",
                                 "TSP-2",
                                 "SN42",
                                 "1.2.0",
                                 R"({"profile":"x"})",
                                 R"([{"id":1}])",
                                 "",
                                 0,
                                 ""};
        id = store.beginSession(metadata, kChannels, 500.0);
        // Samples 0–99, then 30 lost (100–129), then 130–229 in three blocks.
        store.appendBlocks(id, std::vector{blockAt(0, 60), blockAt(60, 40)});
        store.appendBlocks(id, std::vector{blockAt(130, 25), blockAt(155, 25), blockAt(180, 50)});
        store.endSession(id, tactiscope::core::SessionStatus::Complete);
    }
    SessionStore store(file("s.tactiscope"), Database::Access::ReadOnly);
    const auto sessions = store.sessions();
    ASSERT_EQ(sessions.size(), 1u);
    const SessionSummary& s = sessions.front();
    EXPECT_EQ(s.id, id);
    EXPECT_EQ(s.uuid.size(), 36u);
    EXPECT_EQ(s.uuid[14], '4');  // version 4
    EXPECT_EQ(s.metadata.mode, tactiscope::core::Mode::PanelScan);
    EXPECT_EQ(s.metadata.subject, "door-17");
    EXPECT_EQ(s.metadata.operatorName, "Ada");
    EXPECT_EQ(s.metadata.site, "press 3");
    EXPECT_EQ(s.metadata.notes, "first shift");
    EXPECT_EQ(s.metadata.deviceSerial, "SN42");
    EXPECT_EQ(s.metadata.deviceFirmware, "1.2.0");
    EXPECT_EQ(s.metadata.profileJson, R"({"profile":"x"})");
    EXPECT_EQ(s.metadata.calibrationsJson, R"([{"id":1}])");
    EXPECT_DOUBLE_EQ(s.sampleRate_hz, 500.0);
    EXPECT_EQ(s.sampleCount, 230u);
    EXPECT_DOUBLE_EQ(s.duration_s(), 0.46);
    EXPECT_EQ(s.status, tactiscope::core::SessionStatus::Complete);
    EXPECT_EQ(s.startedUtc.size(), 24u);  // 2026-11-21T14:20:28.123Z
    EXPECT_EQ(s.startedUtc.back(), 'Z');
    EXPECT_FALSE(s.endedUtc.empty());

    const auto channels = store.channels(id);
    ASSERT_EQ(channels.size(), 2u);
    EXPECT_EQ(channels[1].descriptor, kChannels[1]);
    EXPECT_DOUBLE_EQ(channels[1].sampleRate_hz, 500.0);

    EXPECT_EQ(store.sampleCount(id), 230u);
    const auto gaps = store.gaps(id);
    ASSERT_EQ(gaps.size(), 1u);
    EXPECT_EQ(gaps[0].firstIndex, 100u);
    EXPECT_EQ(gaps[0].count, 30u);

    // A range across two chunks, the gap and three more chunks.
    const auto force = store.readChannel(id, 1, 50, 150);
    ASSERT_EQ(force.size(), 150u);
    for (std::uint64_t i = 50; i < 200; ++i) {
        if (i >= 100 && i < 130)
            EXPECT_TRUE(std::isnan(force[i - 50])) << i;
        else
            EXPECT_EQ(force[i - 50], valueAt(1, i)) << i;
    }
    // Clipped at the end of the recording.
    EXPECT_EQ(store.readChannel(id, 0, 220, 100).size(), 10u);
    EXPECT_TRUE(store.readChannel(id, 0, 400, 10).empty());
    EXPECT_THROW(store.readChannel(id, 2, 0, 10), StorageError);

    // Both channels at once, in windows that cut chunks and the gap, into
    // the same buffers each time: the values above, window by window.
    std::vector<std::vector<double>> window;
    const std::vector<std::size_t> both{1, 0};
    for (std::uint64_t first = 0; first < 230; first += 37) {
        const std::size_t n = store.readChannels(id, both, first, 37, window);
        ASSERT_EQ(n, std::min<std::uint64_t>(37, 230 - first));
        ASSERT_EQ(window.size(), 2u);
        for (std::size_t k = 0; k < 2; ++k) {
            ASSERT_EQ(window[k].size(), n);
            for (std::size_t i = 0; i < n; ++i) {
                const std::uint64_t index = first + i;
                if (index >= 100 && index < 130)
                    EXPECT_TRUE(std::isnan(window[k][i])) << index;
                else
                    EXPECT_EQ(window[k][i], valueAt(both[k], index)) << index;
            }
        }
    }
    EXPECT_EQ(store.readChannels(id, both, 400, 10, window), 0u);
    EXPECT_TRUE(window[0].empty());
}

TEST_F(SessionStoreTest, AChunkIsLittleEndianBinary32ChannelMajor)
{
    SampleBlock block(2, 2, 0.0, 1.0);
    block.channel(0)[0] = 1.0;    // 0x3F800000
    block.channel(0)[1] = -2.0;   // 0xC0000000
    block.channel(1)[0] = 0.5;    // 0x3F000000
    block.channel(1)[1] = 0.375;  // 0x3EC00000
    const std::vector<std::uint8_t> expected{0x00, 0x00, 0x80, 0x3F, 0x00, 0x00, 0x00, 0xC0,
                                             0x00, 0x00, 0x00, 0x3F, 0x00, 0x00, 0xC0, 0x3E};
    EXPECT_EQ(encodeChunk(block), expected);
    std::vector<double> second(2);
    decodeChunkChannel(expected, 2, 2, 1, 0, second);
    EXPECT_EQ(second, (std::vector<double>{0.5, 0.375}));
    EXPECT_THROW(decodeChunkChannel(std::span(expected).first(12), 2, 2, 1, 0, second), StorageError);
}

TEST_F(SessionStoreTest, OutOfOrderBlocksAreRefusedAndTheBatchIsNotStored)
{
    SessionStore store(file("s.tactiscope"));
    const auto id = store.beginSession(modeOnly(tactiscope::core::Mode::Palpation), kChannels, 500.0);
    store.appendBlocks(id, std::vector{blockAt(0, 10)});
    EXPECT_THROW(store.appendBlocks(id, std::vector{blockAt(10, 10), blockAt(5, 10)}), StorageError);
    EXPECT_EQ(store.sampleCount(id), 10u);
}

TEST_F(SessionStoreTest, ANonDatabaseFileIsRefusedAndLeftUntouched)
{
    const std::string path = file("notes.txt");
    std::ofstream(path) << "these are my notes, not a database; please keep them\n";
    const std::string before = tactiscope::testing::fileBytes(path);
    try {
        SessionStore store(path);
        FAIL() << "opened a text file as a store";
    } catch (const StorageError& e) {
        EXPECT_NE(std::string(e.what()).find("is not a Tactiscope session store"), std::string::npos) << e.what();
    }
    EXPECT_EQ(tactiscope::testing::fileBytes(path), before);
}

TEST_F(SessionStoreTest, AFolderOrAnEmptyFileIsCalledWhatItIs)
{
    // Before: "disk I/O error" for a folder and "an older store version (0)"
    // for an empty file opened to read.
    const auto errorOpening = [](const std::string& path, Database::Access access) -> std::string {
        try {
            SessionStore store(path, access);
        } catch (const StorageError& e) {
            return e.what();
        }
        return "opened";
    };
    for (const auto access : {Database::Access::ReadOnly, Database::Access::ReadWrite})
        EXPECT_NE(errorOpening(m_dir.string(), access).find("is a folder, not a session store"), std::string::npos);
    const std::string empty = file("empty.tactiscope");
    std::ofstream{empty};
    EXPECT_NE(errorOpening(empty, Database::Access::ReadOnly).find("is empty: it holds no sessions yet"),
              std::string::npos);
    EXPECT_EQ(std::filesystem::file_size(empty), 0u);
}

TEST_F(SessionStoreTest, AnotherProgramsSqliteFileIsRefusedAndLeftUntouched)
{
    const std::string path = file("other.db");
    {
        Database other(path, Database::Access::ReadWrite);
        other.exec("CREATE TABLE invoices (n INTEGER); INSERT INTO invoices VALUES (7)");
    }
    const std::string before = tactiscope::testing::fileBytes(path);
    try {
        SessionStore store(path);
        FAIL() << "opened a foreign SQLite file as a store";
    } catch (const StorageError& e) {
        EXPECT_NE(std::string(e.what()).find("another program"), std::string::npos) << e.what();
    }
    EXPECT_EQ(tactiscope::testing::fileBytes(path), before);
}

TEST_F(SessionStoreTest, ANewerStoreOpensReadOnlyButIsNotWritten)
{
    const std::string path = file("newer.tactiscope");
    {
        SessionStore store(path);
        store.beginSession(modeOnly(tactiscope::core::Mode::Capacitive), kChannels, 100.0);
        store.database().exec("PRAGMA user_version = " + std::to_string(kSchemaVersion + 1));
    }
    try {
        SessionStore store(path);
        FAIL() << "opened a newer store for writing";
    } catch (const StorageError& e) {
        EXPECT_NE(std::string(e.what()).find("newer Tactiscope"), std::string::npos) << e.what();
    }
    SessionStore reader(path, Database::Access::ReadOnly);
    ASSERT_EQ(reader.sessions().size(), 1u);
    EXPECT_EQ(reader.sessions().front().metadata.mode, tactiscope::core::Mode::Capacitive);
}

// A store whose header says a version no Tactiscope writes (0 or below,
// with tables): found by the store fuzzer, a read-only open of one with a
// negative version migrated its private copy from before the first
// migration and crashed. Refused, read-only and read-write, file untouched.
TEST_F(SessionStoreTest, AStoreVersionBelowOneIsDamaged)
{
    const std::string path = file("below.tactiscope");
    {
        SessionStore store(path);
        store.beginSession(modeOnly(tactiscope::core::Mode::Capacitive), kChannels, 100.0);
    }
    for (const int version : {0, -1, -2147483647}) {
        Database(path, Database::Access::ReadWrite).exec("PRAGMA user_version = " + std::to_string(version));
        const std::string before = tactiscope::testing::fileBytes(path);
        for (const auto access : {Database::Access::ReadOnly, Database::Access::ReadWrite}) {
            try {
                SessionStore store(path, access);
                ADD_FAILURE() << "opened a store of version " << version;
            } catch (const StoreInputError& e) {
                EXPECT_NE(std::string(e.what()).find("which no Tactiscope writes: the store is damaged"),
                          std::string::npos)
                    << e.what();
            }
        }
        EXPECT_EQ(tactiscope::testing::fileBytes(path), before);
    }
}

TEST_F(SessionStoreTest, ANewStoreHasTheCurrentVersionAndWal)
{
    const std::string path = file("fresh.tactiscope");
    {
        SessionStore store(path);
    }
    Database db(path, Database::Access::ReadOnly);
    auto version = db.prepare("PRAGMA user_version");
    ASSERT_TRUE(version.step());
    EXPECT_EQ(version.int64(0), kSchemaVersion);
    auto application = db.prepare("PRAGMA application_id");
    ASSERT_TRUE(application.step());
    EXPECT_EQ(application.int64(0), 0x54534331);
    auto journal = db.prepare("PRAGMA journal_mode");
    ASSERT_TRUE(journal.step());
    EXPECT_EQ(journal.text(0), "wal");
}
