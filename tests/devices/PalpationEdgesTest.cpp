// The compliance probe at its far edges (issue 55): specimens of 0.3 N/m
// (Q within a hair of 1) and 10⁸ N/m (Q within a hair of k_h/k_l),
// simulated as PalpationUncertaintyTest simulates them (each session its
// noise, its zero taken by a tare while the probe is lifted), read as a
// press and as a session. A press's bound says the object is below (or
// above) a k_o at 2u from its ratio; as a one-sided 2u statement it may
// fail about 2.3 % of the time, within binomial limits. Before the bound
// held the zero's part of u, 9 of 87 at 0.3 N/m failed. A press read in
// range there has limits at Q ∓ 2u through the exact map that hold the
// truth about 95 % of the time. A session whose presses include bounds
// is a bound itself, never the number of its few in-range presses (2 of
// 20 sessions at 10⁸ N/m read 6·10⁶ ± 2·10⁶ N/m).
#include "core/SampleBlock.h"
#include "core/compliance/CombinedPresses.h"
#include "core/compliance/LivePalpation.h"
#include "devices/simulator/PalpationScenario.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

using namespace tactiscope;
using core::compliance::PressStatus;

namespace {

constexpr double kRate_hz = 1000.0;

// What the presses and sessions said, and how often it was wrong: a bound
// on the wrong side of the truth, or 95 % limits without it.
struct Tally {
    std::size_t bounds = 0, wrongBounds = 0;    // presses out of range, and their bounds on the wrong side
    std::size_t inRange = 0, withinLimits = 0;  // presses read, and the truth within their limits
    std::size_t lopsided = 0;                   // of those, limits one side half again the other's or more
    std::size_t sessions = 0, sessionBounds = 0, wrongSessions = 0;
    std::size_t sessionsWithABoundedPress = 0, numbersBesideBounds = 0;

    std::size_t pressStatements() const { return bounds + inRange; }
    std::size_t wrongPressStatements() const { return wrongBounds + inRange - withinLimits; }
};

bool isBound(const core::compliance::PressReading& r)
{
    return r.status == PressStatus::BelowRange || r.status == PressStatus::AboveRange;
}

// `seeds` sessions of presses on a specimen of `truth`; `soft`: its edge is Q = 1.
Tally pressOn(double truth, bool soft, std::uint64_t seeds)
{
    Tally tally;
    std::mt19937 tareMoments(7);
    for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
        devices::simulator::PalpationParameters p;
        p.objectStiffness_n_per_m = truth;
        p.pause_s = 2.0;
        p.seed = seed;
        // A soft specimen pressed deep enough for its force to read.
        if (soft) p.pressDepths_m = {0.03, 0.04, 0.05};
        devices::simulator::PalpationScenario scenario(p);
        core::SampleBlock all(3, static_cast<std::size_t>(16.0 * kRate_hz), 0.0, 1.0 / kRate_hz);
        scenario.generate(all);
        core::compliance::LivePalpation live(scenario.channels(), kRate_hz,
                                             {p.high, p.low, p.adc, p.bridge, {0.01, 100}, {}, {}, {}, {}, {}}, 1.0);
        // The tare, once, while the probe is lifted: its window is the half second before.
        const auto tareAt = static_cast<std::size_t>(std::uniform_real_distribution<double>(1.05, 1.95)(tareMoments) *
                                                     kRate_hz / 100.0) *
                            100;
        for (std::size_t s = 0; s < all.sampleCount(); s += 100) {
            if (s == tareAt) {
                const auto refused = live.tare();
                EXPECT_FALSE(refused.has_value()) << "seed " << seed << ": " << refused.value_or("");
            }
            core::SampleBlock block(3, 100, all.timeAt_s(s), all.dt_s(), s);
            for (std::size_t c = 0; c < 3; ++c)
                std::copy_n(all.channel(c).begin() + static_cast<std::ptrdiff_t>(s), 100, block.channel(c).begin());
            live.consume(block);
        }
        const auto readings = live.takeReadings();
        for (const auto& r : readings) {
            if (r.status == PressStatus::Ok) {
                ++tally.inRange;
                tally.withinLimits += truth >= r.lowerLimit_n_per_m && truth <= r.upperLimit_n_per_m;
                const double down = r.stiffness.objectStiffness_n_per_m - r.lowerLimit_n_per_m;
                const double up = r.upperLimit_n_per_m - r.stiffness.objectStiffness_n_per_m;
                tally.lopsided += std::max(down, up) >= 1.5 * std::min(down, up);
            } else if (r.bound_n_per_m) {
                EXPECT_EQ(r.status, soft ? PressStatus::BelowRange : PressStatus::AboveRange);
                ++tally.bounds;
                tally.wrongBounds += soft ? truth > *r.bound_n_per_m : truth < *r.bound_n_per_m;
            }
        }
        const auto combined = core::compliance::combinePresses(
            core::sensors::CompliancePair(core::sensors::CantileverBeam(p.high), core::sensors::CantileverBeam(p.low)),
            readings);
        if (!combined) continue;
        ++tally.sessions;
        if (std::ranges::any_of(readings, isBound)) {
            ++tally.sessionsWithABoundedPress;
            tally.numbersBesideBounds += combined->status == PressStatus::Ok;
        }
        if (combined->status == PressStatus::Ok) {
            tally.wrongSessions += truth < combined->lowerLimit_n_per_m || truth > combined->upperLimit_n_per_m;
        } else if (combined->bound_n_per_m) {
            ++tally.sessionBounds;
            tally.wrongSessions += soft ? truth > *combined->bound_n_per_m : truth < *combined->bound_n_per_m;
        }
    }
    return tally;
}

