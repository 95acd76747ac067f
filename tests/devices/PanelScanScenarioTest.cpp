// PanelScanScenario: determinism, continuity across blocks, and the physics
// against independent hand calculations of the probe kinematics.
#include "devices/simulator/PanelScanScenario.h"

#include "core/SampleBlock.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <vector>

using tactiscope::core::SampleBlock;
using tactiscope::devices::simulator::PanelScanParameters;
using tactiscope::devices::simulator::PanelScanScenario;

namespace {

// Generates `samples` samples in blocks of `blockSize`; returns {a, b}.
std::pair<std::vector<double>, std::vector<double>> run(PanelScanScenario& scenario, std::size_t samples,
                                                        std::size_t blockSize = 50)
{
    std::vector<double> a, b;
    const double dt = 1.0 / scenario.sampleRate_hz();
    for (std::size_t done = 0; done < samples;) {
        const std::size_t n = std::min(blockSize, samples - done);
        SampleBlock block(2, n, static_cast<double>(done) * dt, dt, done);
        scenario.generate(block);
        a.insert(a.end(), block.channel(0).begin(), block.channel(0).end());
        b.insert(b.end(), block.channel(1).begin(), block.channel(1).end());
        done += n;
    }
    return {a, b};
}

PanelScanParameters noiselessWithoutInertia()
{
    PanelScanParameters p;
    p.noiseSigma = 0.0;
    p.strainPerAcceleration_s2_per_m = 0.0;
    return p;
}

}  // namespace

TEST(PanelScanScenario, AnnouncesTwoStrainChannels)
{
    const PanelScanScenario scenario;
    ASSERT_EQ(scenario.channels().size(), 2u);
    EXPECT_EQ(scenario.channels()[0].name, "a");
    EXPECT_EQ(scenario.channels()[1].name, "b");
    EXPECT_EQ(scenario.channels()[0].kind, tactiscope::core::ChannelKind::Strain);
    EXPECT_EQ(scenario.sampleRate_hz(), 500.0);
}

TEST(PanelScanScenario, TheSameSeedGivesTheSameSamples)
{
    PanelScanParameters p;
    p.seed = 11;
    PanelScanScenario first(p), second(p);
    EXPECT_EQ(run(first, 2000), run(second, 2000));
    p.seed = 12;
    PanelScanScenario other(p);
    EXPECT_NE(run(other, 2000).first, run(first, 2000).first);
}

TEST(PanelScanScenario, BlockSizeDoesNotChangeTheSignal)
{
    PanelScanScenario small, large;
    EXPECT_EQ(run(small, 1500, 7), run(large, 1500, 1500));
}

TEST(PanelScanScenario, CantileverAMeetsTheDefectFirstOnTheForwardStroke)
{
    // With adaptation switched off (τ → ∞) a gauge follows the inclination
    // under it, θ ∝ u·exp(−u²/2) with u = (x − 30 mm)/4 mm: a minimum at
    // x = 26 mm and a maximum at x = 34 mm. A sits at x(t) = 0.1·sin(πt) m,
    // B 15 mm behind it, so on the forward stroke
    //   A: min at asin(0.26)/π = 0.0837 s, max at asin(0.34)/π = 0.1104 s,
    //   B: min at asin(0.41)/π = 0.1345 s, max at asin(0.49)/π = 0.1630 s,
    // and on the way back (x(1 − t) = x(t)) B passes first, in mirror order.
    PanelScanParameters p = noiselessWithoutInertia();
    p.adaptationTime_s = 1e9;
    PanelScanScenario scenario(p);
    const auto [a, b] = run(scenario, 500);  // one second at 500 Hz
    const auto timeOf = [](const std::vector<double>& v, std::size_t from, std::size_t to, bool maximum) {
        std::size_t best = from;
        for (std::size_t i = from; i < to; ++i) {
            if (maximum ? v[i] > v[best] : v[i] < v[best]) best = i;
        }
        return static_cast<double>(best) * 0.002;
    };
    const auto crossing = [](double x_mm) { return std::asin(x_mm / 100.0) / std::numbers::pi; };
    const double halfSample = 0.001 + 1e-9;
    EXPECT_NEAR(timeOf(a, 0, 250, false), crossing(26.0), halfSample);
    EXPECT_NEAR(timeOf(a, 0, 250, true), crossing(34.0), halfSample);
    EXPECT_NEAR(timeOf(b, 0, 250, false), crossing(41.0), halfSample);
    EXPECT_NEAR(timeOf(b, 0, 250, true), crossing(49.0), halfSample);
    EXPECT_NEAR(timeOf(b, 250, 500, false), 1.0 - crossing(41.0), halfSample);
    EXPECT_NEAR(timeOf(a, 250, 500, false), 1.0 - crossing(26.0), halfSample);
}

