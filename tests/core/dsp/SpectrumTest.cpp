// Welch's spectrum against what a sine and white noise must give, and
// its segments against the gaps of a recording.
#include "core/dsp/MainsHum.h"
#include "core/dsp/WelchSpectrum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <numeric>
#include <random>

using namespace tactiscope::core::dsp;

namespace {

std::vector<double> whiteNoise(std::size_t n, double sigma, unsigned seed)
{
    std::mt19937 random(seed);
    std::normal_distribution<double> noise(0.0, sigma);
    std::vector<double> v(n);
    for (double& x : v) x = noise(random);
    return v;
}

void addSine(std::vector<double>& v, double rate, double f, double amplitude, double phase = 0.3)
{
    for (std::size_t i = 0; i < v.size(); ++i)
        v[i] += amplitude * std::sin(2.0 * std::numbers::pi * f * static_cast<double>(i) / rate + phase);
}

}  // namespace

TEST(Spectrum, ASineAt37HzPeaksThereWithItsAmplitude)
{
    const double rate = 1000.0;
    for (const double f : {37.0, 36.8, 37.27}) {  // on a bin and between bins
        auto v = whiteNoise(30000, 0.01, 3);
        addSine(v, rate, f, 2.5);
        const Spectrum s = welchSpectrum(v, rate, {SpectralWindow::Hann, 16});
        ASSERT_FALSE(s.peaks.empty());
        EXPECT_NEAR(s.peaks[0].frequency_hz, f, 0.5) << f;
        EXPECT_NEAR(s.peaks[0].amplitude, 2.5, 0.01 * 2.5) << f;
        EXPECT_GE(s.averages, 16u);
    }
}

TEST(Spectrum, WhiteNoiseHasTheDensityItsVarianceGives)
{
    // One-sided: σ²·2/fs, averaged over the bins between DC and Nyquist.
    const double rate = 1000.0;
    const double sigma = 3.0;
    for (const SpectralWindow window : {SpectralWindow::Hann, SpectralWindow::FlatTop}) {
        const Spectrum s = welchSpectrum(whiteNoise(60000, sigma, 11), rate, {window, 16});
        ASSERT_GE(s.averages, 16u);
        const double mean =
            std::accumulate(s.psd.begin() + 1, s.psd.end() - 1, 0.0) / static_cast<double>(s.psd.size() - 2);
        EXPECT_NEAR(mean, sigma * sigma * 2.0 / rate, 0.05 * sigma * sigma * 2.0 / rate) << toString(window);
    }
}

TEST(Spectrum, TheDensityIntegratesToTheVariance)
{
    const double rate = 2000.0;
    auto v = whiteNoise(80000, 0.5, 4);
    addSine(v, rate, 123.0, 2.0);
    const Spectrum s = welchSpectrum(v, rate, {SpectralWindow::Hann, 32});
    const double power = std::accumulate(s.psd.begin(), s.psd.end(), 0.0) * s.resolution_hz();
    EXPECT_NEAR(power, 0.25 + 2.0, 0.02 * 2.25);  // σ² + A²/2
}

TEST(Spectrum, AGapIsNeverBridged)
{
    // Two stretches at different levels: a segment across the gap would see
    // a step and spread it over every bin; within stretches the means go.
    const double rate = 1000.0;
    auto v = whiteNoise(40000, 1.0, 5);
    for (std::size_t i = 20000; i < v.size(); ++i) v[i] += 5000.0;
    for (std::size_t i = 19990; i < 20000; ++i) v[i] = std::nan("");
    for (std::size_t i = 30000; i < 30100; ++i) v[i] = std::nan("");
    for (std::size_t i = 30200; i < 30300; ++i) v[i] = std::nan("");  // a stretch of 100: too short
    const Spectrum s = welchSpectrum(v, rate, {SpectralWindow::Hann, 16});
    EXPECT_EQ(s.stretches, 3u);
    EXPECT_EQ(s.stretchesTooShort, 1u);
    for (const double p : s.psd) EXPECT_TRUE(std::isfinite(p));
    const double mean =
        std::accumulate(s.psd.begin() + 1, s.psd.end() - 1, 0.0) / static_cast<double>(s.psd.size() - 2);
    EXPECT_NEAR(mean, 2.0 / rate, 0.1 * 2.0 / rate);
}

TEST(Spectrum, TheSegmentIsAsLongAsTheAveragesAllow)
{
    const std::size_t one[] = {10000};
    EXPECT_EQ(segmentLengthFor(one, 16), 1024u);  // 1024: 18 segments; 2048: 8
    EXPECT_EQ(segmentLengthFor(one, 1), 8192u);
    const std::size_t pieces[] = {3000, 3000, 100};
    EXPECT_EQ(segmentLengthFor(pieces, 4), 1024u);  // 2048 fits once in each long piece; 1024 four times
}

