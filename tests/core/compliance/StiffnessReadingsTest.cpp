// Step and press readings of the compliance probe on synthetic forces
// computed from the model with a known object stiffness.
#include "core/compliance/StiffnessReadings.h"

#include <gtest/gtest.h>

#include <random>

using namespace tactiscope::core;
using compliance::PressReader;
using compliance::StepReader;
using sensors::ComplianceRange;

namespace {

sensors::CompliancePair paperSensor()
{
    return sensors::CompliancePair(sensors::CantileverBeam({0.05, 0.01, 0.003, 3e9}),
                                   sensors::CantileverBeam({0.05, 0.01, 0.001, 3e9}));
}

// Forces on each beam pressed by x into an object of stiffness k (series springs).
std::pair<double, double> forces(double x, double k)
{
    return {x * 1620.0 * k / (1620.0 + k), x * 60.0 * k / (60.0 + k)};
}

}  // namespace

TEST(StepReader, AveragesAThousandReadingsAndRejectsSpikes)
{
    StepReader reader(paperSensor(), 1000);
    std::mt19937 random(1);
    std::normal_distribution<double> noise(0.0, 0.002);
    const auto [fh, fl] = forces(0.004, 174.0);
    std::optional<compliance::StepReading> reading;
    for (int i = 0; i < 1000; ++i) {
        const double spike = i % 250 == 0 ? 1.0 : 0.0;  // four electrical spikes
        reading = reader.push(fh + noise(random) + spike, fl + noise(random));
        if (i < 999) {
            EXPECT_FALSE(reading.has_value());
        }
    }
    ASSERT_TRUE(reading.has_value());
    EXPECT_GE(reading->forceHigh.rejected, 4u);
    ASSERT_EQ(reading->stiffness.range, ComplianceRange::InRange);
    EXPECT_NEAR(reading->stiffness.objectStiffness_n_per_m, 174.0, 0.01 * 174.0);
    EXPECT_EQ(reader.collected(), 0u);
}

TEST(PressReader, APressGivesTheObjectStiffnessIndependentOfDepth)
{
    PressReader reader(paperSensor(), {0.01, 20});
    std::optional<compliance::PressReading> reading;
    double t = 0.0;
    // In to 6 mm and out again to −1 mm, 1 ms steps, exact forces.
    for (int i = -100; i <= 1300; ++i, t += 0.001) {
        const double x = (i <= 600 ? i : 1200 - i) * 1e-5;
        const auto [fh, fl] = forces(std::max(x, 0.0), 117.0);
        if (auto r = reader.push(t, x, fh, fl)) reading = r;
    }
    for (int i = 0; i < 100 && !reading; ++i, t += 0.001) reading = reader.push(t, -0.001, 0.0, 0.0);
    ASSERT_TRUE(reading.has_value());
    ASSERT_EQ(reading->stiffness.range, ComplianceRange::InRange);
    EXPECT_NEAR(reading->stiffness.objectStiffness_n_per_m, 117.0, 1e-6);
    EXPECT_NEAR(reading->displacementSlope_n_per_m_per_m, 0.0, 1e-3);
    EXPECT_NEAR(reading->displacementMax_m, 0.006, 1e-12);
    EXPECT_GT(reading->samplesUsed, 1000u);
    EXPECT_FALSE(reader.pressing());
}

TEST(PressReader, ShowsTheRunningValueWhilePressingAndIgnoresTaps)
{
    PressReader reader(paperSensor(), {0.01, 50});
    const auto [fh, fl] = forces(0.003, 60.0);
    for (int i = 0; i < 10; ++i) EXPECT_FALSE(reader.push(i * 0.001, 0.003, fh, fl).has_value());
    ASSERT_TRUE(reader.current().has_value());
    EXPECT_NEAR(reader.current()->first, 60.0, 1e-9);
    // Released after 10 samples: a tap, no reading.
    EXPECT_FALSE(reader.push(0.011, -0.001, 0.0, 0.0).has_value());
    EXPECT_FALSE(reader.finish().has_value());
}

TEST(PressReader, AnObjectStifferThanTheRangeIsReportedAsAbove)
{
    PressReader reader(paperSensor(), {0.01, 20});
    for (int i = 0; i < 100; ++i) reader.push(i * 0.001, 0.002, 30.0, 1.0);  // Q = 30 > 27
    const auto reading = reader.finish();
    ASSERT_TRUE(reading.has_value());
    EXPECT_EQ(reading->stiffness.range, ComplianceRange::Above);
    EXPECT_EQ(reading->samplesOutOfRange, 100u);
}
