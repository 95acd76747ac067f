// What a command writes or reads must not destroy its input or the program:
// an output path that is a command's own input is refused, by file identity
// (a link to the store is the store): before, `sessions export --output S`
// and `report --output S` replaced the store S with a CSV or a PDF, exit 0,
// and `detect in.csv --output in.csv` overwrote its input; and a damaged
// chunk count is "the store is damaged" for every reader (issue 19).
#include "core/storage/SessionStore.h"
#include "support/CliRunner.h"
#include "support/TextFiles.h"

#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace tactiscope;
using tactiscope::testing::readBytes;
using tactiscope::testing::runCli;

namespace {

class UntrustedFiles : public ::testing::Test {
protected:
    void SetUp() override
    {
        m_csv = m_dir.filePath("scan.csv");
        m_db = m_dir.filePath("s.tactiscope");
        ASSERT_EQ(runCli({"simulate", "--seconds", "2", "--output", m_csv}).exitCode, 0);
        ASSERT_EQ(runCli({"import", m_csv, "--db", m_db}).exitCode, 0);
        m_store = readBytes(m_db);
    }

    // The store still opens and holds its session, byte for byte as before.
    void expectStoreIntact() const
    {
        EXPECT_EQ(readBytes(m_db), m_store);
        core::storage::SessionStore store(m_db.toStdString(), core::storage::Database::Access::ReadOnly);
        EXPECT_EQ(store.sessions().size(), 1u);
    }

    QTemporaryDir m_dir;
    QString m_csv, m_db;
    QByteArray m_store;
};

}  // namespace

TEST_F(UntrustedFiles, AnExportOntoItsStoreIsRefused)
{
    const auto result = runCli({"sessions", "--db", m_db, "export", "1", "--format", "csv", "--output", m_db});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_TRUE(result.err.contains(QStringLiteral("refusing to write"))) << result.err.toStdString();
    expectStoreIntact();

    // Through a link: the same file by another name.
    const QString link = m_dir.filePath("alias.tactiscope");
    ASSERT_TRUE(QFile::link(m_db, link));
    EXPECT_EQ(runCli({"sessions", "--db", m_db, "export", "1", "--format", "json", "--output", link}).exitCode, 1);
    expectStoreIntact();
}

TEST_F(UntrustedFiles, AReportOntoItsStoreIsRefused)
{
    const auto result = runCli({"report", "--db", m_db, "--session", "1", "--output", m_db});
    EXPECT_EQ(result.exitCode, 2);
    EXPECT_TRUE(result.err.contains(QStringLiteral("refusing to write"))) << result.err.toStdString();
    expectStoreIntact();
}

TEST_F(UntrustedFiles, DetectOntoItsInputIsRefusedBeforeItReadsIt)
{
    const QByteArray input = readBytes(m_csv);
    const auto result = runCli({"detect", m_csv, "--output", m_csv});
    EXPECT_EQ(result.exitCode, 2);
    EXPECT_TRUE(result.err.contains(QStringLiteral("refusing to write"))) << result.err.toStdString();
    EXPECT_EQ(readBytes(m_csv), input);
}

TEST_F(UntrustedFiles, AnOrdinaryOutputIsWrittenWhole)
{
    const QString out = m_dir.filePath("out.csv");
    ASSERT_EQ(runCli({"detect", m_csv, "--output", out}).exitCode, 0);
    EXPECT_FALSE(QFile::exists(out + ".partial"));
    EXPECT_TRUE(readBytes(out).startsWith("t,out,rab,rba"));
}

TEST_F(UntrustedFiles, ADamagedChunkCountIsADamagedStoreEverywhere)
{
    // The last chunk claims a trillion samples: before, `analyze` and
    // `report` died of std::bad_alloc allocating for them (issue 19).
    {
        core::storage::SessionStore store(m_db.toStdString());
        store.database().exec("UPDATE chunks SET count = 1000000000000 WHERE first_index = "
                              "(SELECT max(first_index) FROM chunks WHERE session_id = 1)");
    }
    const auto analyze = runCli({"analyze", "--db", m_db, "--session", "1"});
    EXPECT_GT(analyze.exitCode, 0);
    EXPECT_TRUE(analyze.err.contains(QStringLiteral("the store is damaged"))) << analyze.err.toStdString();
    const auto report = runCli({"report", "--db", m_db, "--session", "1", "--output", m_dir.filePath("r.pdf")});
    EXPECT_GT(report.exitCode, 0);
    EXPECT_TRUE(report.err.contains(QStringLiteral("the store is damaged"))) << report.err.toStdString();
    const auto exported =
        runCli({"sessions", "--db", m_db, "export", "1", "--format", "csv", "--output", m_dir.filePath("e.csv")});
    EXPECT_GT(exported.exitCode, 0);
    EXPECT_TRUE(exported.err.contains(QStringLiteral("the store is damaged"))) << exported.err.toStdString();
}