// At most the expected count of a rate plus 3σ of its binomial spread.
bool atMost(std::size_t hits, std::size_t runs, double rate)
{
    const double n = static_cast<double>(runs);
    return static_cast<double>(hits) <= n * rate + 3.0 * std::sqrt(n * rate * (1.0 - rate)) + 1.0;
}

void report(const char* name, const Tally& t)
{
    std::printf("%s: press bounds %zu, %zu on the wrong side; presses in range %zu, %zu within their 95 %% limits "
                "(%zu lopsided); sessions %zu, %zu of them bounds, %zu statements wrong; %zu with a bounded press, "
                "%zu of them a number\n",
                name, t.bounds, t.wrongBounds, t.inRange, t.withinLimits, t.lopsided, t.sessions, t.sessionBounds,
                t.wrongSessions, t.sessionsWithABoundedPress, t.numbersBesideBounds);
}

// At the edge every statement (a bound, or limits) holds at its rate over
// all presses and all sessions (the presses read in range there are those
// the noise pushed inside, so their limits alone miss more often), and a
// session beside bounded presses is never a number.
void expectHonest(const Tally& t)
{
    EXPECT_TRUE(atMost(t.wrongBounds, t.bounds, 0.0228)) << "one-sided 2u bounds";
    EXPECT_TRUE(atMost(t.wrongPressStatements(), t.pressStatements(), 0.0455)) << "every press's statement";
    EXPECT_TRUE(atMost(t.wrongSessions, t.sessions, 0.0455)) << "every session's statement";
    EXPECT_EQ(t.numbersBesideBounds, 0u) << "a session whose presses include bounds is a bound";
}

}  // namespace

TEST(PalpationEdges, AtPointThreeNewtonsPerMetreTheBoundsHoldAsOneSidedTwoSigmaStatements)
{
    const Tally t = pressOn(0.3, true, 100);
    report("0.3 N/m", t);
    ASSERT_GE(t.bounds, 100u);
    expectHonest(t);
}

TEST(PalpationEdges, AtTenToTheEightNewtonsPerMetreEverySessionBesideABoundIsABoundThatHolds)
{
    const Tally t = pressOn(1e8, false, 100);
    report("1e8 N/m", t);
    ASSERT_GE(t.bounds, 100u);
    expectHonest(t);
}

// Inside the range but near Q = k_h/k_l (10⁷ N/m), where k_o runs off to
// infinity, the limits through the exact map are lopsided (a linearised ±
// would put the upper one far short) and hold the truth as 95 % limits do.
// (Near Q = 1 the map is nearly straight: the limits are symmetric there.)
TEST(PalpationEdges, NearTheStiffEndTheLimitsAreLopsidedAndHoldTheTruth)
{
    const Tally t = pressOn(1e7, false, 60);
    report("1e7 N/m", t);
    ASSERT_GE(t.inRange, 100u);
    EXPECT_GT(t.lopsided, t.inRange / 2);
    EXPECT_TRUE(atMost(t.inRange - t.withinLimits, t.inRange, 0.0455));
    expectHonest(t);
}
