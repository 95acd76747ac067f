// Which modes a device's channels can feed: the channels each mode reads,
// in its processor's order, and the sentence that names what is missing.
#include "core/ModeCapability.h"
#include "core/modes/ChannelRoles.h"
#include "core/modes/ModeDefinition.h"

#include <gtest/gtest.h>

using namespace tactiscope::core;

namespace {

const ChannelDescriptor kStrainA{"A", "", ChannelKind::Strain};
const ChannelDescriptor kStrainB{"B", "", ChannelKind::Strain};
const ChannelDescriptor kHigh{"high", "counts", ChannelKind::Other};
const ChannelDescriptor kLow{"low", "counts", ChannelKind::Other};
const ChannelDescriptor kDisplacement{"x", "m", ChannelKind::Position};
const ChannelDescriptor kCapacitance{"C", "F", ChannelKind::Capacitance};

}  // namespace

TEST(ModeCapability, APanelProbeFeedsPanelScanWithItsFirstTwoStrainChannels)
{
    const std::vector channels{kDisplacement, kStrainA, kStrainB};
    EXPECT_EQ(modeChannels(Mode::PanelScan, channels), (std::vector<std::size_t>{1, 2}));
    EXPECT_FALSE(modeRefusal(Mode::PanelScan, channels));
    EXPECT_FALSE(modeChannels(Mode::PanelScan, std::vector{kStrainA, kDisplacement}));
}

TEST(ModeCapability, PalpationReadsTwoBeamsThenTheDisplacementWhateverTheOrder)
{
    EXPECT_EQ(modeChannels(Mode::Palpation, std::vector{kHigh, kLow, kDisplacement}),
              (std::vector<std::size_t>{0, 1, 2}));
    EXPECT_EQ(modeChannels(Mode::Palpation, std::vector{kDisplacement, kHigh, kLow}),
              (std::vector<std::size_t>{1, 2, 0}));
    EXPECT_FALSE(modeChannels(Mode::Palpation, std::vector{kHigh, kLow}));
}

TEST(ModeCapability, ARefusalNamesTheRolesMissingWhatTheDeviceHasAndHowToGiveRoles)
{
    const auto refusal = modeRefusal(Mode::Palpation, std::vector{kStrainA, kStrainB});
    ASSERT_TRUE(refusal);
    // The strains can be the beams; no channel can be the displacement.
    EXPECT_EQ(*refusal, "palpation needs a stiff and a soft beam and a displacement: no channel plays displacement; "
                        "this device has A (strain), B (strain).");
    EXPECT_EQ(roleExample(Mode::Palpation, std::vector{kStrainA, kStrainB}),
              "A=stiff-beam,B=soft-beam,NAME=displacement");
    const auto none = modeRefusal(Mode::Capacitive, std::vector<ChannelDescriptor>{});
    ASSERT_TRUE(none);
    EXPECT_EQ(*none, "capacitive needs a capacitance: no channel plays capacitance; this device has none.");
    EXPECT_EQ(roleExample(Mode::Capacitive, std::vector<ChannelDescriptor>{}), "NAME=capacitance");
}

TEST(ModeCapability, TheRunnableModesOfEachProbeEndWithGeneralWhichRunsOnAnyDevice)
{
    EXPECT_EQ(runnableModes(std::vector{kStrainA, kStrainB}), (std::vector{Mode::PanelScan, Mode::General}));
    EXPECT_EQ(runnableModes(std::vector{kHigh, kLow, kDisplacement}), (std::vector{Mode::Palpation, Mode::General}));
    EXPECT_EQ(runnableModes(std::vector{kCapacitance}), (std::vector{Mode::Capacitive, Mode::General}));
    // Two strain gauges and a displacement gauge could be either probe.
    EXPECT_EQ(runnableModes(std::vector{kStrainA, kStrainB, kDisplacement}),
              (std::vector{Mode::PanelScan, Mode::Palpation, Mode::General}));
    EXPECT_EQ(runnableModes(std::vector{kDisplacement}), std::vector{Mode::General});
    EXPECT_EQ(runnableModes(std::vector<ChannelDescriptor>{}), std::vector{Mode::General});
    EXPECT_EQ(modeChannels(Mode::General, std::vector{kHigh}), std::vector<std::size_t>{});
}

