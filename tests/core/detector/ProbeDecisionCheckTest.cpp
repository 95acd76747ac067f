// A probe's own decisions beside the workstation's (issue 38): nothing is
// compared in the warm-up after a (re)start, agreement is counted sample by
// sample, a disagreement of three samples or more is named once at its
// first sample, shorter ones (a decision a hair from θ) are not, and a
// garbled decision counts as none. Expected counts worked out by hand.
#include "core/detector/ProbeDecisionCheck.h"

#include "core/SampleBlock.h"

#include <gtest/gtest.h>

using namespace tactiscope::core;
using namespace tactiscope::core::detector;

namespace {

constexpr double kDt = 0.002;  // 500 Hz: the warm-up is 2000 samples

// A stream of probe decisions (channels a, b, out, rab, rba) from index `first` on.
SampleBlock probeBlock(const std::vector<int>& decisions, std::uint64_t first)
{
    SampleBlock block(5, decisions.size(), static_cast<double>(first) * kDt, kDt, first);
    for (std::size_t s = 0; s < decisions.size(); ++s) {
        block.channel(2)[s] = decisions[s];
        block.channel(3)[s] = decisions[s] > 0 ? 0.9 : 0.1;
        block.channel(4)[s] = decisions[s] < 0 ? 0.9 : 0.1;
    }
    return block;
}

struct Results {
    std::vector<DefectEvent> probeEvents;
    std::vector<ProbeDisagreement> disagreements;
};

void feed(ProbeDecisionCheck& check, const std::vector<int>& probe, const std::vector<int>& workstation,
          std::uint64_t first, Results& run)
{
    const SampleBlock block = probeBlock(probe, first);
    for (std::size_t s = 0; s < probe.size(); ++s) {
        DetectorOutput ws;
        ws.decision = static_cast<std::int8_t>(workstation[s]);
        check.push(block, s, ws, run.probeEvents, run.disagreements);
    }
}

}  // namespace

TEST(ProbeDecisionCheck, FindsTheProbesChannelsByKindAndName)
{
    std::vector<ChannelDescriptor> channels{{"a", "", ChannelKind::Strain},
                                            {"b", "", ChannelKind::Strain},
                                            {"out", "", ChannelKind::Decision},
                                            {"rab", "", ChannelKind::Decision},
                                            {"rba", "", ChannelKind::Decision}};
    const auto found = probeDecisionChannels(channels);
    ASSERT_TRUE(found);
    EXPECT_EQ(found->out, 2U);
    EXPECT_EQ(found->rab, 3U);
    EXPECT_EQ(found->rba, 4U);
    channels[2].kind = ChannelKind::Other;  // a channel merely called "out" is no decision
    EXPECT_FALSE(probeDecisionChannels(channels));
}

TEST(ProbeDecisionCheck, CountsAfterTheWarmUpAndNamesOnlyLastingDisagreements)
{
    ProbeDecisionCheck check({2, 3, 4, std::nullopt, std::nullopt}, kDt, 0.02, std::nullopt);
    Results run;
    // 2000 samples of warm-up in which the two disagree throughout: nothing counted, nothing named.
    feed(check, std::vector<int>(2000, 1), std::vector<int>(2000, 0), 0, run);
    EXPECT_EQ(check.agreement().compared, 0U);
    EXPECT_TRUE(run.disagreements.empty());
    // Then 100 samples: agreement except a 2-sample tip at 10–11 (a near tie, not named)
    // and a 5-sample run at 50–54 where the probe says nothing: named once, at 50.
    std::vector<int> probe(100, 0), workstation(100, 0);
    probe[10] = probe[11] = 1;
    for (int s = 50; s < 55; ++s) workstation[static_cast<std::size_t>(s)] = -1;
    feed(check, probe, workstation, 2000, run);
    EXPECT_EQ(check.agreement().compared, 100U);
    EXPECT_EQ(check.agreement().agreeing, 93U);  // 100 − 2 − 5
    ASSERT_EQ(run.disagreements.size(), 1U);
    EXPECT_NEAR(run.disagreements[0].start_s, 2050 * kDt, 1e-12);
    EXPECT_EQ(run.disagreements[0].probe, 0);
    EXPECT_EQ(run.disagreements[0].workstation, -1);
    EXPECT_NE(run.disagreements[0].text().find("the probe says no defect, the workstation B then A"),
              std::string::npos);
}

