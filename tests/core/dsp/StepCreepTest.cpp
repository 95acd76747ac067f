// The creep after a load step (core/dsp/StepCreep): a beam made here, as
// the simulator makes one, of two first-order stages in series: the beam
// settling (τ_s) to the load and the silicone creeping (τ_c) a share of it
// further. The creep's time constant and share are the stages' own, worked
// out below from the difference equations, not from the fit; its ± is
// tested as a statistic over many recordings.
#include "core/dsp/StepCreep.h"

#include "support/Coverage.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace tactiscope::core::dsp;

namespace {

struct Beam {
    double rate_hz = 10.0;
    double settle_s = 0.4;
    double creep_s = 4.0;
    double creepShare = 0.01;  // of the settled load, creeping further
    double noise = 1.0;
    double drift_per_s = 0.05;
};

// Loads held `dwell_s` each after a 10 s unloaded start, in the beam's units.
std::vector<double> recording(const Beam& beam, const std::vector<double>& loads, double dwell_s, unsigned seed)
{
    std::mt19937_64 random(seed);
    std::normal_distribution<double> noise(0.0, beam.noise);
    const double dt = 1.0 / beam.rate_hz;
    const double settle = 1.0 - std::exp(-dt / beam.settle_s);
    const double creep = 1.0 - std::exp(-dt / beam.creep_s);
    const auto dwell = static_cast<std::size_t>(std::lround(dwell_s * beam.rate_hz));
    const auto start = static_cast<std::size_t>(std::lround(10.0 * beam.rate_hz));
    std::vector<double> y;
    double settled = 0.0, crept = 0.0;
    for (std::size_t i = 0; i < start + dwell * loads.size(); ++i) {
        const double load = i < start ? 0.0 : loads[(i - start) / dwell];
        settled += (load - settled) * settle;
        crept += (beam.creepShare * settled - crept) * creep;
        y.push_back(settled + crept + beam.drift_per_s * static_cast<double>(i) * dt + noise(random));
    }
    return y;
}

// The slow stage's share of a step, from the onset (the sample before the
// first that moves): with p = e^{−dt/τ_s}, q = e^{−dt/τ_c} and β = 1 − q,
// the creep's part of the response is k·(1 − β·p/(p − q))·q^{n+1}, of a
// step 1 + k (k the creep's share), n samples after the load arrives.
double trueShare(const Beam& beam)
{
    const double dt = 1.0 / beam.rate_hz;
    const double p = std::exp(-dt / beam.settle_s), q = std::exp(-dt / beam.creep_s);
    const double slow = beam.creepShare * (1.0 - (1.0 - q) * p / (p - q));
    return slow / (1.0 + beam.creepShare);
}

std::vector<double> staircase()
{
    std::vector<double> loads;
    for (int k = 1; k <= 10; ++k) loads.push_back(100.0 * k);
    for (int k = 9; k >= 0; --k) loads.push_back(100.0 * k);
    return loads;
}

}  // namespace

TEST(StepCreep, ReadsTheCreepsTimeConstantAndShareOfAStaircase)
{
    const Beam beam{.creepShare = 0.05};
    const auto y = recording(beam, staircase(), 20.0, 7);
    const auto creep = findStepCreep(y, beam.rate_hz);
    ASSERT_TRUE(creep.has_value());
    EXPECT_EQ(creep->steps, 20u);  // up ten, down ten
    EXPECT_NEAR(creep->timeConstant_s, 4.0, 3.0 * creep->timeConstantU_s);
    EXPECT_LT(creep->timeConstantU_s, 0.8);
    EXPECT_NEAR(creep->settleTime_s, 0.4, 0.04);
    ASSERT_TRUE(creep->fractionU.has_value());
    EXPECT_NEAR(creep->fraction, trueShare(beam), 3.0 * *creep->fractionU);
}

TEST(StepCreep, TheTimeConstantsAndSharesUncertaintiesCoverTheTruth)
{
    // ±1u must hold the truth 68.3 % of the time and ±2u 95.4 % (3σ binomial).
    const Beam beam{.creepShare = 0.05};
    tactiscope::testing::Coverage timeConstant, share;
    for (unsigned seed = 0; seed < 200; ++seed) {
        const auto y = recording(beam, staircase(), 16.0, 500 + seed);
        const auto creep = findStepCreep(y, beam.rate_hz);
        ASSERT_TRUE(creep.has_value()) << seed;
        timeConstant.add(creep->timeConstant_s - beam.creep_s, creep->timeConstantU_s);
        share.add(creep->fraction - trueShare(beam), creep->fractionU.value());
    }
    EXPECT_TRUE(timeConstant.isGaussian());
    EXPECT_TRUE(share.isGaussian());
}

TEST(StepCreep, NoStepOrACreepLostInTheNoiseIsNone)
{
    const Beam flat;
    EXPECT_FALSE(findStepCreep(recording(flat, {0.0, 0.0}, 30.0, 3), flat.rate_hz).has_value());
    // A beam without creep: the slow constant runs to a bound, or reads none
    // of the step.
    const Beam elastic{.creepShare = 0.0};
    const auto creep = findStepCreep(recording(elastic, staircase(), 20.0, 4), elastic.rate_hz);
    if (creep) {
        EXPECT_LT(std::fabs(creep->fraction), 3.0 * creep->fractionU.value_or(0.0) + 1e-4);
    }
}

TEST(StepCreep, MissingSamplesAreLeftOutNotBridged)
{
    const Beam beam{.creepShare = 0.05};
    auto y = recording(beam, staircase(), 20.0, 9);
    for (std::size_t i = 400; i < 430; ++i) y[i] = std::numeric_limits<double>::quiet_NaN();
    auto creep = findStepCreep(y, beam.rate_hz);
    ASSERT_TRUE(creep.has_value());
    EXPECT_NEAR(creep->timeConstant_s, 4.0, 3.0 * creep->timeConstantU_s);
    // A gap over a step's onset (the third step, at 50 s): that step is
    // left out, where it began being unknown, and the others still read.
    for (std::size_t i = 495; i < 510; ++i) y[i] = std::numeric_limits<double>::quiet_NaN();
    creep = findStepCreep(y, beam.rate_hz);
    ASSERT_TRUE(creep.has_value());
    EXPECT_EQ(creep->steps, 19u);
    EXPECT_NEAR(creep->timeConstant_s, 4.0, 3.0 * creep->timeConstantU_s);
}
