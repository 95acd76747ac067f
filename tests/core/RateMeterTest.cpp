// RateMeter: windowed rate from cumulative counts.
#include "core/RateMeter.h"

#include <gtest/gtest.h>

#include <stdexcept>

using tactiscope::core::RateMeter;

TEST(RateMeter, HasNoRateUntilAWindowHasPassed)
{
    RateMeter meter(1.0);
    meter.observe(10.0, 0);
    meter.observe(10.5, 250);
    EXPECT_FALSE(meter.rate_hz().has_value());
}

TEST(RateMeter, ReportsSamplesPerSecondOfTheLastWindow)
{
    RateMeter meter(1.0);
    meter.observe(10.0, 1000);
    meter.observe(11.0, 1500);
    ASSERT_TRUE(meter.rate_hz().has_value());
    EXPECT_DOUBLE_EQ(*meter.rate_hz(), 500.0);
    // The next window is 2 s long with 2000 more samples.
    meter.observe(12.0, 2500);
    meter.observe(13.0, 3500);
    EXPECT_DOUBLE_EQ(*meter.rate_hz(), 1000.0);
}

TEST(RateMeter, ForgetsEverythingOnReset)
{
    RateMeter meter(0.5);
    meter.observe(0.0, 0);
    meter.observe(1.0, 100);
    meter.reset();
    EXPECT_FALSE(meter.rate_hz().has_value());
    meter.observe(5.0, 0);
    meter.observe(5.5, 10);
    EXPECT_DOUBLE_EQ(*meter.rate_hz(), 20.0);
}

TEST(RateMeter, RejectsANonPositiveWindow)
{
    EXPECT_THROW(RateMeter(0.0), std::invalid_argument);
}
