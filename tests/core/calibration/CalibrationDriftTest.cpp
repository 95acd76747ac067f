// Drift of a sensor's calibrations over time, worked by hand, and the
// trend's stated uncertainty tested as a statistic over many seeds.
#include "core/calibration/CalibrationDrift.h"

#include "support/Coverage.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

using namespace tactiscope::core::calibration;

namespace {

constexpr double kDay_s = 86400.0;
constexpr double kYear_s = 365.25 * kDay_s;

}  // namespace

TEST(CalibrationDrift, SpreadAndChangeFromTheFirst)
{
    // Gauge factors 2.10, 2.12, 2.14 half a year apart, given out of order:
    // mean 2.12, SD 0.02, +1.905 % from the first; three records are too
    // few for a trend.
    const std::vector<double> t{0.5 * kYear_s, 0.0, kYear_s};
    const std::vector<double> gf{2.12, 2.10, 2.14};
    const DriftSummary d = summarizeDrift(t, gf);
    EXPECT_EQ(d.count, 3u);
    EXPECT_NEAR(d.mean, 2.12, 1e-12);
    EXPECT_NEAR(d.standardDeviation, 0.02, 1e-12);
    EXPECT_NEAR(d.firstToLast, 0.04 / 2.10, 1e-12);
    EXPECT_DOUBLE_EQ(d.span_s, kYear_s);
    EXPECT_FALSE(d.trend);
}

TEST(CalibrationDrift, TenRecordsOverAYearOnALineHaveItsSlopeAndNoUncertainty)
{
    // 2.10 rising 0.04 a year, a record every 40 days.
    std::vector<double> t, gf;
    for (int i = 0; i < 10; ++i) {
        t.push_back(40.0 * kDay_s * i);
        gf.push_back(2.10 + 0.04 * t.back() / kYear_s);
    }
    const DriftSummary d = summarizeDrift(t, gf);
    ASSERT_TRUE(d.trend);
    EXPECT_NEAR(d.trend->perYear, 0.04, 1e-9);
    EXPECT_NEAR(d.trend->uncertaintyPerYear, 0.0, 1e-9);
}

// Issue 52: two records 19 minutes apart drew "trend -21.4653 per year".
TEST(CalibrationDrift, RecordsMinutesApartOrTooFewHaveNoTrend)
{
    const DriftSummary minutes = summarizeDrift(std::vector<double>{0.0, 19 * 60.0}, std::vector<double>{2.10, 2.09});
    EXPECT_FALSE(minutes.trend);
    EXPECT_DOUBLE_EQ(minutes.span_s, 19 * 60.0);
    // Ten records, but within a day: a slope, not a trend.
    std::vector<double> t, v;
    for (int i = 0; i < 10; ++i) {
        t.push_back(3600.0 * i);
        v.push_back(2.1 + 0.001 * i);
    }
    EXPECT_FALSE(summarizeDrift(t, v).trend);
}

TEST(CalibrationDrift, OneRecordHasNoSpreadAndNoTrend)
{
    const std::vector<double> t{100.0};
    const std::vector<double> v{1.8};
    const DriftSummary d = summarizeDrift(t, v);
    EXPECT_EQ(d.standardDeviation, 0.0);
    EXPECT_EQ(d.firstToLast, 0.0);
    EXPECT_FALSE(d.trend);
    EXPECT_THROW(summarizeDrift({}, {}), std::invalid_argument);
}

// The trend's ± over 200 sensors: ten calibrations at uneven times over a
// year and a half, each off by Gaussian noise (σ 0.01) from a true drift of
// −0.03 a year.
TEST(CalibrationDrift, TheTrendsUncertaintyCoversTheTrueDriftAsStated)
{
    tactiscope::testing::Coverage coverage;
    for (unsigned seed = 1; seed <= 200; ++seed) {
        std::mt19937_64 random(seed);
        std::uniform_real_distribution<double> when(0.0, 1.5 * kYear_s);
        std::normal_distribution<double> noise(0.0, 0.01);
        std::vector<double> t{0.0, 1.5 * kYear_s}, v;
        while (t.size() < 10) t.push_back(when(random));
        for (const double at : t) v.push_back(2.0 - 0.03 * at / kYear_s + noise(random));
        const auto trend = summarizeDrift(t, v).trend;
        ASSERT_TRUE(trend);
        coverage.add(trend->perYear + 0.03, trend->uncertaintyPerYear);
    }
    EXPECT_TRUE(coverage.isGaussian());
}
