// Limit alarms (issue 39): the limit's words, a hold time that must pass
// beyond a level before its alarm, and a hysteresis that keeps noise at the
// level from chattering, and a clear time (0.1 s) it must stay back for.
// 100 Hz streams: 0.1 s is 10 samples.
#include "core/trigger/LimitWatch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

using namespace tactiscope::core::trigger;

namespace {

std::vector<LimitChange> run(LimitWatch& watch, const std::vector<double>& values)
{
    std::vector<LimitChange> changes;
    for (std::size_t i = 0; i < values.size(); ++i) watch.push(i, values[i], changes);
    return changes;
}

LimitSpec spec(const char* text, double hold_s = 0.0)
{
    LimitSpec s = *parseLimit(text).limit;
    s.hold_s = hold_s;
    return s;
}

}  // namespace

TEST(LimitWatch, ReadsTheLimitsWordsAndSaysWhyNot)
{
    const auto l = parseLimit("force>warning:0.002,critical:0.003").limit;
    ASSERT_TRUE(l);
    EXPECT_EQ(l->quantity, "force");
    EXPECT_EQ(l->side, LimitSide::Above);
    EXPECT_EQ(l->warning, 0.002);
    EXPECT_EQ(l->critical, 0.003);
    EXPECT_EQ(l->text(), "force>warning:0.002,critical:0.003");
    EXPECT_EQ(parseLimit("a<critical:-1e-3").limit->side, LimitSide::Below);
    EXPECT_EQ(parseLimit("a<critical:-1e-3").limit->warning, std::nullopt);
    // A hold time in the same words, and back.
    const auto held = parseLimit("force>critical:0.003,hold:0.2").limit;
    ASSERT_TRUE(held);
    EXPECT_EQ(held->hold_s, 0.2);
    EXPECT_EQ(held->text(), "force>critical:0.003,hold:0.2");
    for (const char* bad :
         {"", "force", ">warning:1", "force>", "force>warning", "force>warning:x", "force>alarm:1",
          "force>warning:3,critical:2", "a<warning:-2,critical:-1", "force>warning:1,hold:-1", "force>hold:1"}) {
        const auto parsed = parseLimit(bad);
        EXPECT_FALSE(parsed.limit) << bad;
        EXPECT_FALSE(parsed.error.empty()) << bad;
    }
}

TEST(LimitWatch, NoiseAtTheLevelRaisesOnceAndClearsOnlyPastTheHysteresis)
{
    // A level of 1 (hysteresis 2 %, 0.02): the value crosses to 1.005 and then
    // wanders ±0.015 around 1 for 200 samples (inside the band): one alarm, no
    // clear; then it drops to 0.97, past the band, at 251: cleared 0.1 s later.
    LimitWatch watch(spec("x>warning:1"), 100.0);
    std::vector<double> v(50, 0.5);
    v.push_back(1.005);
    for (int i = 0; i < 200; ++i) v.push_back(1.0 + 0.015 * std::sin(0.7 * i));
    v.insert(v.end(), 11, 0.97);
    const auto changes = run(watch, v);
    ASSERT_EQ(changes.size(), 2U);
    EXPECT_TRUE(changes[0].raised);
    EXPECT_EQ(changes[0].index, 50U);
    EXPECT_FALSE(changes[1].raised);
    EXPECT_EQ(changes[1].index, 261U);
    EXPECT_EQ(changes[0].text(watch.spec()), "x above its warning limit 1 (1.005)");
}

TEST(LimitWatch, TheHoldTimeMustPassBeyondTheLevel)
{
    // Hold 0.1 s = 10 samples: a 10-sample excursion is no alarm, an 11-sample one is,
    // at its 11th sample (0.1 s after the first).
    LimitWatch watch(spec("x>critical:1", 0.1), 100.0);
    std::vector<double> v(20, 0.0);
    v.insert(v.end(), 10, 2.0);
    v.insert(v.end(), 20, 0.0);
    v.insert(v.end(), 11, 2.0);
    const auto changes = run(watch, v);
    ASSERT_EQ(changes.size(), 1U);
    EXPECT_EQ(changes[0].severity, LimitSeverity::Critical);
    EXPECT_EQ(changes[0].index, 60U);  // the second excursion starts at 50
}

