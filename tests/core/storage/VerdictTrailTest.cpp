// A session's verdict trail through a real store: every decision kept in
// order with who, when, why and on what grounds; the last one is the
// session's verdict (listing and filtering read it); a version-2 store keeps
// its verdicts, without a trail, when migrated; the trail reads in words.
#include "core/report/VerdictTrail.h"
#include "core/storage/AutomaticVerdict.h"
#include "core/storage/Schema.h"
#include "core/storage/SessionStore.h"

#include "support/TempDirectory.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

using namespace tactiscope::core;
using namespace tactiscope::core::storage;

namespace {

using VerdictTrailTest = tactiscope::testing::TempDirectoryTest;

std::int64_t panel(SessionStore& store)
{
    SessionMetadata metadata;
    metadata.mode = Mode::PanelScan;
    metadata.operatorName = "Ada";
    const std::vector<ChannelDescriptor> channels{{"a", "", ChannelKind::Strain}, {"b", "", ChannelKind::Strain}};
    const auto id = store.beginSession(metadata, channels, 500.0);
    store.endSession(id, SessionStatus::Complete);
    return id;
}

}  // namespace

TEST_F(VerdictTrailTest, EveryDecisionIsKeptInOrderAndTheLastIsTheVerdict)
{
    SessionStore store(file("t.tactiscope"));
    const auto id = panel(store);
    detector::DetectorParameters parameters;
    parameters.threshold = 0.8;
    store.decideVerdict(id, automaticDecision("live", 21, 3, parameters));
    store.decideVerdict(id,
                        {0, VerdictRole::Operator, Verdict::DefectsFound, "Ada", "2026-11-23T14:13:02.000Z", "", ""});
    store.decideVerdict(id, {0, VerdictRole::Reviewer, Verdict::Pass, "Q. Engineer", "2026-11-24T16:02:40.000Z",
                             "bump is a marker pen line", ""});

    EXPECT_EQ(store.session(id)->verdict, Verdict::Pass);
    SessionFilter passed;
    passed.verdict = Verdict::Pass;
    EXPECT_EQ(store.sessions(passed).size(), 1u);
    const auto trail = store.verdicts(id);
    ASSERT_EQ(trail.size(), 3u);
    EXPECT_EQ(trail[0].role, VerdictRole::Automatic);
    EXPECT_EQ(trail[0].verdict, Verdict::DefectsFound);  // 3 sites
    EXPECT_FALSE(trail[0].decidedUtc.empty());           // the store's clock
    const auto basis = nlohmann::json::parse(trail[0].basisJson);
    EXPECT_EQ(basis["analysis"], "live");
    EXPECT_EQ(basis["defects"], 21);
    EXPECT_EQ(basis["sites"], 3);
    EXPECT_EQ(basis["threshold"], 0.8);
    EXPECT_EQ(trail[1].decidedBy, "Ada");
    EXPECT_EQ(trail[2].note, "bump is a marker pen line");
    EXPECT_EQ(trail[2].decidedUtc, "2026-11-24T16:02:40.000Z");

    const auto lines = report::verdictTrailLines(trail);
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(lines[0].rfind("automatic: defects found (live detector: 21 defects at 3 sites, threshold 0.8), ", 0), 0u)
        << lines[0];
    EXPECT_EQ(lines[1].rfind("operator Ada kept it, ", 0), 0u) << lines[1];
    EXPECT_EQ(lines[2], "reviewer Q. Engineer changed it to pass, 2026-11-24 16:02 UTC: \"bump is a marker pen line\"");

    store.deleteSession(id);
    auto left = store.database().prepare("SELECT count(*) FROM verdicts");
    ASSERT_TRUE(left.step());
    EXPECT_EQ(left.int64(0), 0);
}

TEST_F(VerdictTrailTest, NoDefectPassesAndAnOperatorWithoutANameIsSaidToBeUnnamed)
{
    SessionStore store(file("t.tactiscope"));
    const auto id = panel(store);
    store.decideVerdict(id, automaticDecision("live", 0, 0, {}));
    store.decideVerdict(id, {0, VerdictRole::Operator, Verdict::DefectsFound, "", "", "dent seen by eye", ""});
    const auto lines = report::verdictTrailLines(store.verdicts(id));
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0].rfind("automatic: pass (live detector: 0 defects, threshold 0.85), ", 0), 0u) << lines[0];
    EXPECT_EQ(lines[1].rfind("operator (unnamed) changed it to defects found, ", 0), 0u) << lines[1];
    EXPECT_THROW(store.decideVerdict(id + 1, {}), StorageError);  // no such session: nothing stored
    EXPECT_EQ(store.verdicts(id + 1).size(), 0u);
}

