// A valid store on a read-only file system (a tmpfs remounted read-only, as
// a write-protected card or a mounted archive is): it opens read-only and
// reads whole, and a read-write open says the store is read-only. Before,
// it could not be opened at all ("unable to open database file"), because
// SQLite could not make the WAL's shared-memory file beside it (issue 19).
// Mounting needs root, which CI is; elsewhere the test skips, saying so.
#include "core/SampleBlock.h"
#include "core/storage/SessionStore.h"
#include "support/TmpfsMount.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

using namespace tactiscope::core;
using storage::Database;
using storage::SessionStore;
using storage::StorageError;

namespace {

class ReadOnlyMedia : public ::testing::Test {
protected:
    void SetUp() override
    {
        if (!m_media.mounted()) GTEST_SKIP() << tactiscope::testing::TmpfsMount::kSkipReason;
        m_store = m_media.file("sessions.tactiscope");
        {
            SessionStore store(m_store);
            storage::SessionMetadata metadata;
            metadata.mode = Mode::PanelScan;
            metadata.subject = "archived door";
            const std::vector<ChannelDescriptor> channels{{"a", "", ChannelKind::Strain}};
            const auto id = store.beginSession(metadata, channels, 100.0);
            SampleBlock block(1, 300, 0.0, 0.01, 0);
            for (std::size_t i = 0; i < 300; ++i) block.channel(0)[i] = static_cast<double>(i);
            store.appendBlocks(id, std::span(&block, 1));
            store.endSession(id, SessionStatus::Complete);
        }
        ASSERT_TRUE(m_media.makeReadOnly());
    }

    tactiscope::testing::TmpfsMount m_media{"8m"};
    std::string m_store;
};

// The private copies of stores read from a read-only disk with a log.
std::size_t privateCopies()
{
    std::size_t count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::temp_directory_path()))
        if (entry.path().filename().string().starts_with("tactiscope-store-")) ++count;
    return count;
}

}  // namespace

TEST_F(ReadOnlyMedia, AStoreOnItOpensReadOnlyAndReadsWhole)
{
    SessionStore store(m_store, Database::Access::ReadOnly);
    const auto sessions = store.sessions();
    ASSERT_EQ(sessions.size(), 1u);
    EXPECT_EQ(sessions[0].metadata.subject, "archived door");
    const auto samples = store.readChannel(sessions[0].id, 0, 0, 300);
    ASSERT_EQ(samples.size(), 300u);
    EXPECT_EQ(samples[299], 299.0);
}

TEST_F(ReadOnlyMedia, AReadWriteOpenSaysTheStoreIsReadOnly)
{
    try {
        SessionStore store(m_store);
        FAIL() << "a store on read-only media was opened read-write";
    } catch (const StorageError& e) {
        EXPECT_NE(std::string(e.what()).find("read-only"), std::string::npos) << e.what();
    }
}

// A crashed station's store copied with its write-ahead log: the newest
// session is only in the log. Before, the read-only open (immutable)
// ignored the log and said the store held only the older session, exit 0,
// no word. Now it reads the store whole from a private copy, says so, and
// leaves no copy behind.
TEST(ReadOnlyMediaWithALog, TheSessionsInTheLogAreReadAndTheReaderIsTold)
{
    tactiscope::testing::TmpfsMount media("8m");
    if (!media.mounted()) GTEST_SKIP() << tactiscope::testing::TmpfsMount::kSkipReason;
    const std::string live = media.file("live.tactiscope"), crashed = media.file("crashed.tactiscope");
    const auto record = [](SessionStore& store, const std::string& subject) {
        storage::SessionMetadata metadata;
        metadata.mode = Mode::PanelScan;
        metadata.subject = subject;
        const std::vector<ChannelDescriptor> channels{{"a", "", ChannelKind::Strain}};
        const auto id = store.beginSession(metadata, channels, 100.0);
        SampleBlock block(1, 50, 0.0, 0.01, 0);
        store.appendBlocks(id, std::span(&block, 1));
        store.endSession(id, SessionStatus::Complete);
    };
    {
        SessionStore first(live);
        record(first, "older door");
    }
    {
        SessionStore second(live);
        record(second, "newest door");
        // Copied while the station still had it open, as a crash leaves it.
        ASSERT_GT(std::filesystem::file_size(live + "-wal"), 0u);
        std::filesystem::copy_file(live, crashed);
        std::filesystem::copy_file(live + "-wal", crashed + "-wal");
    }
    ASSERT_TRUE(media.makeReadOnly());

    const auto copiesBefore = privateCopies();
    {
        SessionStore store(crashed, Database::Access::ReadOnly);
        const auto sessions = store.sessions();
        ASSERT_EQ(sessions.size(), 2u);
        EXPECT_EQ(sessions.front().metadata.subject, "newest door");
        ASSERT_TRUE(store.readNote());
        EXPECT_NE(store.readNote()->find("write-ahead log"), std::string::npos) << *store.readNote();
        EXPECT_EQ(privateCopies(), copiesBefore + 1);
    }
    EXPECT_EQ(privateCopies(), copiesBefore);  // removed with the store
    // A store without a log is read as it is, with nothing to tell.
    SessionStore plain(live, Database::Access::ReadOnly);
    EXPECT_EQ(plain.sessions().size(), 2u);
    EXPECT_FALSE(plain.readNote());
}