TEST(PanelScanScenario, TheCapsuleForgetsABendWithItsAdaptationTime)
{
    // Once A has left the dent (x > 55 mm from t = 0.19 s on the forward
    // stroke, where θ has fallen below 1e-10 of its peak), its bend relaxes as
    // exp(−t/τ).
    PanelScanScenario scenario(noiselessWithoutInertia());
    const auto [a, b] = run(scenario, 250);
    const double tau = scenario.parameters().adaptationTime_s;
    const std::size_t from = 100;  // t = 0.2 s
    const std::size_t to = 175;    // t = 0.35 s, one τ later
    EXPECT_NE(a[from], 0.0);
    EXPECT_NEAR(a[to] / a[from], std::exp(-0.15 / tau), 1e-6);
}

TEST(PanelScanScenario, WithoutADefectOnlyTheFluidInertiaRemains)
{
    // Without dent and noise both gauges read k·x''(t) = −k·ω²·X·sin(ωt).
    PanelScanParameters p;
    p.hasDefect = false;
    p.noiseSigma = 0.0;
    PanelScanScenario scenario(p);
    const auto [a, b] = run(scenario, 1000);
    const double omega = std::numbers::pi;  // 0.5 Hz
    for (std::size_t i = 0; i < a.size(); i += 37) {
        const double t = static_cast<double>(i) * 0.002;
        const double expected = -1e-5 * omega * omega * 0.1 * std::sin(omega * t);
        EXPECT_NEAR(a[i], expected, 1e-15);
        EXPECT_NEAR(b[i], expected, 1e-15);
    }
}

TEST(PanelScanScenario, FaceToFaceGaugesInvertB)
{
    PanelScanParameters p;
    PanelScanScenario normal(p);
    p.faceToFace = true;
    PanelScanScenario facing(p);
    const auto [a1, b1] = run(normal, 1000);
    const auto [a2, b2] = run(facing, 1000);
    EXPECT_EQ(a1, a2);
    for (std::size_t i = 0; i < b1.size(); ++i) ASSERT_EQ(b2[i], -b1[i]);
}

TEST(PanelScanScenario, NoiseHasTheRequestedSpreadAndIsIndependentPerGauge)
{
    PanelScanParameters p;
    p.hasDefect = false;
    p.strainPerAcceleration_s2_per_m = 0.0;
    p.noiseSigma = 2e-6;
    PanelScanScenario scenario(p);
    const auto [a, b] = run(scenario, 40000);
    const auto n = static_cast<double>(a.size());
    const double meanA = std::accumulate(a.begin(), a.end(), 0.0) / n;
    double varA = 0.0, varB = 0.0, cov = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        varA += (a[i] - meanA) * (a[i] - meanA);
        varB += b[i] * b[i];
        cov += a[i] * b[i];
    }
    // Standard error of σ̂ for 40000 samples is about 0.35 %.
    EXPECT_NEAR(std::sqrt(varA / n), 2e-6, 0.05e-6);
    EXPECT_NEAR(std::sqrt(varB / n), 2e-6, 0.05e-6);
    EXPECT_NEAR(meanA, 0.0, 0.05e-6);
    EXPECT_NEAR(cov / std::sqrt(varA * varB), 0.0, 0.03);
}

TEST(PanelScanScenario, RejectsNonPhysicalParameters)
{
    PanelScanParameters p;
    p.sampleRate_hz = 0.0;
    EXPECT_THROW(PanelScanScenario{p}, std::invalid_argument);
    p = {};
    p.adaptationTime_s = -1.0;
    EXPECT_THROW(PanelScanScenario{p}, std::invalid_argument);
    p = {};
    p.noiseSigma = -1e-6;
    EXPECT_THROW(PanelScanScenario{p}, std::invalid_argument);
}