TEST(LimitWatch, WarningThenCriticalOnTheWayUpAndTheOtherWayDownBelowToo)
{
    LimitWatch up(spec("f>warning:2,critical:3"), 100.0);
    std::vector<double> ramp;
    for (int i = 0; i <= 40; ++i) ramp.push_back(0.1 * i);  // 0 … 4
    for (int i = 40; i >= 0; --i) ramp.push_back(0.1 * i);  // and back
    const auto changes = run(up, ramp);
    ASSERT_EQ(changes.size(), 4U);
    EXPECT_EQ(changes[0].severity, LimitSeverity::Warning);  // past 2 at 2.1
    EXPECT_EQ(changes[0].index, 21U);
    EXPECT_EQ(changes[1].severity, LimitSeverity::Critical);  // past 3 at 3.1
    EXPECT_EQ(changes[1].index, 31U);
    EXPECT_FALSE(changes[2].raised);  // back below 3 − 0.06 at 2.9 (index 52), for 0.1 s
    EXPECT_EQ(changes[2].severity, LimitSeverity::Critical);
    EXPECT_EQ(changes[2].index, 62U);
    EXPECT_FALSE(changes[3].raised);  // and below 2 − 0.04 at 1.9 (index 62), for 0.1 s
    EXPECT_EQ(changes[3].severity, LimitSeverity::Warning);
    EXPECT_EQ(changes[3].index, 72U);

    LimitWatch down(spec("a<warning:-1"), 100.0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> dip{0.0, nan, -1.5, nan};
    dip.insert(dip.end(), 11, -0.5);  // back from index 4
    const auto below = run(down, dip);
    ASSERT_EQ(below.size(), 2U);
    EXPECT_EQ(below[0].index, 2U);  // a lost sample changes nothing
    EXPECT_FALSE(below[1].raised);
    EXPECT_EQ(below[1].index, 14U);
}

// Windows (issue 39: "above/below/inside/outside"): one limit for either
// way out of a range, or for a range the value must not dwell in.

TEST(LimitWatch, ReadsWindowsAndRefusesOnesThatAreNot)
{
    const auto out = parseLimit("a outside warning:-900..900,critical:-990..990,hold:0.05").limit;
    ASSERT_TRUE(out);
    EXPECT_EQ(out->quantity, "a");
    EXPECT_EQ(out->side, LimitSide::Outside);
    EXPECT_EQ(out->warning, LimitLevel(-900, 900));
    EXPECT_EQ(out->critical, LimitLevel(-990, 990));
    EXPECT_EQ(out->hold_s, 0.05);
    EXPECT_EQ(out->text(), "a outside warning:-900..900,critical:-990..990,hold:0.05");
    const auto in = parseLimit("C  inside  critical:-1e-15..1e-15").limit;
    ASSERT_TRUE(in);
    EXPECT_EQ(in->side, LimitSide::Inside);
    EXPECT_EQ(in->text(), "C inside critical:-1e-15..1e-15");
    for (const char* bad : {"a outside", "a between warning:1..2", "a outside warning:900..-900",
                            "a outside warning:-900", "a outside warning:-900..", "a>warning:-1..1",
                            // critical within the warning window outside, around it inside: backwards
                            "a outside warning:-990..990,critical:-900..900", "a inside warning:-1..1,critical:-2..2",
                            "a outside warning:-1..1,critical:-1..1"}) {
        const auto parsed = parseLimit(bad);
        EXPECT_FALSE(parsed.limit) << bad;
        EXPECT_FALSE(parsed.error.empty()) << bad;
    }
    // One end may be shared: critical only past the high end.
    EXPECT_TRUE(parseLimit("a outside warning:-1..1,critical:-1..2").limit);
}

TEST(LimitWatch, OutsideAWindowIsWatchedAtBothEndsWithTheirHysteresis)
{
    // Window −1..1 (hysteresis 2 % of 1): out past the high end with noise
    // ±0.015 at it, back in, out past the low end likewise, back in.
    LimitWatch watch(spec("a outside warning:-1..1"), 100.0);
    std::vector<double> v(20, 0.0);
    v.push_back(1.005);
    for (int i = 0; i < 100; ++i) v.push_back(1.0 + 0.015 * std::sin(0.7 * i));
    v.push_back(0.975);  // 121: back in by more than 0.02, cleared 0.1 s later
    v.insert(v.end(), 20, 0.0);
    v.push_back(-1.005);  // 142
    for (int i = 0; i < 100; ++i) v.push_back(-1.0 + 0.015 * std::sin(0.7 * i));
    v.insert(v.end(), 11, -0.975);  // 243
    const auto changes = run(watch, v);
    ASSERT_EQ(changes.size(), 4U);
    EXPECT_EQ(changes[0].index, 20U);
    EXPECT_EQ(changes[1].index, 131U);
    EXPECT_FALSE(changes[1].raised);
    EXPECT_EQ(changes[2].index, 142U);
    EXPECT_EQ(changes[3].index, 253U);
    EXPECT_EQ(changes[0].text(watch.spec(), "count"), "a outside its warning window -1..1 count (1.005 count)");
    EXPECT_EQ(changes[3].text(watch.spec()), "a back inside its warning window -1..1");
}

TEST(LimitWatch, InsideAWindowHonoursTheHoldTime)
{
    // A dead channel: C stuck within ±0.1 for more than 0.1 s (10 samples
    // at 100 Hz). Passing through is no alarm; dwelling is, at its 11th
    // sample; it clears 0.1 s after it is 0.002 past either end.
    LimitWatch watch(spec("C inside critical:-0.1..0.1", 0.1), 100.0);
    std::vector<double> v;
    for (int i = 0; i < 30; ++i) v.push_back(1.0 - 0.1 * i);  // through the window in 1 sample steps of 0.1
    v.insert(v.end(), 15, 0.05);                              // 30…44 dwelling
    v.push_back(0.101);                                       // 45: out, but within the hysteresis
    v.push_back(0.05);                                        // 46
    v.insert(v.end(), 11, 0.103);                             // 47…: out past it
    const auto changes = run(watch, v);
    ASSERT_EQ(changes.size(), 2U);
    EXPECT_TRUE(changes[0].raised);
    EXPECT_EQ(changes[0].index, 40U);
    EXPECT_FALSE(changes[1].raised);
    EXPECT_EQ(changes[1].index, 57U);
    EXPECT_EQ(changes[0].text(watch.spec()), "C inside its critical window -0.1..0.1 (0.05)");
    EXPECT_EQ(changes[1].text(watch.spec()), "C back outside its critical window -0.1..0.1");
}

TEST(LimitWatch, ANarrowWindowStillLeavesRoomToComeBackTo)
{
    // 0.99..1.0 is narrower than twice 2 % of 1: the hysteresis shrinks to a
    // quarter of the width (0.0025) so the alarm can clear at all.
    LimitSpec narrow = spec("x outside warning:0.99..1");
    narrow.clear_s = 0.0;  // cleared at once: the hysteresis alone
    LimitWatch watch(narrow, 100.0);
    // With 0.02 it could never clear: 0.99 + 0.02 lies above 1.0 − 0.02.
    const auto changes = run(watch, {0.995, 1.001, 0.999, 0.995});
    ASSERT_EQ(changes.size(), 2U);
    EXPECT_EQ(changes[0].index, 1U);
    EXPECT_EQ(changes[1].index, 3U);  // 0.999 is within 0.0025 of the end; 0.995 is not
}

TEST(LimitWatch, NoisyCrossingsRaiseOnceEachAndChatterWithoutTheHysteresis)
{
    // A slow triangle out of the window 0..1 and back, three times, with
    // Gaussian noise σ = 0.004 (a fifth of the hysteresis 0.02): each
    // excursion is one alarm and one clear. The same stream with no
    // hysteresis and no clear time chatters, so the test can tell.
    std::mt19937 random(39);
    std::normal_distribution<double> noise(0.0, 0.004);
    std::vector<double> v;
    for (int cycle = 0; cycle < 3; ++cycle) {
        for (int i = 0; i <= 400; ++i) v.push_back(0.9 + 0.2 * i / 400.0 + noise(random));
        for (int i = 400; i >= 0; --i) v.push_back(0.9 + 0.2 * i / 400.0 + noise(random));
    }
    LimitWatch steady(spec("x outside warning:0..1"), 100.0);
    const auto changes = run(steady, v);
    ASSERT_EQ(changes.size(), 6U);
    for (std::size_t i = 0; i < changes.size(); ++i) EXPECT_EQ(changes[i].raised, i % 2 == 0) << i;
    LimitSpec bare = spec("x outside warning:0..1");
    bare.hysteresis_fraction = 0.0;
    bare.clear_s = 0.0;
    LimitWatch chattering(bare, 100.0);
    EXPECT_GT(run(chattering, v).size(), 12U);
}

TEST(LimitWatch, NoiseLargerThanTheHysteresisAtAWindowsEndRaisesOnceAndClearsOnceItStaysBack)
{
    // Issue 52 (fresh eyes): a 1 kHz channel whose noise (σ = 0.05, far
    // beyond the 2 % hysteresis) rides at the window's end for 2 s crosses
    // it every few samples. It is one alarm from its first crossing, cleared
    // 0.1 s after the value settles back; without the clear time it is
    // hundreds.
    std::mt19937 random(52);
    std::normal_distribution<double> noise(0.0, 0.05);
    std::vector<double> v(500, 0.0);
    for (int i = 0; i < 2000; ++i) v.push_back(1.0 + noise(random));
    v.insert(v.end(), 500, 0.0);  // back from 2500
    LimitWatch watch(spec("a outside warning:-1..1"), 1000.0);
    const auto changes = run(watch, v);
    ASSERT_EQ(changes.size(), 2U);
    EXPECT_TRUE(changes[0].raised);
    EXPECT_LT(changes[0].index, 510U);
    // 0.1 s after the last sample back: 2500, or the last noise ones if they were.
    EXPECT_LE(changes[1].index, 2600U);
    EXPECT_GE(changes[1].index, 2590U);
    LimitSpec bare = spec("a outside warning:-1..1");
    bare.clear_s = 0.0;
    LimitWatch chattering(bare, 1000.0);
    EXPECT_GT(run(chattering, v).size(), 200U);
}

TEST(LimitWatch, AGivenLimitReplacesThoseGuardingASideInCommon)
{
    const auto limit = [](const char* text) { return *parseLimit(text).limit; };
    EXPECT_TRUE(limit("a outside warning:-1..1").replaces(limit("a>warning:2")));
    EXPECT_TRUE(limit("a outside warning:-1..1").replaces(limit("a<warning:-2")));
    EXPECT_TRUE(limit("a>warning:2").replaces(limit("a outside warning:-1..1")));
    EXPECT_TRUE(limit("a>warning:2").replaces(limit("a>critical:5")));
    EXPECT_FALSE(limit("a>warning:2").replaces(limit("a<warning:-2")));
    EXPECT_FALSE(limit("a inside warning:-1..1").replaces(limit("a outside warning:-2..2")));
    EXPECT_FALSE(limit("b>warning:2").replaces(limit("a>warning:2")));
}

// Issue 52: a stored alarm reads in the units the user typed and saw, not
// as raw SI floats ("2e-05 (2.106e-05)", "0.000956 N").
TEST(LimitWatch, AStoredAlarmIsWordedInTheUnitsPeopleReadIt)
{
    using tactiscope::core::ChannelKind;
    LimitChange change;
    change.severity = LimitSeverity::Critical;
    change.value = 0.000978;
    const auto force = spec("force>warning:0.000597,critical:0.000956");
    EXPECT_EQ(change.text(force, readableWording(ChannelKind::Force, "N", 0.000956)),
              "force above its critical limit 956 µN (978 µN)");
    change.severity = LimitSeverity::Warning;
    change.value = 2.106e-05;
    const auto strain = spec("a>warning:20e-6,critical:28e-6");
    EXPECT_EQ(change.text(strain, readableWording(ChannelKind::Strain, "", 20e-6)),
              "a above its warning limit 20 µε (21.1 µε)");
    change.raised = false;
    EXPECT_EQ(change.text(strain, readableWording(ChannelKind::Strain, "", 20e-6)),
              "a back below its warning limit 20 µε");
    change.raised = true;
    change.value = 1.2e-15;
    const auto window = spec("C inside warning:-1e-15..1e-15");
    EXPECT_EQ(change.text(window, readableWording(ChannelKind::Capacitance, "F", 1e-15)),
              "C inside its warning window -1..1 fF (1.2 fF)");
    change.value = 3.5;
    EXPECT_EQ(change.text(spec("x>warning:3"), readableWording(ChannelKind::Other, "", 3.0)),
              "x above its warning limit 3 (3.5)");
    change.value = 2500.0;
    EXPECT_EQ(change.text(spec("p>warning:2000"), readableWording(ChannelKind::Other, "Pa", 2000.0)),
              "p above its warning limit 2 kPa (2.5 kPa)");
    // A value a thousandfold beyond the level (a board's counts given a
    // unit they are not in) in its own prefix, not in e-notation.
    change.value = 3440.0;
    EXPECT_EQ(change.text(force, readableWording(ChannelKind::Force, "N", 0.000956)),
              "force above its warning limit 597 µN (3.44 kN)");
    // Counts in plain numbers and without a prefix, a plain number's small
    // levels in decimals: no e-notation.
    change.value = 1089.0;
    EXPECT_EQ(
        change.text(spec("stiff outside warning:-990..990"), readableWording(ChannelKind::Other, "counts", 990.0)),
        "stiff outside its warning window -990..990 counts (1089 counts)");
    change.value = -0.366;
    EXPECT_EQ(change.text(spec("b outside warning:-1e-05..1e-05"), readableWording(ChannelKind::Other, "", 1e-5)),
              "b outside its warning window -0.00001..0.00001 (-0.366)");
}
