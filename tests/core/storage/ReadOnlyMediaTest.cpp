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