TEST(ModeCapability, ChannelsGivenRolesFeedAModeTheirValuesFit)
{
    // An Arduino's two unlabelled columns: no kind, so no mode but general…
    const std::vector<ChannelDescriptor> board{{"a", "", ChannelKind::Other}, {"b", "", ChannelKind::Other}};
    EXPECT_FALSE(modeChannels(Mode::PanelScan, board));
    const auto refusal = modeRefusal(Mode::PanelScan, board);
    ASSERT_TRUE(refusal);
    EXPECT_NE(refusal->find("no channel plays cantilever-a, cantilever-b"), std::string::npos) << *refusal;
    EXPECT_EQ(roleExample(Mode::PanelScan, board), "a=cantilever-a,b=cantilever-b");
    // …and given roles, plain numbers are still no strains; as strains
    // (a unit given), B first on the wire, A second.
    const auto given = applyRoles(board, parseRoleAssignment("b=cantilever-a, a=cantilever-b"));
    EXPECT_FALSE(modeChannels(Mode::PanelScan, given));
    const std::vector<ChannelDescriptor> strains{{"a", "", ChannelKind::Strain}, {"b", "", ChannelKind::Strain}};
    EXPECT_EQ(modeChannels(Mode::PanelScan, applyRoles(strains, parseRoleAssignment("b=cantilever-a, a=cantilever-b"))),
              (std::vector<std::size_t>{1, 0}));
    // One role given, the other still missing: named alone.
    const auto half = applyRoles(board, parseRoleAssignment("a=cantilever-a"));
    EXPECT_NE(modeRefusal(Mode::PanelScan, half)->find("no channel plays cantilever-b;"), std::string::npos);
}

TEST(ModeCapability, AGivenRoleWinsOverTheKindsAndAChannelWithARoleIsNotTakenForAnother)
{
    // Three strain channels; the user says the third is A.
    const ChannelDescriptor kStrainC{"C", "", ChannelKind::Strain};
    auto channels = applyRoles(std::vector{kStrainA, kStrainB, kStrainC}, {{"C", ChannelRole::CantileverA}});
    // A is C; B is the first strain channel without a role.
    EXPECT_EQ(modeChannels(Mode::PanelScan, channels), (std::vector<std::size_t>{2, 0}));
    // A channel the device declared capacitance and the user made the soft
    // beam is no longer a capacitance, and no beam either: a beam reads a
    // strain, a force or counts.
    channels = applyRoles(std::vector{kHigh, kCapacitance, kDisplacement}, {{"C", ChannelRole::SoftBeam}});
    EXPECT_FALSE(modeChannels(Mode::Palpation, channels));
    EXPECT_FALSE(modeChannels(Mode::Capacitive, channels));
    channels = applyRoles(std::vector{kHigh, kLow, kDisplacement}, {{"high", ChannelRole::SoftBeam}});
    EXPECT_EQ(modeChannels(Mode::Palpation, channels), (std::vector<std::size_t>{1, 0, 2}));
}