TEST(ProbeDecisionCheck, ARestartWarmsUpAgainAndAGarbledDecisionIsNone)
{
    ProbeDecisionCheck check({2, 3, 4, std::nullopt, std::nullopt}, kDt, 0.02, std::nullopt);
    Results run;
    feed(check, std::vector<int>(2100, 0), std::vector<int>(2100, 0), 0, run);
    EXPECT_EQ(check.agreement().compared, 100U);
    check.restart(run.probeEvents);  // lost samples: the workstation starts from silence
    feed(check, std::vector<int>(1999, 1), std::vector<int>(1999, 0), 2200, run);
    EXPECT_EQ(check.agreement().compared, 100U);  // still warming up
    // A value that is no decision (7) counts as none, so it agrees with the workstation's 0.
    feed(check, {0, 7}, {0, 0}, 4199, run);
    EXPECT_EQ(check.agreement().compared, 101U);
    EXPECT_EQ(check.agreement().agreeing, 101U);
    EXPECT_TRUE(run.disagreements.empty());
}

TEST(ProbeDecisionCheck, TheProbesLagsGiveItsEventsTheirLag)
{
    // out, rab, rba, lag_ab, lag_ba after the strains: lag_ab 0.05 s is 25 samples.
    std::vector<ChannelDescriptor> channels{{"a", "", ChannelKind::Strain}, {"b", "", ChannelKind::Strain}};
    for (const char* name : {"out", "rab", "rba"}) channels.push_back({name, "", ChannelKind::Decision});
    for (const char* name : {"lag_ab", "lag_ba"}) channels.push_back({name, "s", ChannelKind::Decision});
    const auto found = probeDecisionChannels(channels);
    ASSERT_TRUE(found && found->lagAb && found->lagBa);
    ProbeDecisionCheck check(*found, kDt, 0.02, 0.015);
    SampleBlock block(7, 200, 0.0, kDt, 0);
    for (std::size_t s = 100; s < 106; ++s) {
        block.channel(2)[s] = 1;
        block.channel(3)[s] = 0.9;
        block.channel(5)[s] = 0.05;
    }
    Results run;
    for (std::size_t s = 0; s < 200; ++s) check.push(block, s, DetectorOutput{}, run.probeEvents, run.disagreements);
    check.finish(run.probeEvents);
    ASSERT_EQ(run.probeEvents.size(), 1U);
    EXPECT_NEAR(run.probeEvents[0].peakLag_s, 0.05, 1e-12);
    ASSERT_TRUE(run.probeEvents[0].speed_m_per_s);
    EXPECT_NEAR(*run.probeEvents[0].speed_m_per_s, 0.3, 1e-12);  // 15 mm in 50 ms
}

TEST(ProbeDecisionCheck, SegmentsTheProbesDecisionsIntoEvents)
{
    ProbeDecisionCheck check({2, 3, 4, std::nullopt, std::nullopt}, kDt, 0.02, std::nullopt);
    Results run;
    std::vector<int> probe(200, 0);
    for (int s = 100; s < 106; ++s) probe[static_cast<std::size_t>(s)] = 1;
    feed(check, probe, probe, 0, run);
    check.finish(run.probeEvents);
    ASSERT_EQ(run.probeEvents.size(), 1U);
    EXPECT_EQ(run.probeEvents[0].direction, 1);
    EXPECT_NEAR(run.probeEvents[0].start_s, 100 * kDt, 1e-12);
    EXPECT_NEAR(run.probeEvents[0].peakR, 0.9, 1e-12);
}
