// Triggered recordings (issue 39): the condition's words, and the machine on
// streams with known crossings. A 100 Hz stream makes the counts easy to
// check by hand: 0.5 s is 50 samples.
#include "core/trigger/TriggerMachine.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

using namespace tactiscope::core::trigger;

namespace {

// Pushes `values` from index 0 on; the spans started and ended, in order.
struct Cut {
    std::vector<TriggeredSpan> started, ended;
};

Cut run(TriggerMachine& machine, const std::vector<double>& values, std::uint64_t first = 0)
{
    Cut cut;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const auto step = machine.push(first + i, values[i]);
        if (step.started) cut.started.push_back(*step.started);
        if (step.ended) cut.ended.push_back(*step.ended);
    }
    return cut;
}

// 0 everywhere except 1 on [from, to).
std::vector<double> pulse(std::size_t n, std::size_t from, std::size_t to)
{
    std::vector<double> v(n, 0.0);
    for (std::size_t i = from; i < to; ++i) v[i] = 1.0;
    return v;
}

TriggerSettings settings(const char* text, double pre, double post, double holdOff = 0.0,
                         std::optional<unsigned> sessions = std::nullopt)
{
    return {*parseTrigger(text).condition, pre, post, holdOff, sessions};
}

}  // namespace

TEST(TriggerCondition, ReadsEveryFormAndSaysWhyNot)
{
    auto c = parseTrigger("a>20e-6").condition;
    ASSERT_TRUE(c);
    EXPECT_EQ(c->quantity, "a");
    EXPECT_EQ(c->kind, TriggerKind::Above);
    EXPECT_EQ(c->level, 20e-6);
    EXPECT_EQ(parseTrigger(" force < 0.001 ").condition->kind, TriggerKind::Below);
    EXPECT_EQ(parseTrigger("a rising -1.5").condition->level, -1.5);
    EXPECT_EQ(parseTrigger("a falling 0").condition->kind, TriggerKind::Falling);
    c = parseTrigger("force inside 0.001..0.002").condition;
    ASSERT_TRUE(c);
    EXPECT_EQ(c->level, 0.001);
    EXPECT_EQ(c->high, 0.002);
    EXPECT_EQ(parseTrigger("force outside -1e-5..1e-5").condition->kind, TriggerKind::Outside);
    EXPECT_EQ(parseTrigger("force inside 0.001..0.002").condition->text(), "force inside 0.001..0.002");
    EXPECT_EQ(parseTrigger("a>2e-05").condition->text(), "a>2e-05");
    for (const char* bad : {"", "a", ">1", "a>", "a>x", "a>nan", "a>inf", "a rising", "a sideways 1", "a inside 2..1",
                            "a inside 1", "a outside 1..x"}) {
        const auto parsed = parseTrigger(bad);
        EXPECT_FALSE(parsed.condition) << bad;
        EXPECT_FALSE(parsed.error.empty()) << bad;
    }
}

TEST(TriggerMachine, ALevelCutsFromPreBeforeItToPostAfterItClears)
{
    // 100 Hz: the level holds on samples 300…349; pre 0.5 s = 50 samples, post 1 s = 100.
    TriggerMachine machine(settings("a>0.5", 0.5, 1.0), 100.0);
    const Cut cut = run(machine, pulse(1000, 300, 350));
    ASSERT_EQ(cut.started.size(), 1U);
    ASSERT_EQ(cut.ended.size(), 1U);
    EXPECT_EQ(cut.ended[0].trigger, 300U);  // the trigger instant: the first sample that holds
    EXPECT_EQ(cut.ended[0].first, 250U);    // exactly 50 before
    EXPECT_EQ(cut.ended[0].end, 450U);      // cleared at 350, then exactly 100 more
    EXPECT_EQ(machine.state(), TriggerState::Armed);
}

TEST(TriggerMachine, AnEdgeCountsItsPostFromTheEdgeAndALevelHighAtTheStartIsNoTrigger)
{
    // High from the first sample to 99: not armed until it falls, so the rise at 200 triggers.
    std::vector<double> v = pulse(600, 0, 100);
    for (std::size_t i = 200; i < 600; ++i) v[i] = 1.0;
    TriggerMachine level(settings("a>0.5", 0.0, 0.0), 100.0);
    const Cut levelCut = run(level, v);
    ASSERT_EQ(levelCut.started.size(), 1U);
    EXPECT_EQ(levelCut.started[0].trigger, 200U);
    EXPECT_TRUE(levelCut.ended.empty());  // it still holds at the end

    TriggerMachine edge(settings("a rising 0.5", 0.1, 0.2), 100.0);
    const Cut edgeCut = run(edge, v);
    ASSERT_EQ(edgeCut.ended.size(), 1U);  // the first sample has no sample before it: no edge
    EXPECT_EQ(edgeCut.ended[0].trigger, 200U);
    EXPECT_EQ(edgeCut.ended[0].first, 190U);
    EXPECT_EQ(edgeCut.ended[0].end, 221U);  // the edge's sample, then 20 more
}

