// The fast PairDetector against the direct Eigen implementation, and against
// signals whose answer is known by construction.
#include "core/detector/PairDetector.h"

#include "DirectDetector.h"
#include "core/detector/DetectorSignals.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace tactiscope::core::detector;
using tactiscope::reference::DirectDetector;
using namespace tactiscope::testing;

namespace {

DetectorParameters smallParameters()
{
    DetectorParameters p;
    p.lags_s = lagRange_s(0.002, 0.060, 0.002);  // 30 lags: 3 full vectors + padding
    return p;
}

// Runs both implementations sample by sample and compares every lag's R.
void expectSameAsDirect(KernelVariant variant, const DetectorParameters& p, const std::vector<double>& a,
                        const std::vector<double>& b, double tolerance = 1e-9)
{
    PairDetector fast(p, variant);
    DirectDetector direct(p);
    const std::size_t lags = fast.parameters().lags.size();
    std::vector<double> rab(lags), rba(lags);
    std::size_t decisionsCompared = 0;
    for (std::size_t t = 0; t < a.size(); ++t) {
        DetectorOutput f, d;
        fast.process({&a[t], 1}, {&b[t], 1}, {&f, 1});
        direct.process({&a[t], 1}, {&b[t], 1}, {&d, 1});
        fast.currentCorrelations(rab, rba);
        for (std::size_t i = 0; i < lags; ++i) {
            ASSERT_NEAR(rab[i], direct.lastRab()[i], tolerance) << "sample " << t << " lag " << i;
            ASSERT_NEAR(rba[i], direct.lastRba()[i], tolerance) << "sample " << t << " lag " << i;
        }
        ASSERT_NEAR(f.rab, d.rab, tolerance) << "sample " << t;
        ASSERT_NEAR(f.rba, d.rba, tolerance) << "sample " << t;
        // A decision can only differ where R sits within rounding of the threshold.
        if (std::abs(d.rab - p.threshold) > tolerance && std::abs(d.rba - p.threshold) > tolerance) {
            ASSERT_EQ(f.decision, d.decision) << "sample " << t;
            ++decisionsCompared;
        }
    }
    EXPECT_GT(decisionsCompared, a.size() * 9 / 10);
}

std::vector<DetectorOutput> runAll(PairDetector& detector, const std::vector<double>& a, const std::vector<double>& b)
{
    std::vector<DetectorOutput> out(a.size());
    detector.process(a, b, out);
    return out;
}

}  // namespace

// Every instruction-set variant of the kernel is checked on machines that
// have it (this one has all three).
class PairDetectorKernel : public ::testing::TestWithParam<KernelVariant> {
protected:
    void SetUp() override
    {
        if (!kernelVariantSupported(GetParam())) GTEST_SKIP() << "CPU lacks " << toString(GetParam());
    }
};

INSTANTIATE_TEST_SUITE_P(AllVariants, PairDetectorKernel,
                         ::testing::Values(KernelVariant::Baseline, KernelVariant::Avx2, KernelVariant::Avx512),
                         [](const ::testing::TestParamInfo<KernelVariant>& variant) {
                             switch (variant.param) {
                             case KernelVariant::Baseline:
                                 return std::string("Baseline");
                             case KernelVariant::Avx2:
                                 return std::string("Avx2");
                             case KernelVariant::Avx512:
                                 return std::string("Avx512");
                             }
                             return std::string("Unknown");
                         });

TEST_P(PairDetectorKernel, ExponentialFormEqualsTheDirectInverseOnEverySampleAndLag)
{
    // A delayed copy plus independent noise: correlations across the whole
    // range, including the region near 1.
    const auto source = whiteNoise(1500, 2e-5, 1);
    const auto a = plus(source, whiteNoise(1500, 5e-6, 2));
    const auto b = plus(delayedBy(source, 12), whiteNoise(1500, 5e-6, 3));
    expectSameAsDirect(GetParam(), smallParameters(), a, b);
}

TEST_P(PairDetectorKernel, FixedLambdaAndFaceToFaceEqualTheDirectInverse)
{
    DetectorParameters p = smallParameters();
    p.lambdaRule = LambdaRule::Fixed;
    p.fixedLambda_s = 0.05;
    p.faceToFace = true;
    const auto source = whiteNoise(1200, 2e-5, 4);
    const auto a = plus(delayedBy(source, 7), whiteNoise(1200, 4e-6, 5));
    const auto b = plus(source, whiteNoise(1200, 4e-6, 6));
    expectSameAsDirect(GetParam(), p, a, b);
}

