// What a command writes or reads must not destroy its input or the program:
// an output path that is a command's own input is refused, by file identity
// (a link to the store is the store): before, `sessions export --output S`
// and `report --output S` replaced the store S with a CSV or a PDF, exit 0,
// and `detect in.csv --output in.csv` overwrote its input; and a damaged
// chunk count is "the store is damaged" for every reader (issue 19).
#include "core/storage/SessionStore.h"
#include "support/CliRunner.h"
#include "support/TextFiles.h"

#include <QDir>
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
    EXPECT_TRUE(readBytes(out).startsWith("t,out,rab,rba"));
    // No temporary is left in the folder (they are hidden: ".out.csv.XXXXXX").
    EXPECT_TRUE(QDir(m_dir.path()).entryList({QStringLiteral(".*")}, QDir::Files | QDir::Hidden).isEmpty());
    // Written with the permissions any new file gets, not a temporary's 0600.
    EXPECT_TRUE(QFile::permissions(out) & QFileDevice::ReadGroup);
}

// Before, the temporary beside an output was OUT.partial, opened by name:
// a link of that name to the store let `sessions export` truncate the
// store (exit 1) and `report` replace it with the PDF (exit 0), and
// `detect --output OUT` emptied its own input when that was OUT.partial.
// The temporary is now a new file nobody can name in advance.
TEST_F(UntrustedFiles, AFileOrLinkWhereTheTemporaryUsedToBeIsNeverTouched)
{
    const QString out = m_dir.filePath("out.csv");
    ASSERT_TRUE(QFile::link(m_db, out + ".partial"));
    EXPECT_EQ(runCli({"sessions", "--db", m_db, "export", "1", "--format", "csv", "--output", out}).exitCode, 0);
    expectStoreIntact();
    EXPECT_TRUE(readBytes(out).startsWith("t [s]"));

    const QString pdf = m_dir.filePath("r.pdf");
    ASSERT_TRUE(QFile::link(m_db, pdf + ".partial"));
    const auto report = runCli({"report", "--db", m_db, "--session", "1", "--output", pdf});
    EXPECT_EQ(report.exitCode, 0) << report.err.toStdString();
    expectStoreIntact();
    EXPECT_TRUE(readBytes(pdf).startsWith("%PDF"));

    // The input itself is called what the temporary used to be.
    const QString input = m_dir.filePath("d.csv.partial");
    ASSERT_TRUE(QFile::copy(m_csv, input));
    const QByteArray before = readBytes(input);
    EXPECT_EQ(runCli({"detect", input, "--output", m_dir.filePath("d.csv")}).exitCode, 0);
    EXPECT_EQ(readBytes(input), before);
    EXPECT_TRUE(readBytes(m_dir.filePath("d.csv")).startsWith("t,out,rab,rba"));
}

// The store itself called what a report's temporary used to be.
TEST_F(UntrustedFiles, AStoreNamedLikeAnOldTemporarySurvivesAReport)
{
    const QString renamed = m_dir.filePath("r.pdf.partial");
    ASSERT_TRUE(QFile::rename(m_db, renamed));
    m_db = renamed;
    const auto report = runCli({"report", "--db", m_db, "--session", "1", "--output", m_dir.filePath("r.pdf")});
    EXPECT_EQ(report.exitCode, 0) << report.err.toStdString();
    expectStoreIntact();
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

// Every number a reader sizes something by, damaged one at a time (found
// by an attack on the product): before, a first index of 4·10¹⁸ or a gap
// of 2⁶² samples aborted `report` and had `export` write NaN rows until the
// disk was full; the channel rows deleted made `sessions show` and
// `export` crash; a negative chunk count was silent (NaN rows, "0 lost",
// exit 0), and so were a chunk moved below index 0 or further on (a
// deleted one leaves the same hole), and a
// channel rate of 1e300 or 1e-300 Hz (issue 54). Each is now "the store is damaged", naming the session, from
// every reader, at once.
TEST_F(UntrustedFiles, EveryDamagedNumberIsADamagedStoreForEveryReader)
{
    const std::vector<std::pair<const char*, const char*>> damages{
        {"a chunk's first index of 4e18", "UPDATE chunks SET first_index = 4000000000000000000 WHERE first_index = "
                                          "(SELECT max(first_index) FROM chunks WHERE session_id = 1)"},
        {"a gap of 2^62 samples", "INSERT INTO gaps (session_id, first_index, count) VALUES (1, 1000000, "
                                  "4611686018427387904)"},
        {"the channel rows deleted", "DELETE FROM channels WHERE session_id = 1"},
        {"a negative chunk count",
         "PRAGMA ignore_check_constraints = 1; UPDATE chunks SET count = -130 WHERE first_index = "
         "(SELECT max(first_index) FROM chunks WHERE session_id = 1)"},
        {"a chunk count of 2^40", "UPDATE chunks SET count = 1099511627776 WHERE first_index = 0"},
        // Issue 54: each read as NaN rows with "0 lost".
        {"the first chunk moved to index -250", "UPDATE chunks SET first_index = -250 WHERE first_index = 0"},
        {"the chunk moved 250 samples on (samples in no chunk and no gap)",
         "UPDATE chunks SET first_index = first_index + 250 WHERE first_index = 0"},
        {"a channel rate of 1e300 Hz", "UPDATE channels SET sample_rate_hz = 1e300 WHERE position = 0"},
        {"a channel rate of 1e-300 Hz", "UPDATE channels SET sample_rate_hz = 1e-300 WHERE position = 0"},
    };
    const QByteArray intact = readBytes(m_db);
    for (const auto& [what, sql] : damages) {
        SCOPED_TRACE(what);
        {
            QFile file(m_db);
            ASSERT_TRUE(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
            file.write(intact);
        }
        {
            core::storage::SessionStore store(m_db.toStdString());
            store.database().exec(sql);
        }
        const std::vector<QStringList> readers{
            {"sessions", "--db", m_db, "show", "1"},
            {"sessions", "--db", m_db, "export", "1", "--format", "csv", "--output", m_dir.filePath("e.csv")},
            {"analyze", "--db", m_db, "--session", "1"},
            {"report", "--db", m_db, "--session", "1", "--output", m_dir.filePath("r.pdf")},
        };
        for (const QStringList& reader : readers) {
            const auto run = runCli(reader);
            EXPECT_GT(run.exitCode, 0) << reader.join(' ').toStdString();
            EXPECT_TRUE(run.err.contains(QStringLiteral("the store is damaged: in session 1")))
                << reader.join(' ').toStdString() << ": " << run.err.toStdString();
        }
        EXPECT_FALSE(QFile::exists(m_dir.filePath("e.csv")));
    }
}
