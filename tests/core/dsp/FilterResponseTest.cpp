// The filters against their analytic responses and the figures:
// Butterworth magnitudes from the bilinear transform's closed form, the
// notch on a hummed strain channel, delays, gaps and bit-exact repeats.
#include "SineFit.h"
#include "core/dsp/ButterworthDesign.h"
#include "core/dsp/ChannelFilter.h"
#include "core/dsp/FilterSettings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <random>

using namespace tactiscope::core::dsp;
using tactiscope::testing::fitSines;

namespace {

double decibels(double gain)
{
    return 20.0 * std::log10(gain);
}

// |H|² of a digital Butterworth designed by the pre-warped bilinear transform.
double analyticButterworth(PassBand band, int order, double f, double fc, double fs)
{
    const double ratio = std::tan(std::numbers::pi * f / fs) / std::tan(std::numbers::pi * fc / fs);
    const double x = band == PassBand::Low ? ratio : 1.0 / ratio;
    return 1.0 / std::sqrt(1.0 + std::pow(x, 2 * order));
}

std::vector<double> sines(double rate_hz, std::size_t n, const std::vector<std::pair<double, double>>& parts)
{
    std::vector<double> v(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        for (const auto& [f, a] : parts)
            v[i] += a * std::sin(2.0 * std::numbers::pi * f * static_cast<double>(i) / rate_hz);
    return v;
}

}  // namespace

TEST(FilterResponse, ButterworthMagnitudesFollowTheAnalyticResponse)
{
    for (const PassBand band : {PassBand::Low, PassBand::High}) {
        for (int order = 2; order <= 8; ++order) {
            for (const double fc : {2.0, 20.0, 150.0}) {
                const BiquadCascade filter(butterworth(band, order, fc, 1000.0));
                for (const double f : {0.3 * fc, 0.7 * fc, fc, 1.4 * fc, 2.0 * fc}) {
                    if (f >= 450.0) continue;
                    const double expected = analyticButterworth(band, order, f, fc, 1000.0);
                    EXPECT_NEAR(decibels(std::abs(filter.response(f / 1000.0))), decibels(expected), 0.01)
                        << (band == PassBand::Low ? "low" : "high") << " order " << order << " fc " << fc << " f " << f;
                }
            }
        }
    }
}

TEST(FilterResponse, AFourthOrderLowPassIsThreeDecibelsDownAtItsCutoff)
{
    // Measured in the time domain: a sine at the cut-off through the filter.
    const double rate = 1000.0;
    for (const double fc : {5.0, 40.0, 200.0}) {
        FilterSettings settings;
        settings.lowpass_hz = fc;
        const auto input = sines(rate, 20000, {{fc, 1.0}});
        const auto output = filterSeries(settings, rate, input);
        const double gain = fitSines(output, rate, {fc}, 10000)[0].amplitude;
        EXPECT_NEAR(decibels(gain), -3.0, 0.2) << fc << " Hz";
    }
}

TEST(FilterResponse, TheNotchTakesFortyDecibelsOfHumAndLeavesTheSignal)
{
    // The strain channel: 1 kHz, a 2 Hz signal of 100 µε, 1,000 µε
    // of 50 Hz hum and its 150 Hz harmonic; and the same at 60 Hz at a
    // board's actual rate, not its nominal one.
    for (const auto& [mains, rate] : {std::pair{50.0, 1000.0}, std::pair{60.0, 1000.37}}) {
        const auto input = sines(rate, 20000, {{2.0, 100.0}, {mains, 1000.0}, {3.0 * mains, 300.0}});
        FilterSettings settings;
        settings.notch_hz = mains;
        const auto output = filterSeries(settings, rate, input);
        // After the notch has settled (1/(π·2 Hz) ≈ 0.16 s; 5 s to be sure).
        const auto fitted = fitSines(output, rate, {2.0, mains, 3.0 * mains}, 5000);
        EXPECT_LT(decibels(fitted[1].amplitude / 1000.0), -40.0) << mains;
        EXPECT_LT(decibels(fitted[2].amplitude / 300.0), -40.0) << mains;
        EXPECT_NEAR(fitted[0].amplitude, 100.0, 0.5) << mains;  // ≤ 0.5 % of the 2 Hz amplitude
    }
}

TEST(FilterResponse, ZeroPhaseLeavesTheSignalWhereItWas)
{
    const double rate = 1000.0;
    const auto input = sines(rate, 20000, {{2.0, 100.0}, {50.0, 1000.0}});
    FilterSettings settings;
    settings.notch_hz = 50.0;
    settings.lowpass_hz = 20.0;
    settings.zeroPhase = true;
    const auto output = filterSeries(settings, rate, input);
    const auto before = fitSines(input, rate, {2.0}, 2000)[0];
    const auto after = fitSines(std::span(output).first(18000), rate, {2.0}, 2000)[0];
    EXPECT_NEAR(after.phase, before.phase, 1e-3);
    EXPECT_NEAR(after.amplitude, 100.0, 0.5);
    EXPECT_EQ(ChannelFilter(settings, rate).delay_s(), 0.0);
}

TEST(FilterResponse, TheDelayShownIsHowFarARampLags)
{
    // A slow ramp through a low-pass comes out shifted by the DC group delay.
    const double rate = 500.0;
    for (const auto& [lowpass, average] : {std::pair{10.0, 0.0}, std::pair{25.0, 0.02}}) {
        FilterSettings settings;
        settings.lowpass_hz = lowpass;
        settings.movingAverage_s = average;
        std::vector<double> ramp(5000);
        for (std::size_t i = 0; i < ramp.size(); ++i) ramp[i] = static_cast<double>(i) / rate;
        ChannelFilter filter(settings, rate);
        std::vector<double> out = ramp;
        filter.process(out);
        const double lag = ramp.back() - out.back();
        EXPECT_NEAR(filter.delay_s(), lag, 1e-6) << lowpass;
    }
}

TEST(FilterResponse, AGapRestartsTheFilterAndStaysAGap)
{
    const double rate = 1000.0;
    auto values = sines(rate, 4000, {{3.0, 10.0}, {50.0, 50.0}});
    for (std::size_t i = 1500; i < 1600; ++i) values[i] = std::nan("");
    FilterSettings settings;
    settings.notch_hz = 50.0;
    settings.lowpass_hz = 30.0;
    const auto output = filterSeries(settings, rate, values);
    for (std::size_t i = 1500; i < 1600; ++i) EXPECT_TRUE(std::isnan(output[i]));
    // After the gap it is a fresh filter's output on the rest.
    const auto fresh = filterSeries(settings, rate, std::span(values).subspan(1600));
    for (std::size_t i = 0; i < fresh.size(); ++i) ASSERT_EQ(output[1600 + i], fresh[i]) << i;
}

TEST(FilterResponse, BlocksOfAnySizeGiveTheSameBits)
{
    // Live filtering comes in blocks; re-analysis runs the whole session.
    const double rate = 2000.0;
    std::mt19937 random(5);
    std::normal_distribution<double> noise(0.0, 3.0);
    std::vector<double> values(30000);
    for (std::size_t i = 0; i < values.size(); ++i)
        values[i] = 200.0 * std::sin(static_cast<double>(i) * 0.01) + noise(random);
    FilterSettings settings;
    settings.notch_hz = 60.0;
    settings.highpass_hz = 0.5;
    settings.lowpass_hz = 100.0;
    settings.order = 6;
    settings.movingAverage_s = 0.005;
    const auto whole = filterSeries(settings, rate, values);
    ChannelFilter live(settings, rate);
    std::uniform_int_distribution<std::size_t> blockSize(1, 700);
    std::vector<double> streamed;
    for (std::size_t at = 0; at < values.size();) {
        const std::size_t n = std::min(blockSize(random), values.size() - at);
        std::vector<double> block(values.begin() + static_cast<std::ptrdiff_t>(at),
                                  values.begin() + static_cast<std::ptrdiff_t>(at + n));
        live.process(block);
        streamed.insert(streamed.end(), block.begin(), block.end());
        at += n;
    }
    ASSERT_EQ(streamed.size(), whole.size());
    EXPECT_EQ(std::memcmp(streamed.data(), whole.data(), whole.size() * sizeof(double)), 0);
}

TEST(FilterResponse, TheMovingAverageIsTheMeanOfTheLastSamples)
{
    std::mt19937 random(9);
    std::uniform_real_distribution<double> value(-1e3, 1e3);
    std::vector<double> values(100000);
    for (double& v : values) v = 5e6 + value(random);  // a large offset, as a raw bridge has
    FilterSettings settings;
    settings.movingAverage_s = 0.037;  // 37 samples at 1 kHz
    const auto output = filterSeries(settings, 1000.0, values);
    for (std::size_t i = 36; i < values.size(); i += 997) {
        double sum = 0.0;
        for (std::size_t j = i - 36; j <= i; ++j) sum += values[j];
        EXPECT_NEAR(output[i], sum / 37.0, 1e-8) << i;
    }
}

TEST(FilterResponse, SettingsOutsideWhatCanBeBuiltAreRefusedInWords)
{
    FilterSettings settings;
    settings.notch_hz = 55.0;
    EXPECT_NE(filterRefusal(settings, 1000.0).value_or("").find("50 or 60"), std::string::npos);
    settings = {};
    settings.lowpass_hz = 300.0;
    EXPECT_NE(filterRefusal(settings, 500.0).value_or("").find("0.45"), std::string::npos);
    settings.order = 9;
    settings.lowpass_hz = 10.0;
    EXPECT_NE(filterRefusal(settings, 500.0).value_or("").find("2 to 8"), std::string::npos);
    settings = {};
    settings.highpass_hz = 20.0;
    settings.lowpass_hz = 10.0;
    EXPECT_NE(filterRefusal(settings, 500.0).value_or("").find("below"), std::string::npos);
    settings = {};
    settings.notch_hz = 60.0;
    EXPECT_TRUE(filterRefusal(settings, 100.0).has_value());  // 60 Hz is beyond 0.45 × 100 Hz
    EXPECT_THROW(ChannelFilter(settings, 100.0), std::invalid_argument);
}

TEST(FilterResponse, SettingsSayWhatTheyAre)
{
    FilterSettings settings;
    EXPECT_EQ(settings.text(), "none");
    settings.notch_hz = 50.0;
    settings.lowpass_hz = 20.0;
    settings.order = 6;
    EXPECT_EQ(settings.text(), "mains notch 50 Hz and harmonics, low-pass 20 Hz (Butterworth, order 6)");
    settings.highpass_hz = 0.5;
    settings.movingAverage_s = 0.01;
    settings.zeroPhase = true;
    EXPECT_EQ(settings.text(), "mains notch 50 Hz and harmonics, band-pass 0.5–20 Hz (Butterworth, order 6), "
                               "moving average 10 ms, zero-phase");
}