TEST_F(VerdictTrailTest, AVersion2StoreKeepsItsVerdictsWithoutATrail)
{
    const std::string path = file("v2.tactiscope");
    {
        Database db(path, Database::Access::ReadWrite);
        ASSERT_EQ(prepareSchema(db, 2), 0);
        db.exec("INSERT INTO sessions (id, uuid, mode, started_utc, status, verdict, app_version) "
                "VALUES (1, 'u', 'panel-scan', '2026-01-01T00:00:00.000Z', 'complete', 'defects found', '0.1')");
    }
    SessionStore store(path);
    EXPECT_EQ(store.session(1)->verdict, Verdict::DefectsFound);
    EXPECT_TRUE(store.verdicts(1).empty());
    store.decideVerdict(1, {0, VerdictRole::Reviewer, Verdict::Pass, "Q. Engineer", "", "", ""});
    EXPECT_EQ(report::verdictTrailLines(store.verdicts(1)).front().rfind("reviewer Q. Engineer decided: pass", 0), 0u);
}

// Issue 52: a session of several devices takes its parts' worst verdict,
// naming the part that decided; a judging part without a verdict (too
// short, cut short) leaves it unjudged unless another found defects; parts
// that judge nothing (a load cell) give none.
TEST(PartsVerdict, TheWorstPartDecidesAndAnUnjudgedPartLeavesAPassOpen)
{
    const auto part = [](std::int64_t id, const char* name, Mode mode, std::optional<Verdict> verdict) {
        SessionSummary s;
        s.id = id;
        s.metadata.mode = mode;
        s.metadata.deviceName = name;
        s.verdict = verdict;
        return s;
    };
    const std::vector<SessionSummary> found{part(2, "left", Mode::PanelScan, Verdict::Pass),
                                            part(3, "right", Mode::PanelScan, Verdict::DefectsFound),
                                            part(4, "cell", Mode::General, std::nullopt)};
    const auto decision = partsDecision(found);
    ASSERT_TRUE(decision);
    EXPECT_EQ(decision->verdict, Verdict::DefectsFound);
    EXPECT_EQ(decision->role, VerdictRole::Automatic);
    const auto basis = nlohmann::json::parse(decision->basisJson);
    EXPECT_EQ(basis["decided_by_part"], "right");
    EXPECT_EQ(basis["part_session"], 3);
    EXPECT_EQ(basis["parts"].size(), 2u);
    // Said as its parts' verdicts, not as a detector that found nothing.
    const std::vector<VerdictDecision> trail{*decision};
    EXPECT_EQ(report::verdictTrailLines(trail).front().rfind(
                  "automatic: defects found (the worst of its parts': left pass, right defects found), ", 0),
              0u)
        << report::verdictTrailLines(trail).front();

    const std::vector<SessionSummary> passing{part(2, "left", Mode::PanelScan, Verdict::Pass),
                                              part(4, "cell", Mode::General, std::nullopt)};
    ASSERT_TRUE(partsDecision(passing));
    EXPECT_EQ(partsDecision(passing)->verdict, Verdict::Pass);

    const std::vector<SessionSummary> unjudged{part(2, "left", Mode::PanelScan, Verdict::Pass),
                                               part(3, "right", Mode::PanelScan, std::nullopt)};
    EXPECT_FALSE(partsDecision(unjudged));
    std::vector<SessionSummary> saidWhy = unjudged;
    saidWhy[1].unjudged = "too short to judge (0.3 s of the 0.6 s the detector needs)";
    EXPECT_EQ(partsUnjudged(saidWhy), "right: too short to judge (0.3 s of the 0.6 s the detector needs)");
    EXPECT_EQ(partsUnjudged(found), "");
    const std::vector<SessionSummary> nothingJudges{part(4, "cell", Mode::General, std::nullopt),
                                                    part(5, "beam", Mode::Capacitive, std::nullopt)};
    EXPECT_FALSE(partsDecision(nothingJudges));
    // A part that judges nothing but went past a critical limit (fresh
    // eyes: a beam overloaded beside a passing panel gave "pass"): the
    // session's readings are not all true, so no pass, and it says why.
    std::vector<SessionSummary> overloaded = passing;
    overloaded[1].unjudged = "not judged: it went past a critical limit";
    EXPECT_FALSE(partsDecision(overloaded));
    EXPECT_EQ(partsUnjudged(overloaded), "cell: not judged: it went past a critical limit");
    overloaded[0].verdict = Verdict::DefectsFound;  // defects found stand whatever else is true
    ASSERT_TRUE(partsDecision(overloaded));
    EXPECT_EQ(partsDecision(overloaded)->verdict, Verdict::DefectsFound);
}
