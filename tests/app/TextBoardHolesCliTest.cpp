// A value a board prints that is no number ("nan", "inf", "ovf", one
// beyond what a stored sample holds) is a hole in its channel alone
// (issue 53): the other channels' values at that line are kept, the store
// holds NaN there, `record` says how many, and the mode's live detector
// goes on after it (a NaN carried through its filters would blind it for
// the rest of the session). Real pseudo-terminals, a board printing the
// simulator's panel-scan stroke.
#include "core/SampleBlock.h"
#include "core/storage/SessionStore.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"
#include "support/TextBoard.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

using tactiscope::testing::runCli;
using tactiscope::testing::sessionIdIn;
using tactiscope::testing::TextBoard;
namespace storage = tactiscope::core::storage;

namespace {

constexpr double kRate_hz = 500.0;
constexpr std::uint64_t kEvery = 400;  // a line in so many has a hole in b

// What line n's b says instead of a number, in turn.
const char* holeIn(std::uint64_t n)
{
    static const char* const spellings[] = {"nan", "inf", "-inf", "ovf", "NaN", "1e39"};
    return spellings[(n / kEvery) % std::size(spellings)];
}

}  // namespace

TEST(TextBoardHolesCli, AValueThatIsNoNumberIsAHoleInItsChannelAloneAndTheDetectorGoesOn)
{
    // The panel-scan stroke: a dent crossed four times each way in 8 s.
    constexpr std::size_t kSamples = 60 * 500;
    auto scenario = tactiscope::devices::simulator::makeScenario("panel-scan", 5, kRate_hz);
    auto stroke = std::make_shared<tactiscope::core::SampleBlock>(2, kSamples, 0.0, 1.0 / kRate_hz);
    scenario->generate(*stroke);
    QTemporaryDir dir;
    const std::string link = dir.filePath(QStringLiteral("board")).toStdString();
    TextBoard board(link, {kRate_hz, [stroke](std::uint64_t n) {
                               char line[96];
                               const std::size_t s = n % kSamples;
                               std::snprintf(line, sizeof line, "a[strain]:%.17g b[strain]:%.17g n:%llu\n",
                                             stroke->value(0, s), stroke->value(1, s),
                                             static_cast<unsigned long long>(n));
                               std::string text = line;
                               if (n % kEvery == 0) {
                                   const auto b = text.find(" b[strain]:") + 11;
                                   text.replace(b, text.find(' ', b) - b, holeIn(n));
                               }
                               return text;
                           }});
    ASSERT_TRUE(board.ok());
    const QString db = dir.filePath(QStringLiteral("holes.tactiscope"));
    const auto result = runCli({"record", "--port", QString::fromStdString(link), "--protocol", "text", "--rate",
                                QString::number(kRate_hz), "--seconds", "8", "--mode", "panel-scan", "--roles",
                                "a=cantilever-a,b=cantilever-b", "--db", db});
    ASSERT_EQ(result.exitCode, 0) << result.err.toStdString();
    const auto id = sessionIdIn(result.out);
    ASSERT_GT(id, 0) << result.out.toStdString();

    // Each value where the board printed it: a always, b but at the holes.
    storage::SessionStore store(db.toStdString(), storage::Database::Access::ReadOnly);
    const std::uint64_t count = store.sampleCount(id);
    const auto a = store.readChannel(id, 0, 0, count);
    const auto b = store.readChannel(id, 1, 0, count);
    const auto n = store.readChannel(id, 2, 0, count);
    std::uint64_t holes = 0;
    for (std::uint64_t i = 0; i < count; ++i) {
        ASSERT_TRUE(std::isfinite(n[i])) << i;
        const auto line = static_cast<std::uint64_t>(std::llround(n[i]));
        const std::size_t s = line % kSamples;
        ASSERT_EQ(a[i], static_cast<double>(static_cast<float>(stroke->value(0, s)))) << line;
        if (line % kEvery == 0) {
            EXPECT_TRUE(std::isnan(b[i])) << line << ": " << holeIn(line);
            ++holes;
        } else {
            ASSERT_EQ(b[i], static_cast<double>(static_cast<float>(stroke->value(1, s)))) << line;
        }
    }
    EXPECT_GE(holes, 8u);
    EXPECT_TRUE(result.err.contains(
        QStringLiteral(
            "values that were no number (nan, inf) or not printed are stored as holes in their channel alone: %1 in b")
            .arg(holes)))
        << result.err.toStdString();

    // The detector found the dent at each crossing after the holes too:
    // the stroke crosses it every second, a hole comes every 0.8 s.
    const auto show = runCli({"sessions", "--db", db, "show", "last", "--json"});
    ASSERT_EQ(show.exitCode, 0) << show.err.toStdString();
    const QJsonArray events = QJsonDocument::fromJson(show.out.toUtf8()).object()["events"].toArray();
    EXPECT_GE(events.size(), 6) << show.out.toStdString();
    EXPECT_GT(events.last().toObject()["start_s"].toDouble(), 6.0) << show.out.toStdString();
}
