// A palpation board's scales: its displacement printed as plain numbers
// (millimetres, an encoder's counts) is read through its profile's length
// scale, and refused without one, naming the channel and how to give it; a
// beam's offset centres its clipping, a beam in a length is refused, and
// one without a full scale is said to have no clipping judged.
#include "core/compliance/PalpationForces.h"

#include "core/sensors/BuiltInProfiles.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <variant>

using namespace tactiscope::core;

namespace {

compliance::LivePalpationSettings settingsWith(sensors::ChannelScales scales)
{
    const auto probe = std::get<sensors::CompliancePairProfile>(*sensors::builtInProfile(Mode::Palpation));
    compliance::LivePalpationSettings settings;
    settings.high = probe.high;
    settings.low = probe.low;
    settings.scales = std::move(scales);
    settings.highInput = settings.lowInput = compliance::BeamInput::ProfileScale;
    return settings;
}

const std::vector<ChannelDescriptor> kCounts{{"stiff", "counts", ChannelKind::Other, ChannelRole::StiffBeam},
                                             {"soft", "counts", ChannelKind::Other, ChannelRole::SoftBeam},
                                             {"d", "counts", ChannelKind::Other, ChannelRole::Displacement}};

}  // namespace

TEST(PalpationForces, ADisplacementInCountsIsReadThroughItsProfilesLengthScale)
{
    const sensors::ChannelScales beams{{"stiff", {"N", 200.0, 32768.0}}, {"soft", {"N", 50.0, 32768.0}}};
    auto millimetres = beams;
    millimetres.emplace("d", sensors::ChannelScale{"mm", 1.0, std::nullopt});
    EXPECT_DOUBLE_EQ(compliance::PalpationForces(kCounts, settingsWith(millimetres)).displacement_m(2.5), 2.5e-3);
    auto encoder = beams;  // 400 counts a millimetre
    encoder.emplace("d", sensors::ChannelScale{"mm", 400.0, std::nullopt});
    EXPECT_DOUBLE_EQ(compliance::PalpationForces(kCounts, settingsWith(encoder)).displacement_m(1000.0), 2.5e-3);
    auto centred = beams;  // a unipolar converter's: 2048 counts at zero
    centred.emplace("d", sensors::ChannelScale{"mm", 400.0, std::nullopt, 2048.0});
    EXPECT_DOUBLE_EQ(compliance::PalpationForces(kCounts, settingsWith(centred)).displacement_m(1048.0), -2.5e-3);
    // A length channel is in metres already.
    auto inMetres = kCounts;
    inMetres[2] = {"d", "m", ChannelKind::Position, ChannelRole::Displacement};
    EXPECT_DOUBLE_EQ(compliance::PalpationForces(inMetres, settingsWith(beams)).displacement_m(0.004), 0.004);
    try {
        compliance::PalpationForces(kCounts, settingsWith(beams));
        ADD_FAILURE() << "counts without a length scale were read";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()), "the displacement d is in counts and the sensor profile gives it no length "
                                         "scale (\"channels\": {\"d\": {\"unit\": \"mm\"}})");
    }
}

// A beam on a unipolar converter (0 to 4095, 2048 at no force) clips at
// either end of its range: |count − offset| within 1 % of the full scale.
// Its force is measured from the zero, whatever the offset.
TEST(PalpationForces, ABeamsOffsetCentresItsClippingAndChangesNoForce)
{
    const sensors::ChannelScales scales{{"stiff", {"N", 200.0, 2048.0, 2048.0}},
                                        {"soft", {"N", 50.0, 2048.0, 2048.0}},
                                        {"d", {"mm", 1.0, std::nullopt}}};
    compliance::PalpationForces forces(kCounts, settingsWith(scales));
    for (const double clipped : {4095.0, 0.0, 20.0, 4076.0}) EXPECT_TRUE(forces.atLimit(true, clipped)) << clipped;
    for (const double inRange : {2048.0, 4000.0, 100.0}) EXPECT_FALSE(forces.atLimit(true, inRange)) << inRange;
    forces.setZero({2050.0, 2040.0, std::nullopt});
    EXPECT_DOUBLE_EQ(forces.forceHigh(2250.0), 1.0);  // 200 counts a newton above its zero
    EXPECT_DOUBLE_EQ(forces.forceLow(2090.0), 1.0);
}

// A beam's scale in a length (the profile's scales take lengths for the
// displacement) is refused, naming the beam: it was read as a strain.
TEST(PalpationForces, ABeamGivenALengthScaleIsRefused)
{
    const sensors::ChannelScales scales{
        {"stiff", {"mm", 200.0, 2048.0}}, {"soft", {"N", 50.0, 2048.0}}, {"d", {"mm", 1.0, std::nullopt}}};
    try {
        compliance::PalpationForces(kCounts, settingsWith(scales));
        ADD_FAILURE() << "a beam in millimetres was read";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()), "the beam stiff is given a scale in mm, a length; a beam's counts are read "
                                         "as a force (N, mN) or a strain (strain, µε)");
    }
}

// A beam in counts given no full_scale has no clipping judged: said,
// naming it, so that an operator knows a press at its limit reads as any
// other; with every beam's full scale, nothing is said.
TEST(PalpationForces, ABeamWithoutAFullScaleIsSaidToHaveNoClippingJudged)
{
    const sensors::ChannelScales judged{
        {"stiff", {"N", 200.0, 2048.0}}, {"soft", {"N", 50.0, 2048.0}}, {"d", {"mm", 1.0, std::nullopt}}};
    EXPECT_FALSE(compliance::PalpationForces(kCounts, settingsWith(judged)).unjudgedClipping());
    const sensors::ChannelScales softUnjudged{
        {"stiff", {"N", 200.0, 2048.0}}, {"soft", {"N", 50.0, std::nullopt}}, {"d", {"mm", 1.0, std::nullopt}}};
    compliance::PalpationForces forces(kCounts, settingsWith(softUnjudged));
    const auto said = forces.unjudgedClipping();
    ASSERT_TRUE(said);
    EXPECT_NE(said->find("gives soft no \"full_scale\""), std::string::npos) << *said;
    EXPECT_FALSE(forces.atLimit(false, 1e9));
}
