// Which modes a device's channels can feed: the channels each mode reads,
// in its processor's order, and the sentence that names what is missing.
#include "core/ModeCapability.h"

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

TEST(ModeCapability, ARefusalNamesWhatTheModeNeedsAndWhatTheDeviceHas)
{
    const auto refusal = modeRefusal(Mode::Palpation, std::vector{kStrainA, kStrainB});
    ASSERT_TRUE(refusal);
    EXPECT_EQ(*refusal, "palpation needs two beam channels and a displacement (position) channel; this device has "
                        "A (strain), B (strain).");
    const auto none = modeRefusal(Mode::Capacitive, std::vector<ChannelDescriptor>{});
    ASSERT_TRUE(none);
    EXPECT_EQ(*none, "capacitive needs a capacitance channel; this device has none.");
}

TEST(ModeCapability, TheRunnableModesOfEachProbe)
{
    EXPECT_EQ(runnableModes(std::vector{kStrainA, kStrainB}), std::vector{Mode::PanelScan});
    EXPECT_EQ(runnableModes(std::vector{kHigh, kLow, kDisplacement}), std::vector{Mode::Palpation});
    EXPECT_EQ(runnableModes(std::vector{kCapacitance}), std::vector{Mode::Capacitive});
    // Two strain gauges and a displacement gauge could be either probe.
    EXPECT_EQ(runnableModes(std::vector{kStrainA, kStrainB, kDisplacement}),
              (std::vector{Mode::PanelScan, Mode::Palpation}));
    EXPECT_TRUE(runnableModes(std::vector{kDisplacement}).empty());
}