TEST_P(PairDetectorKernel, SlidingWindowFormEqualsABruteForceWindow)
{
    DetectorParameters p = smallParameters();
    p.window_s = 0.080;  // 40 samples
    const auto source = whiteNoise(900, 2e-5, 7);
    const auto a = plus(source, whiteNoise(900, 5e-6, 8));
    const auto b = plus(delayedBy(source, 9), whiteNoise(900, 5e-6, 9));
    expectSameAsDirect(GetParam(), p, a, b, 1e-8);
}

TEST_P(PairDetectorKernel, ScatteredLagsEqualTheDirectInverse)
{
    // Lags that are not consecutive samples take the gathering path.
    DetectorParameters p;
    p.lags_s = {0.004, 0.010, 0.012, 0.030, 0.046, 0.050, 0.090, 0.100, 0.130, 0.150, 0.022};
    const auto source = whiteNoise(1000, 2e-5, 10);
    const auto a = plus(source, whiteNoise(1000, 5e-6, 13));
    const auto b = plus(delayedBy(source, 15), whiteNoise(1000, 5e-6, 14));
    expectSameAsDirect(GetParam(), p, a, b);
}

TEST(PairDetector, RefusesAKernelTheCpuCannotRun)
{
    for (KernelVariant v : {KernelVariant::Baseline, KernelVariant::Avx2, KernelVariant::Avx512}) {
        if (kernelVariantSupported(v)) {
            EXPECT_NO_THROW(PairDetector(DetectorParameters{}, v));
        } else {
            EXPECT_THROW(PairDetector(DetectorParameters{}, v), std::invalid_argument);
        }
    }
    EXPECT_TRUE(kernelVariantSupported(KernelVariant::Baseline));
}

TEST(PairDetector, ADelayedCopyIsSeenAsAThenBAtItsLag)
{
    // b(t) = a(t − 40 ms): R_ab peaks at k = 20 samples. For white a of
    // variance σ², V at that lag is σ²·C + ε²·I with b(t) ≡ a(t−c), so
    // R_ab → σ²/(σ² + ε²) = 0.99946 for σ = 3·10⁻⁴ and ε = 7·10⁻⁶.
    DetectorParameters p;  // the paper's settings
    const auto a = whiteNoise(3000, 3e-4, 11);
    const auto b = delayedBy(a, 20);
    PairDetector detector(p);
    const auto out = runAll(detector, a, b);
    std::size_t positive = 0, negative = 0;
    for (std::size_t t = 200; t < out.size(); ++t) {  // after warm-up
        positive += out[t].decision == 1;
        negative += out[t].decision == -1;
        EXPECT_EQ(out[t].lagAb, 20u) << "sample " << t;
        EXPECT_GT(out[t].rab, 0.99);
    }
    EXPECT_EQ(positive, out.size() - 200);
    EXPECT_EQ(negative, 0u);

    // Lag by lag at the last sample, k = 20 stands out in both directions.
    // (Single lags with λ = c of a few samples are noisy estimates and may
    // cross the threshold alone; the maximum is what decides.)
    std::vector<double> rab(detector.parameters().lags.size()), rba(rab.size());
    detector.currentCorrelations(rab, rba);
    const double atLag = rab[19];  // lags are 1…75 samples
    EXPECT_EQ(detector.parameters().lags[19], 20u);
    for (std::size_t i = 0; i < rab.size(); ++i) {
        if (i != 19) {
            EXPECT_LT(rab[i], atLag) << "lag " << i;
        }
        EXPECT_LT(rba[i], atLag) << "lag " << i;
    }
}

TEST(PairDetector, TheMirrorCaseIsSeenAsBThenA)
{
    const auto b = whiteNoise(3000, 3e-4, 12);
    const auto a = delayedBy(b, 35);
    PairDetector detector{DetectorParameters{}};
    const auto out = runAll(detector, a, b);
    for (std::size_t t = 300; t < out.size(); ++t) {
        ASSERT_EQ(out[t].decision, -1) << "sample " << t;
        ASSERT_EQ(out[t].lagBa, 35u);
    }
}

