// Drift of a sensor's calibrations over time, worked by hand.
#include "core/calibration/CalibrationDrift.h"

#include <gtest/gtest.h>

#include <vector>

using namespace tactiscope::core::calibration;

TEST(CalibrationDrift, SpreadChangeAndTrendPerYear)
{
    // Gauge factors 2.10, 2.12, 2.14 half a year apart, given out of order:
    // mean 2.12, SD 0.02, +1.905 % from the first, 0.04 per year.
    constexpr double halfYear = 0.5 * 365.25 * 86400.0;
    const std::vector<double> t{halfYear, 0.0, 2 * halfYear};
    const std::vector<double> gf{2.12, 2.10, 2.14};
    const DriftSummary d = summarizeDrift(t, gf);
    EXPECT_EQ(d.count, 3u);
    EXPECT_NEAR(d.mean, 2.12, 1e-12);
    EXPECT_NEAR(d.standardDeviation, 0.02, 1e-12);
    EXPECT_NEAR(d.firstToLast, 0.04 / 2.10, 1e-12);
    ASSERT_TRUE(d.trendPerYear);
    EXPECT_NEAR(*d.trendPerYear, 0.04, 1e-12);
}

TEST(CalibrationDrift, OneRecordHasNoSpreadAndNoTrend)
{
    const std::vector<double> t{100.0};
    const std::vector<double> v{1.8};
    const DriftSummary d = summarizeDrift(t, v);
    EXPECT_EQ(d.standardDeviation, 0.0);
    EXPECT_EQ(d.firstToLast, 0.0);
    EXPECT_FALSE(d.trendPerYear);
    EXPECT_THROW(summarizeDrift({}, {}), std::invalid_argument);
}
