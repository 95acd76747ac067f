// `tactiscope-cli sessions` on a real store written here through the store
// API with known values: list, show, CSV and JSON export (values back to
// the bit), delete, and bad input with exit code 2.
#include "core/SampleBlock.h"
#include "core/storage/SessionStore.h"
#include "support/CliRunner.h"
#include "support/TextFiles.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cstdlib>

using namespace tactiscope;
using tactiscope::testing::runCli;

namespace {

// Channel c, sample i → (i + 1)·0.1 + c (not exact in binary or decimal, so
// the export has to round-trip binary32 properly).
double valueAt(std::size_t c, std::uint64_t i)
{
    return static_cast<double>(i + 1) * 0.1 + static_cast<double>(c);
}

core::SampleBlock block(std::uint64_t first, std::size_t count)
{
    core::SampleBlock b(2, count, static_cast<double>(first) / 200.0, 1.0 / 200.0, first);
    for (std::size_t c = 0; c < 2; ++c)
        for (std::size_t s = 0; s < count; ++s) b.channel(c)[s] = valueAt(c, first + s);
    return b;
}

// Two sessions; the second (newest) has 50 samples, 10 lost, 40 more.
QString makeStore(const QTemporaryDir& dir)
{
    const QString path = dir.filePath("s.tactiscope");
    core::storage::SessionStore store(path.toStdString());
    const std::vector<core::ChannelDescriptor> channels{{"a", "", core::ChannelKind::Strain},
                                                        {"force", "N", core::ChannelKind::Force}};
    core::storage::SessionMetadata first;
    first.mode = tactiscope::core::Mode::Palpation;
    first.subject = "phantom-2";
    const auto one = store.beginSession(first, channels, 200.0);
    store.appendBlocks(one, std::vector{block(0, 20)});
    store.endSession(one, tactiscope::core::SessionStatus::Complete);
    core::storage::SessionMetadata second;
    second.mode = tactiscope::core::Mode::PanelScan;
    second.subject = "door-17";
    second.operatorName = "Ada";
    const auto two = store.beginSession(second, channels, 200.0);
    store.appendBlocks(two, std::vector{block(0, 50), block(60, 40)});
    store.endSession(two, tactiscope::core::SessionStatus::Complete);
    return path;
}

QJsonDocument parse(const QString& text)
{
    return QJsonDocument::fromJson(text.toUtf8());
}

QString readFile(const QString& path)
{
    return QString::fromUtf8(tactiscope::testing::readBytes(path));
}

}  // namespace

TEST(SessionsCli, ListAndShow)
{
    QTemporaryDir dir;
    const QString db = makeStore(dir);
    const auto list = runCli({"sessions", "--db", db, "list", "--json"});
    ASSERT_EQ(list.exitCode, 0) << list.err.toStdString();
    const QJsonArray sessions = parse(list.out).array();
    ASSERT_EQ(sessions.size(), 2);
    EXPECT_EQ(sessions[0].toObject()["id"].toInt(), 2);  // newest first
    EXPECT_EQ(sessions[0].toObject()["subject"].toString(), "door-17");
    EXPECT_EQ(sessions[0].toObject()["operator"].toString(), "Ada");
    EXPECT_EQ(sessions[0].toObject()["status"].toString(), "complete");
    EXPECT_DOUBLE_EQ(sessions[0].toObject()["duration_s"].toDouble(), 0.5);  // 100 samples at 200 Hz
    EXPECT_EQ(sessions[1].toObject()["mode"].toString(), "palpation");

    const auto palpation = runCli({"sessions", "--db", db, "list", "--json", "--mode", "palpation"});
    ASSERT_EQ(parse(palpation.out).array().size(), 1);
    EXPECT_EQ(parse(palpation.out).array()[0].toObject()["id"].toInt(), 1);
    const auto search = runCli({"sessions", "--db", db, "list", "--json", "--search", "DOOR"});
    ASSERT_EQ(parse(search.out).array().size(), 1);
    EXPECT_EQ(parse(search.out).array()[0].toObject()["id"].toInt(), 2);
    EXPECT_EQ(parse(runCli({"sessions", "--db", db, "list", "--json", "--from", "2999"}).out).array().size(), 0);

    const auto text = runCli({"sessions", "--db", db, "list"});
    EXPECT_TRUE(text.out.contains("door-17 / Ada")) << text.out.toStdString();

    const auto show = runCli({"sessions", "--db", db, "show", "last", "--json"});
    ASSERT_EQ(show.exitCode, 0) << show.err.toStdString();
    const QJsonObject metadata = parse(show.out).object();
    EXPECT_EQ(metadata["session"].toObject()["id"].toInt(), 2);
    EXPECT_EQ(metadata["session"].toObject()["samples_per_channel"].toInt(), 100);
    EXPECT_EQ(metadata["channels"].toArray()[1].toObject()["unit"].toString(), "N");
    EXPECT_EQ(metadata["gaps"].toArray()[0].toObject()["first_index"].toInt(), 50);
    EXPECT_EQ(metadata["gaps"].toArray()[0].toObject()["count"].toInt(), 10);
    // The session's span holds its gap's lost samples (record counts them apart: 90 received, 10 lost).
    const auto gapped = runCli({"sessions", "--db", db, "show", "2"});
    EXPECT_TRUE(gapped.out.contains("90 per channel, 10 lost (0.500 s)")) << gapped.out.toStdString();
    const auto human = runCli({"sessions", "--db", db, "show", "1"});
    EXPECT_TRUE(human.out.contains("20 per channel, 0 lost (0.100 s)")) << human.out.toStdString();
    EXPECT_TRUE(human.out.contains("force [N]")) << human.out.toStdString();
}

