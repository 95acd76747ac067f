// The elastica against the classical tip-loaded uniform cantilever, and the
// capacitive beam's limits and the compliance probe's ADC limits against
// values computed independently: the uniform beam's tip deflection from
// Bisshopp & Drucker (1945), F·l²/EI = 1 → 0.3017·l and 2 → 0.4935·l
// (also by a separate RK2 shooting script, 20 000 steps: 0.301721,
// 0.493457); the paper's sensor No. 1 (l = 15 mm, α = 0.6, A₁ = 9.98016e-5,
// A₂ = 9.18421e-5 N·m per m of width) by that script: at 1 mN the linear
// model overstates the deflection by 5.440 %, and it does so by 2 % at
// 0.5971572 mN and by 5 % at 0.9568554 mN.
#include "core/sensors/LargeDeflection.h"
#include "core/sensors/BuiltInProfiles.h"
#include "core/sensors/SensorLimits.h"

#include <gtest/gtest.h>

#include <variant>

using namespace tactiscope::core;
using namespace tactiscope::core::sensors;

namespace {

const CapacitiveBeamProfile& paperBeam()
{
    static const auto profile = builtInProfile(Mode::Capacitive);
    return std::get<CapacitiveBeamProfile>(*profile);
}

}  // namespace

TEST(LargeDeflection, AUniformCantileverDeflectsAsBisshoppAndDruckerFound)
{
    const BendingStiffness uniform = [](double) { return 1.0; };
    const auto one = tipDeflection(uniform, 1.0, 1.0);
    EXPECT_NEAR(one.linear_m, 1.0 / 3.0, 1e-7);
    EXPECT_NEAR(one.exact_m, 0.301721, 2e-5);
    EXPECT_NEAR(tipDeflection(uniform, 1.0, 2.0).exact_m, 0.493457, 2e-5);
    // Small loads: the two agree.
    EXPECT_NEAR(tipDeflection(uniform, 1.0, 1e-4).modelError(), 0.0, 1e-6);
    EXPECT_THROW(tipDeflection(uniform, 1.0, 0.0), std::invalid_argument);
    EXPECT_THROW(tipDeflection(uniform, -1.0, 1.0), std::invalid_argument);
}

TEST(LargeDeflection, ThePaperBeamsLinearModelHoldsToTwoPercentBelowSixTenthsOfAMillinewton)
{
    const CapacitiveBeam beam(paperBeam().geometry);
    const auto stiffness = bendingStiffness(beam);
    const double length_m = paperBeam().geometry.beam.length_m;
    const auto at1mN = tipDeflection(stiffness, length_m, 1e-3);
    // The linear part is the model's own closed form (eq. 28).
    EXPECT_NEAR(at1mN.linear_m, 1e-3 * beam.tipDeflectionPerNewton_m(), 1e-9);
    EXPECT_NEAR(at1mN.modelError(), 0.05440, 2e-4);
    EXPECT_NEAR(forceAtModelError(stiffness, length_m, 0.02), 0.5971572e-3, 1e-3 * 0.5971572e-3);
    EXPECT_NEAR(forceAtModelError(stiffness, length_m, 0.05), 0.9568554e-3, 1e-3 * 0.9568554e-3);
    EXPECT_THROW(forceAtModelError(stiffness, length_m, 0.0), std::invalid_argument);
}

TEST(SensorLimits, TheCapacitiveBeamWarnsAndIsCriticalWhereItsModelStopsHolding)
{
    const SensorProfile profile = paperBeam();
    const auto limits = modelLimits(profile, {});
    ASSERT_EQ(limits.size(), 1u);
    EXPECT_EQ(limits[0].limit.quantity, "force");
    EXPECT_EQ(limits[0].limit.side, trigger::LimitSide::Above);
    // Three digits, towards zero: never later than the model.
    EXPECT_DOUBLE_EQ(limits[0].limit.warning->low, 0.000597);
    EXPECT_DOUBLE_EQ(limits[0].limit.critical->low, 0.000956);
    EXPECT_NE(limits[0].basis.find("small-deflection"), std::string::npos);
}

TEST(SensorLimits, TheStiffBeamInCountsIsWatchedAtItsAdcsRangeEitherWay)
{
    const auto profile = builtInProfile(Mode::Palpation);
    std::vector<ChannelDescriptor> channels{{"high", "counts", ChannelKind::Other},
                                            {"low", "counts", ChannelKind::Other},
                                            {"x", "m", ChannelKind::Position}};
    channels[0].role = ChannelRole::StiffBeam;
    channels[1].role = ChannelRole::SoftBeam;
    channels[2].role = ChannelRole::Displacement;
    // A 16-bit bipolar ADC: full scale 32768 counts; 90 % and 99 % of it,
    // either sign: one window.
    const auto limits = modelLimits(*profile, channels);
    ASSERT_EQ(limits.size(), 1u);
    EXPECT_EQ(limits[0].limit.text(), "high outside warning:-29491..29491,critical:-32440..32440");
    // A unipolar 12-bit one: 4096 counts, one side.
    straingauge::AdcSettings adc;
    adc.bits = 12;
    adc.bipolar = false;
    const auto unipolar = modelLimits(*profile, channels, adc);
    ASSERT_EQ(unipolar.size(), 1u);
    EXPECT_EQ(unipolar[0].limit.text(), "high>warning:3686,critical:4055");
    // A board's range its profile declares, about its offset: a 12-bit
    // converter centred on 2048 counts.
    auto board = std::get<CompliancePairProfile>(*profile);
    board.channels.emplace("high", ChannelScale{"N", 200.0, 2048.0, 2048.0});
    const auto centred = modelLimits(board, channels);
    ASSERT_EQ(centred.size(), 1u);
    EXPECT_EQ(centred[0].limit.text(), "high outside warning:205..3891,critical:21..4075");
    // Beams sending force or strain have no ADC range known: no limit.
    channels[0].unit = "N";
    EXPECT_TRUE(modelLimits(*profile, channels).empty());
}

TEST(SensorLimits, AProfilesOwnLimitsReplaceTheModelsAndAnEmptyListMeansNone)
{
    auto probe = paperBeam();
    probe.limits = std::vector<trigger::LimitSpec>{*trigger::parseLimit("force>warning:0.0004").limit};
    auto limits = profileLimits(probe, {});
    ASSERT_EQ(limits.size(), 1u);
    EXPECT_EQ(limits[0].limit.warning, 0.0004);
    EXPECT_FALSE(limits[0].limit.critical);
    EXPECT_EQ(limits[0].basis, "the sensor profile's");
    probe.limits = std::vector<trigger::LimitSpec>{};
    EXPECT_TRUE(profileLimits(probe, {}).empty());
    probe.limits.reset();
    EXPECT_EQ(profileLimits(probe, {}).size(), 1u);  // the model's

    // Through the profile's JSON and back; a limit that does not read is refused.
    probe.limits = std::vector<trigger::LimitSpec>{*trigger::parseLimit("force>warning:0.0004,critical:0.0007").limit};
    const auto again = std::get<CapacitiveBeamProfile>(parseSensorProfile(toJson(probe), "test"));
    ASSERT_TRUE(again.limits);
    ASSERT_EQ(again.limits->size(), 1u);
    EXPECT_EQ(again.limits->front().warning, 0.0004);
    EXPECT_EQ(again.limits->front().critical, 0.0007);
    auto text = toJson(probe);
    text.replace(text.find("warning:"), 8, "warming:");
    EXPECT_THROW(parseSensorProfile(text, "test"), ProfileError);
}
