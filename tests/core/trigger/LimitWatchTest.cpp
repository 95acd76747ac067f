// Limit alarms (issue 39): the limit's words, a hold time that must pass
// beyond a level before its alarm, and a hysteresis that keeps noise at the
// level from chattering. 100 Hz streams: 0.1 s is 10 samples.
#include "core/trigger/LimitWatch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
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
    EXPECT_TRUE(l->above);
    EXPECT_EQ(l->warning, 0.002);
    EXPECT_EQ(l->critical, 0.003);
    EXPECT_EQ(l->text(), "force>warning:0.002,critical:0.003");
    EXPECT_FALSE(parseLimit("a<critical:-1e-3").limit->above);
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
    // clear; then it drops to 0.97, past the band: cleared there.
    LimitWatch watch(spec("x>warning:1"), 100.0);
    std::vector<double> v(50, 0.5);
    v.push_back(1.005);
    for (int i = 0; i < 200; ++i) v.push_back(1.0 + 0.015 * std::sin(0.7 * i));
    v.push_back(0.97);
    const auto changes = run(watch, v);
    ASSERT_EQ(changes.size(), 2U);
    EXPECT_TRUE(changes[0].raised);
    EXPECT_EQ(changes[0].index, 50U);
    EXPECT_EQ(changes[0].level, 1.0);
    EXPECT_FALSE(changes[1].raised);
    EXPECT_EQ(changes[1].index, 251U);
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
    EXPECT_FALSE(changes[2].raised);  // back below 3 − 0.06 at 2.9
    EXPECT_EQ(changes[2].severity, LimitSeverity::Critical);
    EXPECT_FALSE(changes[3].raised);  // and below 2 − 0.04 at 1.9
    EXPECT_EQ(changes[3].severity, LimitSeverity::Warning);

    LimitWatch down(spec("a<warning:-1"), 100.0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto below = run(down, {0.0, nan, -1.5, nan, -0.5});
    ASSERT_EQ(below.size(), 2U);
    EXPECT_EQ(below[0].index, 2U);  // a lost sample changes nothing
    EXPECT_FALSE(below[1].raised);
    EXPECT_EQ(below[1].index, 4U);
}
