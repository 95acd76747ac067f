// SI → display conversion per channel kind.
#include "ui/common/DisplayUnits.h"

#include <gtest/gtest.h>

using tactiscope::core::ChannelDescriptor;
using tactiscope::core::ChannelKind;
using tactiscope::ui::displayUnitFor;

TEST(DisplayUnits, ShowsStrainInMicrostrain)
{
    const auto unit = displayUnitFor({"a", "", ChannelKind::Strain});
    EXPECT_EQ(unit.scale, 1e6);
    EXPECT_EQ(unit.axisTitle(), QStringLiteral("Strain (µε)"));
}

TEST(DisplayUnits, ShowsCapacitanceInPicofarads)
{
    const auto unit = displayUnitFor({"c", "F", ChannelKind::Capacitance});
    EXPECT_EQ(unit.scale, 1e12);
    EXPECT_EQ(unit.symbol, QStringLiteral("pF"));
}

TEST(DisplayUnits, KeepsAnUnknownKindInItsOwnUnit)
{
    const auto unit = displayUnitFor({"t", "K", ChannelKind::Other});
    EXPECT_EQ(unit.scale, 1.0);
    EXPECT_EQ(unit.axisTitle(), QStringLiteral("Value (K)"));
}
