// One simulated world: the gauge-factor rig clamps the very beams the
// palpation phantom is pressed with (devices/simulator/SimulatedProbe.h).
// Each beam is calibrated on its rig as the wizard does (the settled mean
// of each hung mass, calibrateGaugeFactor), and the 117 N/m phantom is then
// read through those calibrations: every press reads 117 N/m within 2u,
// and the forces are the probe's true ones. One beam calibrated alone skews
// the force ratio and is said to.
#include "core/SampleBlock.h"
#include "core/calibration/CalibrationRecord.h"
#include "core/calibration/GaugeFactorCalibration.h"
#include "core/compliance/LivePalpation.h"
#include "core/compliance/PalpationForces.h"
#include "core/sensors/BuiltInProfiles.h"
#include "devices/simulator/GaugeCalibrationScenario.h"
#include "devices/simulator/PalpationScenario.h"

#include <gtest/gtest.h>

#include <numeric>

using namespace tactiscope;

namespace {

constexpr double kTruth_n_per_m = 117.0;

core::sensors::CompliancePairProfile probe()
{
    return std::get<core::sensors::CompliancePairProfile>(*core::sensors::builtInProfile(core::Mode::Palpation));
}

// The settled counts of the rig under `load_n`: hung, waited for 1 s (over
// six settling times), then averaged over 0.5 s.
double settledCounts(devices::simulator::GaugeCalibrationScenario& rig, double load_n)
{
    rig.loadRig()->place(load_n);
    const double rate = rig.sampleRate_hz();
    core::SampleBlock block(1, static_cast<std::size_t>(1.5 * rate), 0.0, 1.0 / rate);
    rig.generate(block);
    const auto counts = block.channel(0);
    const auto settled = counts.subspan(static_cast<std::size_t>(1.0 * rate));
    return std::accumulate(settled.begin(), settled.end(), 0.0) / static_cast<double>(settled.size());
}

core::calibration::CalibrationRecord calibrateOnTheRig(bool softBeam)
{
    devices::simulator::GaugeCalibrationParameters p;
    p.softBeam = softBeam;
    p.seed = 5;
    devices::simulator::GaugeCalibrationScenario rig(p);
    const auto& profile = probe();
    const core::straingauge::StrainGaugeChain nominal(p.adc, p.bridge);
    const double zero = settledCounts(rig, 0.0);
    std::vector<core::calibration::CalibrationLoad> loads;
    // Masses that keep each beam in its ADC's range: the soft one is 9× as strained.
    for (const double grams : softBeam ? std::vector{5.0, 10.0, 20.0, 40.0} : std::vector{20.0, 50.0, 100.0, 200.0}) {
        const double force = grams * 1e-3 * core::calibration::kStandardGravity_m_per_s2;
        loads.push_back({force, 0.0, settledCounts(rig, force)});
    }
    const core::sensors::CantileverBeam beam(softBeam ? profile.low : profile.high);
    auto result = core::calibration::calibrateGaugeFactor(
        beam, nominal, {zero}, loads, core::calibration::beamSensorName(profile.name, !softBeam), "tester");
    EXPECT_NEAR(result.gaugeFactor, devices::simulator::kProbeTrueGaugeFactor, 0.005) << (softBeam ? "soft" : "stiff");
    result.record.timestampUtc = "2026-11-25T08:00:00Z";
    return result.record;
}

// The phantom's presses read live through `records`, fed as the acquisition does.
std::vector<core::compliance::PressReading> palpate(const std::vector<core::calibration::CalibrationRecord>& records,
                                                    std::optional<std::string>* warning = nullptr)
{
    devices::simulator::PalpationParameters p;
    p.objectStiffness_n_per_m = kTruth_n_per_m;
    p.seed = 17;
    devices::simulator::PalpationScenario scenario(p);
    const auto settings = core::compliance::palpationSettings(probe(), p.sampleRate_hz, scenario.channels(), records);
    core::compliance::LivePalpation live(scenario.channels(), p.sampleRate_hz, settings, 2.0);
    if (warning) *warning = live.mixedCalibrationWarning();
    std::vector<core::compliance::PressReading> readings;
    std::uint64_t index = 0;
    for (int block = 0; block < 400; ++block) {  // 20 s in 50 ms blocks: four presses
        core::SampleBlock samples(3, 50, static_cast<double>(index) / p.sampleRate_hz, 1.0 / p.sampleRate_hz, index);
        scenario.generate(samples);
        live.consume(samples);
        index += 50;
        for (auto& r : live.takeReadings()) readings.push_back(std::move(r));
    }
    return readings;
}

}  // namespace

TEST(OneSimulatedWorld, CalibratedOnTheRigThePhantomReadsItsTrueStiffness)
{
    const std::vector records{calibrateOnTheRig(false), calibrateOnTheRig(true)};
    std::optional<std::string> warning;
    const auto readings = palpate(records, &warning);
    EXPECT_FALSE(warning);
    ASSERT_GE(readings.size(), 3u);
    for (const auto& r : readings) {
        ASSERT_EQ(r.stiffness.range, core::sensors::ComplianceRange::InRange);
        EXPECT_NEAR(r.stiffness.objectStiffness_n_per_m, kTruth_n_per_m, 2.0 * r.uncertainty_n_per_m())
            << "press at " << r.start_s << " s, u " << r.uncertainty_n_per_m();
    }
}

TEST(OneSimulatedWorld, OneBeamCalibratedAloneSkewsTheRatioAndIsSaidTo)
{
    std::optional<std::string> warning;
    const auto readings = palpate({calibrateOnTheRig(false)}, &warning);
    ASSERT_TRUE(warning);
    EXPECT_NE(warning->find("only the stiff beam"), std::string::npos) << *warning;
    ASSERT_FALSE(readings.empty());
    // The soft beam's 7 % gauge error is all in the ratio now.
    EXPECT_GT(std::abs(readings.front().stiffness.objectStiffness_n_per_m - kTruth_n_per_m), 0.05 * kTruth_n_per_m);
}