TEST(PairDetector, ACommonCyclicDisturbanceIsNotADefectThoughPlainCorrelationSaysSo)
{
    // Both gauges see the same 1 Hz hand motion, b 60 ms behind a, plus
    // independent noise: to a plain correlation b(t) and a(t − 60 ms) look
    // alike (≈ 0.99 here), the paper's false alarm. The partial correlation
    // removes what a(t) and b(t−c) explain — for a sinusoid, everything but
    // the noise — and finds nothing.
    const std::size_t n = 4000;
    const double dt = 0.002;
    const double shift = -2.0 * std::numbers::pi * 1.0 * 0.060;
    const auto a = plus(sine(n, dt, 1.0, 1e-4), whiteNoise(n, 2e-6, 21));
    const auto b = plus(sine(n, dt, 1.0, 1e-4, shift), whiteNoise(n, 2e-6, 22));
    DetectorParameters p;
    p.lambdaRule = LambdaRule::Fixed;
    p.fixedLambda_s = 0.3;  // long memory, so the plain correlation is stable
    PairDetector detector(p);
    DirectDetector direct(p);
    const auto out = runAll(detector, a, b);
    std::vector<DetectorOutput> directOut(n);
    direct.process(a, b, directOut);

    for (std::size_t t = 1000; t < n; ++t) ASSERT_EQ(out[t].decision, 0) << "sample " << t;
    const auto& plain = direct.lastPlainAb();
    EXPECT_GT(*std::max_element(plain.begin(), plain.end()), 0.85);  // would have "detected"
    EXPECT_LT(*std::max_element(direct.lastRab().begin(), direct.lastRab().end()), 0.85);
}

TEST(PairDetector, FaceToFaceNegatesB)
{
    const auto a = whiteNoise(1000, 3e-5, 31);
    const auto b = delayedBy(a, 15);
    std::vector<double> negated(b.size());
    std::transform(b.begin(), b.end(), negated.begin(), [](double v) { return -v; });
    DetectorParameters facing;
    facing.faceToFace = true;
    PairDetector normal{DetectorParameters{}}, mounted(facing);
    const auto expected = runAll(normal, a, b);
    const auto got = runAll(mounted, a, negated);
    for (std::size_t t = 0; t < a.size(); ++t) {
        ASSERT_EQ(got[t].decision, expected[t].decision);
        ASSERT_DOUBLE_EQ(got[t].rab, expected[t].rab);
    }
    EXPECT_EQ(got.back().decision, 1);
}

TEST(PairDetector, TinySignalsStayFiniteAndQuietThanksToEpsilon)
{
    // Signals a million times below ε: the ε²·I₄ term dominates V.
    const auto source = whiteNoise(2000, 1e-12, 41);
    const auto b = delayedBy(source, 10);
    PairDetector detector{DetectorParameters{}};
    const auto out = runAll(detector, source, b);
    for (const auto& o : out) {
        ASSERT_TRUE(std::isfinite(o.rab) && std::isfinite(o.rba));
        ASSERT_LE(std::abs(o.rab), 1.0 + 1e-12);
        ASSERT_EQ(o.decision, 0);
    }
}

TEST(PairDetector, ChunkingDoesNotChangeTheResult)
{
    const auto source = whiteNoise(9000, 2e-5, 51);  // longer than one internal run
    const auto b = plus(delayedBy(source, 30), whiteNoise(9000, 5e-6, 52));
    PairDetector whole{DetectorParameters{}}, pieces{DetectorParameters{}};
    const auto expected = runAll(whole, source, b);
    std::vector<DetectorOutput> got(source.size());
    const std::size_t sizes[] = {1, 7, 5000, 13};
    for (std::size_t done = 0, i = 0; done < source.size(); ++i) {
        const std::size_t n = std::min(sizes[i % 4], source.size() - done);
        pieces.process({&source[done], n}, {&b[done], n}, {&got[done], n});
        done += n;
    }
    for (std::size_t t = 0; t < source.size(); ++t) {
        ASSERT_EQ(got[t].rab, expected[t].rab) << "sample " << t;
        ASSERT_EQ(got[t].lagBa, expected[t].lagBa) << "sample " << t;
    }
}

TEST(PairDetector, ASnapshotContinuesExactlyAndResetStartsAfresh)
{
    const auto a = whiteNoise(6000, 2e-5, 61);
    const auto b = delayedBy(a, 25);
    DetectorParameters p;
    PairDetector first(p);
    std::vector<DetectorOutput> head(3000), tail(3000), resumed(3000);
    first.process({a.data(), 3000}, {b.data(), 3000}, head);
    const auto saved = first.snapshot();
    first.process({a.data() + 3000, 3000}, {b.data() + 3000, 3000}, tail);

    PairDetector second(p);
    second.restore(saved);
    second.process({a.data() + 3000, 3000}, {b.data() + 3000, 3000}, resumed);
    for (std::size_t t = 0; t < 3000; ++t) ASSERT_EQ(resumed[t].rab, tail[t].rab);

    second.reset();
    std::vector<DetectorOutput> again(3000);
    second.process({a.data(), 3000}, {b.data(), 3000}, again);
    for (std::size_t t = 0; t < 3000; ++t) ASSERT_EQ(again[t].rba, head[t].rba);

    DetectorParameters other;
    other.lags_s = lagRange_s(0.002, 0.010, 0.002);
    PairDetector different(other);
    EXPECT_THROW(different.restore(saved), std::invalid_argument);
}
