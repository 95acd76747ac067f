// SI → display conversion per channel kind.
#include "ui/DisplayUnits.h"

#include <QLocale>

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

TEST(DisplayUnits, ANumberThatRoundsToZeroHasNoSign)
{
    // A baseline's −0.0004 pF of noise is "0.000 pF", not "-0.000 pF".
    EXPECT_EQ(tactiscope::ui::fixedText(-0.0004, 3), QLocale().toString(0.0, 'f', 3));
    EXPECT_EQ(tactiscope::ui::fixedText(-0.0006, 3), QLocale().toString(-0.001, 'f', 3));
    EXPECT_EQ(tactiscope::ui::fixedText(-0.04, 1), QLocale().toString(0.0, 'f', 1));
    EXPECT_EQ(tactiscope::ui::fixedText(2.5, 0), QLocale().toString(2.5, 'f', 0));
}

TEST(DisplayUnits, ValuesReadSideBySideShareTheirDecimals)
{
    // Five significant digits at the larger of a stretch's extremes.
    EXPECT_EQ(tactiscope::ui::decimalsForMagnitude(5.884, 5), 4);  // -5.8840 … -3.9928
    EXPECT_EQ(tactiscope::ui::decimalsForMagnitude(117.0, 5), 2);  // 116.98
    EXPECT_EQ(tactiscope::ui::decimalsForMagnitude(51440.0, 5), 0);
    EXPECT_EQ(tactiscope::ui::decimalsForMagnitude(0.0, 5), 4);
}