TEST(TriggerMachine, HoldOffAndTheSessionCountAreHonouredAndSessionsNeverOverlap)
{
    // Pulses every 100 samples, 10 long; post 0.2 s (20), hold-off 0.5 s (50), 3 sessions.
    std::vector<double> v(1200, 0.0);
    for (std::size_t p = 100; p < 1200; p += 100)
        for (std::size_t i = p; i < p + 10; ++i) v[i] = 1.0;
    TriggerMachine machine(settings("a>0.5", 0.6, 0.2, 0.5, 3), 100.0);
    const Cut cut = run(machine, v);
    ASSERT_EQ(cut.ended.size(), 3U);
    // 1st: trigger 100, end 130; hold-off to 180: the pulse at 200 is the 2nd (ends 230, re-arms
    // at 280), the pulse at 300 the 3rd.
    EXPECT_EQ(cut.ended[0].trigger, 100U);
    EXPECT_EQ(cut.ended[0].first, 40U);
    EXPECT_EQ(cut.ended[0].end, 130U);
    EXPECT_EQ(cut.ended[1].trigger, 200U);
    EXPECT_EQ(cut.ended[1].first, 140U);
    EXPECT_EQ(cut.ended[2].trigger, 300U);
    EXPECT_EQ(cut.ended[2].first, 240U);
    EXPECT_EQ(machine.state(), TriggerState::Finished);
    // A pre time longer than the gap: a session starts where the one before ended.
    TriggerMachine close(settings("a>0.5", 2.0, 0.0, 0.0, 2), 100.0);
    const Cut closeCut = run(close, v);
    ASSERT_EQ(closeCut.ended.size(), 2U);
    EXPECT_EQ(closeCut.ended[0].first, 0U);  // the stream's start: nothing before it to keep
    EXPECT_EQ(closeCut.ended[1].first, closeCut.ended[0].end);
}

TEST(TriggerMachine, WindowsAndNoValues)
{
    TriggerMachine inside(settings("x inside 2..3", 0.0, 0.0), 100.0);
    const Cut in = run(inside, {0, 1, 2, 2.5, 3, 4, 5});
    ASSERT_EQ(in.ended.size(), 1U);
    EXPECT_EQ(in.ended[0].trigger, 2U);  // 2 is inside (ends included)
    EXPECT_EQ(in.ended[0].end, 5U);      // 4 is outside: the session is 2, 2.5, 3
    TriggerMachine outside(settings("x outside -1..1", 0.0, 0.0), 100.0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const Cut out = run(outside, {0, nan, 0.5, 1.5, 0});
    ASSERT_EQ(out.ended.size(), 1U);
    EXPECT_EQ(out.ended[0].trigger, 3U);  // a lost sample (NaN) triggers nothing
    EXPECT_EQ(out.ended[0].end, 4U);
    // Before any value (a force before its zero) the machine waits for a
    // first one, which its status says; it judged nothing yet.
    TriggerMachine unknown(settings("force>0.5", 0.0, 0.0), 100.0);
    run(unknown, {nan, nan});
    EXPECT_FALSE(unknown.valueSeen());
    EXPECT_EQ(unknown.state(), TriggerState::Waiting);
    run(unknown, {0.0}, 2);
    EXPECT_TRUE(unknown.valueSeen());
    EXPECT_EQ(unknown.state(), TriggerState::Armed);
    EXPECT_THROW(TriggerMachine(settings("x>1", -1.0, 0.0), 100.0), std::invalid_argument);
    EXPECT_THROW(TriggerMachine(settings("x>1", 0.0, 0.0, 0.0, 0), 100.0), std::invalid_argument);
}

TEST(TriggerMachine, SubjectsAreNumberedOnFromTheFirstOnes)
{
    using tactiscope::core::trigger::numberedSubject;
    EXPECT_EQ(numberedSubject("door-17", 0), "door-17");
    EXPECT_EQ(numberedSubject("door-17", 1), "door-18");
    EXPECT_EQ(numberedSubject("door-17", 5), "door-22");
    EXPECT_EQ(numberedSubject("panel-009", 1), "panel-010");
    EXPECT_EQ(numberedSubject("panel-099", 1), "panel-100");
    EXPECT_EQ(numberedSubject("panel", 0), "panel");
    EXPECT_EQ(numberedSubject("panel", 1), "panel-2");
    EXPECT_EQ(numberedSubject("panel", 2), "panel-3");
    EXPECT_EQ(numberedSubject("", 3), "");
    EXPECT_EQ(numberedSubject("42", 1), "43");
    // A run of digits too long to count is part of a name.
    EXPECT_EQ(numberedSubject("lot-1234567890123456789012", 1), "lot-1234567890123456789012-2");
}

TEST(TriggerMachine, TheSettingsReadAsTheRecordKeepsThem)
{
    using namespace tactiscope::core::trigger;
    TriggerSettings settings;
    settings.condition = *parseTrigger("a>20e-6").condition;
    settings.pre_s = 0.5;
    settings.post_s = 1.0;
    EXPECT_EQ(settingsText(settings), "a>2e-05, pre 0.5 s, post 1 s, hold-off 0 s");
}