TEST(SessionsCli, CsvExportHasOneRowPerStoredSampleExactToTheBit)
{
    QTemporaryDir dir;
    const QString db = makeStore(dir);
    const QString csv = dir.filePath("out.csv");
    const auto result = runCli({"sessions", "--db", db, "export", "last", "--format", "csv", "--output", csv});
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
    const QStringList lines = readFile(csv).split('\n', Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 1 + 90);  // header, 50 + 40 samples (the 10 lost have no row)
    EXPECT_EQ(lines[0], "t [s],a [strain],force [N]");
    for (int row = 1; row < lines.size(); ++row) {
        const auto index = static_cast<std::uint64_t>(row <= 50 ? row - 1 : row - 1 + 10);
        const QStringList fields = lines[row].split(',');
        ASSERT_EQ(fields.size(), 3);
        EXPECT_DOUBLE_EQ(fields[0].toDouble(), static_cast<double>(index) / 200.0) << row;
        for (std::size_t c = 0; c < 2; ++c)
            ASSERT_EQ(std::strtof(fields[static_cast<int>(c) + 1].toLatin1().constData(), nullptr),
                      static_cast<float>(valueAt(c, index)))
                << row;
    }
    const QJsonObject meta = parse(readFile(dir.filePath("out.meta.json"))).object();
    EXPECT_EQ(meta["session"].toObject()["subject"].toString(), "door-17");
    const QJsonObject strain = meta["channels"].toArray()[0].toObject();
    EXPECT_EQ(strain["column"].toString(), "a [strain]");
    EXPECT_EQ(strain["unit"].toString(), "");
    EXPECT_EQ(strain["kind"].toString(), "strain");
    EXPECT_TRUE(QDir(dir.path()).entryList({QStringLiteral(".out.*")}, QDir::Files | QDir::Hidden).isEmpty())
        << "a temporary was left";

    // Without its side file, as another tool passes it on, the units in
    // the header still say what each column is.
    ASSERT_TRUE(QFile::remove(dir.filePath("out.meta.json")));
    const QString elsewhere = dir.filePath("elsewhere.tactiscope");
    ASSERT_EQ(runCli({"import", csv, "--db", elsewhere, "--mode", "palpation"}).exitCode, 0);
    core::storage::SessionStore imported(elsewhere.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto channels = imported.channels(1);
    ASSERT_EQ(channels.size(), 2u);
    EXPECT_EQ(channels[0].descriptor, (core::ChannelDescriptor{"a", "", core::ChannelKind::Strain}));
    EXPECT_EQ(channels[1].descriptor, (core::ChannelDescriptor{"force", "N", core::ChannelKind::Force}));
    EXPECT_EQ(channels[0].sampleRate_hz, 200.0);
}

TEST(SessionsCli, ASessionIsNamedByItsUuidAsByItsId)
{
    // Ids differ from store to store; a uuid names the same session in all.
    QTemporaryDir dir;
    const QString db = makeStore(dir);
    std::string uuid;
    {
        core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
        uuid = store.session(1)->uuid;
    }
    const QString byId = dir.filePath("by-id.csv"), byUuid = dir.filePath("by-uuid.csv");
    ASSERT_EQ(runCli({"sessions", "--db", db, "export", "1", "--format", "csv", "--output", byId}).exitCode, 0);
    const auto result =
        runCli({"sessions", "--db", db, "export", QString::fromStdString(uuid), "--format", "csv", "--output", byUuid});
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
    EXPECT_EQ(tactiscope::testing::readBytes(byUuid), tactiscope::testing::readBytes(byId));
    const auto shown = runCli({"sessions", "--db", db, "show", QString::fromStdString(uuid), "--json"});
    ASSERT_EQ(shown.exitCode, 0);
    EXPECT_EQ(parse(shown.out).object()["session"].toObject()["subject"].toString(), QStringLiteral("phantom-2"));
    // A well-formed uuid the store does not hold is refused like an unknown id.
    EXPECT_EQ(runCli({"sessions", "--db", db, "show", "00000000-0000-4000-8000-000000000000"}).exitCode, 2);
}

// "last" is the session stored last, whatever the host's clock said (issue
// 54): after a clock set back a day, the new session begins "before" the
// old one; before, `report --session last` wrote the old one's report
// under the new one's name.
TEST(SessionsCli, LastIsTheSessionStoredLastWhateverTheClockSaid)
{
    QTemporaryDir dir;
    const QString db = makeStore(dir);
    {
        core::storage::SessionStore store(db.toStdString());
        core::storage::SessionMetadata metadata;
        metadata.mode = tactiscope::core::Mode::PanelScan;
        metadata.subject = "door-18";
        const std::string yesterday = "2026-11-20T08:00:00.000Z";
        const auto id =
            store.beginSession(metadata, std::vector<core::ChannelDescriptor>{{"a", "", core::ChannelKind::Strain}},
                               200.0, {{}, yesterday, {}});
        store.endSession(id, tactiscope::core::SessionStatus::Complete, yesterday);
        ASSERT_EQ(id, 3);
    }
    const auto shown = runCli({"sessions", "--db", db, "show", "last", "--json"});
    ASSERT_EQ(shown.exitCode, 0) << shown.err.toStdString();
    EXPECT_EQ(parse(shown.out).object()["session"].toObject()["subject"].toString(), QStringLiteral("door-18"));
}

TEST(SessionsCli, JsonExportHoldsMetadataAndColumns)
{
    QTemporaryDir dir;
    const QString db = makeStore(dir);
    const QString path = dir.filePath("out.json");
    ASSERT_EQ(runCli({"sessions", "--db", db, "export", "1", "--format", "json", "--output", path}).exitCode, 0);
    const QJsonObject all = parse(readFile(path)).object();
    EXPECT_EQ(all["session"].toObject()["mode"].toString(), "palpation");
    const QJsonObject samples = all["samples"].toObject();
    ASSERT_EQ(samples["t"].toArray().size(), 20);
    ASSERT_EQ(samples["force"].toArray().size(), 20);
    EXPECT_DOUBLE_EQ(samples["t"].toArray()[19].toDouble(), 19.0 / 200.0);
    EXPECT_EQ(static_cast<float>(samples["force"].toArray()[19].toDouble()), static_cast<float>(valueAt(1, 19)));
}

TEST(SessionsCli, DeleteRemovesTheSessionAndItsSamples)
{
    QTemporaryDir dir;
    const QString db = makeStore(dir);
    const auto result = runCli({"sessions", "--db", db, "delete", "2"});
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
    EXPECT_EQ(result.out, "Deleted session 2.\n");
    core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
    ASSERT_EQ(store.sessions().size(), 1u);
    auto chunks = store.database().prepare("SELECT count(*) FROM chunks WHERE session_id = 2");
    ASSERT_TRUE(chunks.step());
    EXPECT_EQ(chunks.int64(0), 0);  // cascaded
    auto gaps = store.database().prepare("SELECT count(*) FROM gaps");
    ASSERT_TRUE(gaps.step());
    EXPECT_EQ(gaps.int64(0), 0);
}

TEST(SessionsCli, BadInputExitsWithCodeTwo)
{
    QTemporaryDir dir;
    const QString db = makeStore(dir);
    const QString notes = dir.filePath("notes.txt");
    QFile file(notes);
    ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    file.write("not a store\n");
    file.close();
    const std::vector<std::pair<QStringList, QString>> cases{
        {{"sessions", "list"}, "--db FILE is required"},
        {{"sessions", "--db", db}, "say what to do"},
        {{"sessions", "--db", db, "rename", "1"}, "unknown action 'rename'"},
        {{"sessions", "--db", db, "show"}, "show needs one session"},
        {{"sessions", "--db", db, "show", "99"}, "there is no session '99'"},
        {{"sessions", "--db", db, "export", "1", "--output", "x.csv"}, "--format must be csv or json"},
        {{"sessions", "--db", db, "export", "1", "--format", "csv"}, "--output PATH is required"},
        {{"sessions", "--db", dir.filePath("missing.tactiscope"), "list"}, "does not exist"},
        {{"sessions", "--db", notes, "list"}, "is not a Tactiscope session store"},
    };
    for (const auto& [arguments, message] : cases) {
        const auto result = runCli(arguments);
        EXPECT_EQ(result.exitCode, 2) << arguments.join(' ').toStdString();
        EXPECT_TRUE(result.err.contains(message))
            << arguments.join(' ').toStdString() << ": " << result.err.toStdString();
    }
}

// A newline in a subject faked a row of its own in the plain list (and a
// line of its own in show); stored text now stays on its line, escaped.
TEST(SessionsCli, ANewlineInASubjectFakesNoRow)
{
    QTemporaryDir dir;
    const QString path = dir.filePath("s.tactiscope");
    {
        core::storage::SessionStore store(path.toStdString());
        const std::vector<core::ChannelDescriptor> channels{{"a", "", core::ChannelKind::Strain},
                                                            {"force", "N", core::ChannelKind::Force}};
        core::storage::SessionMetadata m;
        m.subject = "door-17\n    99  2026-01-01T00:00:00Z  panel-scan complete 1.0 s  forged / Eve";
        const auto id = store.beginSession(m, channels, 200.0);
        store.appendBlocks(id, std::vector{block(0, 20)});
        store.endSession(id, tactiscope::core::SessionStatus::Complete);
    }
    const auto list = runCli({"sessions", "--db", path, "list"});
    ASSERT_EQ(list.exitCode, 0) << list.err.toStdString();
    EXPECT_EQ(list.out.split('\n', Qt::SkipEmptyParts).size(), 2) << list.out.toStdString();  // the header, one row
    EXPECT_TRUE(list.out.contains(QStringLiteral("door-17\\n    99"))) << list.out.toStdString();
    const auto show = runCli({"sessions", "--db", path, "show", "1"});
    EXPECT_FALSE(show.out.contains(QStringLiteral("\n    99"))) << show.out.toStdString();
}

// A session of 3 000 channels: export and report read each chunk once per
// window, not once per channel. Before, 2 500 columns took 11 s to export
// as CSV, 10 000 took minutes as JSON, and a report of 2 500 took 37 s and
// 7.4 GB (its plot had a lane per channel). No time is asserted: the
// quadratic forms would make this test run for minutes.
TEST(SessionsCli, AWideSessionExportsWholeAndReportsAPageOfLanes)
{
    QTemporaryDir dir;
    constexpr int kChannels = 3000, kRows = 100;
    QString text = QStringLiteral("t [s]");
    for (int c = 0; c < kChannels; ++c) text += QStringLiteral(",c%1 [N]").arg(c);
    text += '\n';
    for (int r = 0; r < kRows; ++r) {
        text += QString::number(r / 100.0, 'g', 17);
        for (int c = 0; c < kChannels; ++c) text += ',' + QString::number((r * 7 + c) % 101);
        text += '\n';
    }
    const QString csv = dir.filePath("wide.csv"), db = dir.filePath("wide.tactiscope");
    tactiscope::testing::writeText(csv, text);
    ASSERT_EQ(runCli({"import", csv, "--db", db}).exitCode, 0);

    const QString out = dir.filePath("out.csv");
    ASSERT_EQ(runCli({"sessions", "--db", db, "export", "1", "--format", "csv", "--output", out}).exitCode, 0);
    const QStringList rows = readFile(out).split('\n', Qt::SkipEmptyParts);
    ASSERT_EQ(rows.size(), 1 + kRows);
    const QStringList last = rows.back().split(',');
    ASSERT_EQ(last.size(), 1 + kChannels);
    EXPECT_EQ(last[1 + 2999].toInt(), (99 * 7 + 2999) % 101);

    const QString json = dir.filePath("out.json");
    ASSERT_EQ(runCli({"sessions", "--db", db, "export", "1", "--format", "json", "--output", json}).exitCode, 0);
    const QJsonObject samples = parse(readFile(json)).object()["samples"].toObject();
    ASSERT_EQ(samples.size(), 1 + kChannels);
    EXPECT_EQ(samples["c2999"].toArray()[99].toInt(), (99 * 7 + 2999) % 101);
    EXPECT_DOUBLE_EQ(samples["t"].toArray()[99].toDouble(), 0.99);

    // A page of lanes, the rest summarised (it was a lane per channel).
    const auto report = runCli({"report", "--db", db, "--session", "1", "--output", dir.filePath("r.pdf")});
    EXPECT_EQ(report.exitCode, 0) << report.err.toStdString();
    EXPECT_TRUE(report.out.contains(QStringLiteral("(4 pages)"))) << report.out.toStdString();
}