TEST(ChannelRoles, ARoleListIsParsedAndWrittenBackAndBadOnesAreNamed)
{
    const auto roles = parseRoleAssignment(" a = cantilever-a ,b=cantilever-b,");
    EXPECT_EQ(roles, (RoleAssignment{{"a", ChannelRole::CantileverA}, {"b", ChannelRole::CantileverB}}));
    EXPECT_EQ(roleAssignmentText(roles), "a=cantilever-a,b=cantilever-b");
    EXPECT_TRUE(parseRoleAssignment("").empty());
    const auto message = [](const char* text) {
        try {
            parseRoleAssignment(text);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message("a"), "'a' is not NAME=ROLE (e.g. a=cantilever-a)");
    EXPECT_EQ(message("=stiff-beam"), "'=stiff-beam' names no channel");
    EXPECT_EQ(message("a=cantilever-c"),
              "'cantilever-c' is not a channel role; the roles are cantilever-a, "
              "cantilever-b, stiff-beam, soft-beam, displacement, capacitance, reference-force or position");
    EXPECT_EQ(message("a=stiff-beam,a=soft-beam"), "channel 'a' is given two roles");
    EXPECT_EQ(message("a=stiff-beam,b=stiff-beam"), "the role stiff-beam is given to both 'a' and 'b'");
}

TEST(ChannelRoles, ARoleForAChannelTheDeviceLacksIsRefusedAndAGivenRoleMovesOffAnother)
{
    ChannelDescriptor declaredA = kStrainA;
    declaredA.role = ChannelRole::CantileverA;
    EXPECT_THROW(applyRoles(std::vector{declaredA, kStrainB}, {{"Z", ChannelRole::CantileverA}}),
                 std::invalid_argument);
    // B is made A: the device's A loses the role, so no role is played twice.
    const auto moved = applyRoles(std::vector{declaredA, kStrainB}, {{"B", ChannelRole::CantileverA}});
    EXPECT_FALSE(moved[0].role);
    EXPECT_EQ(moved[1].role, ChannelRole::CantileverA);
    for (const auto& definition : modeDefinitions())
        for (const ChannelRole role : definition.roles) EXPECT_EQ(channelRoleFromString(toString(role)), role);
}

// Issue 53: a role given to a plain number does not make it a strain.
TEST(ModeCapability, ARoleGivenToAPlainNumberIsRefusedNamingTheChannelAndWhatTheRoleReads)
{
    const auto given =
        applyRoles(std::vector<ChannelDescriptor>{{"a", "", ChannelKind::Other}, {"b", "", ChannelKind::Other}},
                   parseRoleAssignment("a=cantilever-a,b=cantilever-b"));
    EXPECT_FALSE(modeChannels(Mode::PanelScan, given));
    const auto refusal = modeRefusal(Mode::PanelScan, given);
    ASSERT_TRUE(refusal);
    EXPECT_EQ(*refusal, "panel-scan needs two strain cantilevers (A and B): a plays cantilever-a but is a plain "
                        "number (no unit), and cantilever-a reads a strain (strain, µε); b plays cantilever-b but is "
                        "a plain number (no unit), and cantilever-b reads a strain (strain, µε); this device has a "
                        "(cantilever-a), b (cantilever-b).");
    EXPECT_EQ(channelsWithoutFittingUnit(Mode::PanelScan, given), (std::vector<std::string>{"a", "b"}));
    // A beam in °C is no beam either; in counts, N or as a strain it is.
    const auto degrees =
        applyRoles(std::vector<ChannelDescriptor>{{"t", "°C", ChannelKind::Other}, kLow, kDisplacement},
                   parseRoleAssignment("t=stiff-beam"));
    EXPECT_TRUE(modeRefusal(Mode::Palpation, degrees)->find("t plays stiff-beam but is in °C") != std::string::npos);
    for (const ChannelDescriptor& beam : {kHigh, kStrainA, ChannelDescriptor{"f", "N", ChannelKind::Force}}) {
        const auto channels =
            applyRoles(std::vector{beam, kLow, kDisplacement}, RoleAssignment{{beam.name, ChannelRole::StiffBeam}});
        EXPECT_FALSE(modeRefusal(Mode::Palpation, channels)) << beam.name;
    }
    // Unassigned plain numbers are matched by no role's kind.
    EXPECT_EQ(runnableModes(std::vector<ChannelDescriptor>{
                  {"a", "", ChannelKind::Other}, {"b", "", ChannelKind::Other}, kDisplacement}),
              (std::vector{Mode::General}));
}
