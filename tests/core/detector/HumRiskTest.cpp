// The hum the detector is warned of: a line of twice the gauges' noise or
// more that no notch at its frequency took out, judged on health figures
// built here (white noise of σ has a floor of σ/√(f_s/2) per √Hz).
#include "core/detector/HumRisk.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace tactiscope::core;

namespace {

constexpr double kRate_hz = 500.0;

dsp::ChannelHealth hummed(double mains_hz, double amplitude, double sigma)
{
    dsp::ChannelHealth health;
    if (amplitude > 0.0) health.hum = dsp::MainsHum{mains_hz, mains_hz, amplitude};
    health.noiseFloor_per_sqrt_hz = sigma / std::sqrt(kRate_hz / 2.0);
    return health;
}

}  // namespace

TEST(HumRisk, AHumOverTwiceTheNoiseIsARiskUnlessANotchAtItsFrequencyTookItOut)
{
    const std::vector<std::string> names{"a", "b"};
    // 25 and 15 µε of 50 Hz on 0.5 µε of noise: a is the worse.
    const std::vector health{hummed(50.0, 25e-6, 0.5e-6), hummed(50.0, 15e-6, 0.5e-6)};
    const auto risk = detector::detectorHumRisk(names, health, kRate_hz, std::nullopt);
    ASSERT_TRUE(risk);
    EXPECT_EQ(risk->channel, "a");
    EXPECT_EQ(risk->mains_hz, 50.0);
    EXPECT_NEAR(risk->noise, 0.5e-6, 1e-12);
    EXPECT_FALSE(detector::detectorHumRisk(names, health, kRate_hz, 50.0)) << "the notch took it out";
    EXPECT_TRUE(detector::detectorHumRisk(names, health, kRate_hz, 60.0)) << "a 60 Hz notch leaves 50 Hz hum";
    // At the noise's level, or none at all: no risk (docs/detector.md: 0.5 µε over 0.5 µε loses nothing).
    EXPECT_FALSE(detector::detectorHumRisk({"a"}, {hummed(50.0, 0.9e-6, 0.5e-6)}, kRate_hz, std::nullopt));
    EXPECT_TRUE(detector::detectorHumRisk({"a"}, {hummed(50.0, 1.1e-6, 0.5e-6)}, kRate_hz, std::nullopt));
    EXPECT_FALSE(detector::detectorHumRisk({"a"}, {hummed(50.0, 0.0, 0.5e-6)}, kRate_hz, std::nullopt));
}

TEST(HumRisk, ItsTextNamesTheChannelTheAmountAndTheNotchThatLeftIt)
{
    const detector::HumRisk risk{"a", 50.0, 25e-6, 0.5e-6};
    EXPECT_EQ(detector::humRiskText(risk, std::nullopt, 1e6, "µε"),
              "a carries 25 µε of 50 Hz hum, 50 times its noise, which the detector read without a notch: it loses "
              "crossings under such a hum (docs/detector.md, \"Under mains hum\")");
    EXPECT_EQ(detector::humRiskText(risk, 60.0, 1.0, ""),
              "a carries 50 Hz hum, 50 times its noise, which the 60 Hz notch leaves: the detector loses crossings "
              "under such a hum (docs/detector.md, \"Under mains hum\")");
}
