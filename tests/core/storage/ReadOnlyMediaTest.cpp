// A valid store on a read-only file system (a tmpfs remounted read-only, as
// a write-protected card or a mounted archive is): it opens read-only and
// reads whole, and a read-write open says the store is read-only. Before,
// it could not be opened at all ("unable to open database file"), because
// SQLite could not make the WAL's shared-memory file beside it (issue 19).
// Mounting needs root, which CI is; elsewhere the test skips, saying so.
#include "core/SampleBlock.h"
#include "core/storage/SessionStore.h"

#include <gtest/gtest.h>

#include <sys/mount.h>

#include <cstdlib>
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
        char folder[] = "/tmp/tactiscope-ro-XXXXXX";
        ASSERT_NE(::mkdtemp(folder), nullptr);
        m_mount = folder;
        if (::mount("tmpfs", m_mount.c_str(), "tmpfs", 0, "size=8m") != 0) {
            std::filesystem::remove(m_mount);
            m_mount.clear();
            GTEST_SKIP() << "mounting a tmpfs needs root: the read-only media test is skipped";
        }
        m_store = m_mount + "/sessions.tactiscope";
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
        ASSERT_EQ(::mount("tmpfs", m_mount.c_str(), "tmpfs", MS_REMOUNT | MS_RDONLY, "size=8m"), 0);
    }

    void TearDown() override
    {
        if (m_mount.empty()) return;
        ::umount(m_mount.c_str());
        std::filesystem::remove(m_mount);
    }

    std::string m_mount, m_store;
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
