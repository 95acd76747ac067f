// The strain-gauge chain against hand-computed bridge values.
#include "core/straingauge/StrainGaugeChain.h"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace tactiscope::core::straingauge;

namespace {

StrainGaugeChain chain(BridgeType type)
{
    return StrainGaugeChain(AdcSettings{16, 10.0, true, 200.0}, BridgeSettings{type, 5.0, 2.0});
}

}  // namespace

TEST(StrainGaugeChain, ScalesCountsToBridgeVolts)
{
    // 16 bits bipolar over ±10 V, gain 200: one count is 10/32768/200 V.
    const auto c = chain(BridgeType::HalfBending);
    EXPECT_DOUBLE_EQ(c.bridgeVolts(1.0), 10.0 / 32768.0 / 200.0);
    EXPECT_DOUBLE_EQ(c.counts(c.bridgeVolts(1234.0)), 1234.0);
    EXPECT_DOUBLE_EQ(c.fullScaleCounts(), 32768.0);
    const StrainGaugeChain unipolar(AdcSettings{12, 5.0, false, 1.0}, BridgeSettings{});
    EXPECT_DOUBLE_EQ(unipolar.bridgeVolts(4096.0), 5.0);
}

TEST(StrainGaugeChain, QuarterBridgeIsNonlinearAsItsEquationSays)
{
    // 1000 µε, GF 2: x = 0.002, V_r = x/(4 + 2x) = 0.002/4.004.
    const auto c = chain(BridgeType::Quarter);
    EXPECT_DOUBLE_EQ(c.bridgeRatioForRelativeChange(0.002), 0.002 / 4.004);
    const double counts = c.countsForStrain(1e-3);
    EXPECT_NEAR(c.bridgeRatio(counts), 0.002 / 4.004, 1e-15);
    EXPECT_NEAR(c.strain(counts), 1e-3, 1e-15);
    // The linearised 4·V_r/GF would read 0.1 % low here.
    EXPECT_NEAR(4.0 * c.bridgeRatio(counts) / 2.0, 0.999e-3, 1e-9);
}

TEST(StrainGaugeChain, HalfAndFullBendingBridgesAreLinear)
{
    // 1000 µε, GF 2, 5 V: half bridge V_r = GF·ε/2 = 1e-3 (5 mV), full 2e-3 (10 mV).
    const auto half = chain(BridgeType::HalfBending);
    const auto full = chain(BridgeType::FullBending);
    EXPECT_NEAR(half.bridgeVolts(half.countsForStrain(1e-3)), 5e-3, 1e-15);
    EXPECT_NEAR(full.bridgeVolts(full.countsForStrain(1e-3)), 10e-3, 1e-15);
    EXPECT_NEAR(half.strain(half.countsForStrain(-2.5e-4)), -2.5e-4, 1e-16);
}

TEST(StrainGaugeChain, TareRemovesTheBridgeOffset)
{
    auto c = chain(BridgeType::HalfBending);
    const double offset = 137.0;
    c.tare(offset);
    EXPECT_DOUBLE_EQ(c.strain(offset), 0.0);
    EXPECT_NEAR(c.strain(c.countsForStrain(5e-4, offset)), 5e-4, 1e-16);
}

TEST(StrainGaugeChain, RejectsNonPhysicalSettings)
{
    EXPECT_THROW(StrainGaugeChain(AdcSettings{1, 10.0, true, 1.0}, BridgeSettings{}), std::invalid_argument);
    EXPECT_THROW(StrainGaugeChain(AdcSettings{}, BridgeSettings{BridgeType::Quarter, 0.0, 2.0}), std::invalid_argument);
    EXPECT_THROW(StrainGaugeChain(AdcSettings{}, BridgeSettings{BridgeType::Quarter, 5.0, -2.0}),
                 std::invalid_argument);
}