TEST(Spectrum, MainsHumIsFoundWithItsAmplitude)
{
    const double rate = 1000.0;
    for (const double mains : {50.0, 60.0}) {
        auto v = whiteNoise(40000, 2.0, 6);
        addSine(v, rate, mains + 0.07, 7.0);
        addSine(v, rate, 3.0 * mains, 2.0);
        const auto hum = findMainsHum(welchSpectrum(v, rate, {SpectralWindow::Hann, 8}));
        ASSERT_TRUE(hum.has_value());
        EXPECT_EQ(hum->mains_hz, mains);
        EXPECT_NEAR(hum->amplitude, 7.0, 0.02 * 7.0);
    }
    EXPECT_FALSE(findMainsHum(welchSpectrum(whiteNoise(40000, 2.0, 7), rate, {SpectralWindow::Hann, 8})).has_value());
}

TEST(Spectrum, AnAccumulatorResetGivesWhatAFreshOneGives)
{
    // A live spectrum reuses its accumulator frame after frame.
    const double rate = 500.0;
    auto first = whiteNoise(5000, 1.0, 8);
    auto second = whiteNoise(5000, 2.0, 9);
    addSine(second, rate, 60.0, 3.0);
    WelchAccumulator reused(rate, 512, SpectralWindow::Hann);
    reused.push(first);
    reused.reset();
    reused.push(second);
    WelchAccumulator fresh(rate, 512, SpectralWindow::Hann);
    fresh.push(second);
    const Spectrum a = reused.result();
    const Spectrum b = fresh.result();
    EXPECT_EQ(a.averages, b.averages);
    EXPECT_EQ(a.stretches, b.stretches);
    EXPECT_EQ(a.psd, b.psd);
    EXPECT_EQ(a.amplitude, b.amplitude);
}

TEST(Spectrum, AKeptAccumulatorGivesWhatAFreshSpectrumGivesAndIsMadeAgainForAnotherWindow)
{
    // The spectrum view's path: one accumulator kept from call to call.
    const double rate = 500.0;
    auto first = whiteNoise(5000, 1.0, 8);
    auto second = whiteNoise(3000, 2.0, 9);
    addSine(second, rate, 60.0, 3.0);
    std::unique_ptr<WelchAccumulator> kept;
    welchSpectrum(first, rate, {SpectralWindow::Hann, 16}, kept);
    // Another series, then another window (a plan that would be wrong
    // kept), then another segment length: each as a fresh spectrum.
    for (const auto& [values, settings] : {std::pair{&second, SpectrumSettings{SpectralWindow::Hann, 16}},
                                           std::pair{&first, SpectrumSettings{SpectralWindow::FlatTop, 16}},
                                           std::pair{&first, SpectrumSettings{SpectralWindow::FlatTop, 4}}}) {
        const Spectrum a = welchSpectrum(*values, rate, settings, kept);
        const Spectrum b = welchSpectrum(*values, rate, settings);
        EXPECT_EQ(a.segmentLength, b.segmentLength);
        EXPECT_EQ(a.averages, b.averages);
        EXPECT_EQ(a.psd, b.psd);
        EXPECT_EQ(a.amplitude, b.amplitude);
    }
}

TEST(Spectrum, BehindALowPassNoiseIsNoLine)
{
    // Noise low-passed at 100 Hz: the pass band stands far above the stop
    // band, but nothing in it is a line; a real line in it still is.
    const double rate = 1000.0;
    auto noise = whiteNoise(40000, 1.0, 12);
    std::vector<double> smooth(noise.size());
    double state = 0.0;
    for (std::size_t i = 0; i < noise.size(); ++i) smooth[i] = state = 0.5 * state + 0.5 * noise[i];
    for (std::size_t i = 0; i < noise.size(); ++i) smooth[i] = i > 0 ? 0.5 * (smooth[i] + smooth[i - 1]) : smooth[i];
    const Spectrum plain = welchSpectrum(smooth, rate, {SpectralWindow::Hann, 16});
    for (const auto& p : plain.peaks) ADD_FAILURE() << "a line at " << p.frequency_hz << " Hz, " << p.amplitude;
    addSine(smooth, rate, 23.0, 2.0);
    const Spectrum lined = welchSpectrum(smooth, rate, {SpectralWindow::Hann, 16});
    ASSERT_FALSE(lined.peaks.empty());
    EXPECT_NEAR(lined.peaks.front().frequency_hz, 23.0, 0.5);
}
