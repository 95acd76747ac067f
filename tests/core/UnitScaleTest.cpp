// The units a channel may be given (core/UnitScale.h): each one's kind and
// factor to SI, checked against the SI prefixes by hand; a unit not in the
// table is kept as given; the --units list.
#include "core/UnitScale.h"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace tactiscope::core;

TEST(UnitScale, EachUnitHasItsKindAndItsFactorToTheStoredSiUnit)
{
    struct Case {
        const char* unit;
        ChannelKind kind;
        const char* si;
        double factor;
    };
    for (const Case& c :
         {Case{"strain", ChannelKind::Strain, "", 1.0}, Case{"µε", ChannelKind::Strain, "", 1e-6},
          Case{"ue", ChannelKind::Strain, "", 1e-6}, Case{"N", ChannelKind::Force, "N", 1.0},
          Case{"mN", ChannelKind::Force, "N", 1e-3}, Case{"uN", ChannelKind::Force, "N", 1e-6},
          Case{"kN", ChannelKind::Force, "N", 1e3}, Case{"mm", ChannelKind::Position, "m", 1e-3},
          Case{"µm", ChannelKind::Position, "m", 1e-6}, Case{"pF", ChannelKind::Capacitance, "F", 1e-12},
          Case{"fF", ChannelKind::Capacitance, "F", 1e-15}}) {
        ChannelDescriptor channel{"x", "", ChannelKind::Other};
        EXPECT_EQ(giveUnit(channel, c.unit), c.factor) << c.unit;
        EXPECT_EQ(channel.kind, c.kind) << c.unit;
        EXPECT_EQ(channel.unit, c.si) << c.unit;
    }
    ChannelDescriptor temperature{"t", "", ChannelKind::Other};
    EXPECT_EQ(giveUnit(temperature, "°C"), 1.0);
    EXPECT_EQ(temperature.unit, "°C");
    EXPECT_EQ(temperature.kind, ChannelKind::Other);
    EXPECT_TRUE(isCounts("counts"));
    EXPECT_FALSE(isCounts(""));
    EXPECT_EQ(newtonsPer("mN"), 1e-3);
    EXPECT_FALSE(newtonsPer("pF"));
    EXPECT_EQ(faradsPer("pF"), 1e-12);
}

TEST(UnitScale, TheUnitsListNamesEachChannelOnceWithAUnit)
{
    EXPECT_EQ(parseUnitAssignment(" a = µε , b=mN"), (UnitAssignment{{"a", "µε"}, {"b", "mN"}}));
    const auto message = [](const char* text) {
        try {
            parseUnitAssignment(text);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message("a"), "'a' is not NAME=UNIT (e.g. a=µε)");
    EXPECT_EQ(message("a="), "channel 'a' is given no unit");
    EXPECT_EQ(message("a=mN,a=N"), "channel 'a' is given two units");
    EXPECT_EQ(message("force=mN;pos=mm"), "'mN;pos=mm' is not a unit (separate the items with ',')");
    // A unit of the table in another case is a slip, not a unit of its own
    // (MN would be a meganewton); one not in the table is kept as given.
    EXPECT_EQ(message("force=MN"), "'MN' (force): did you mean mN? A unit's case is part of it");
    EXPECT_EQ(message("c=PF"), "'PF' (c): did you mean pF? A unit's case is part of it");
    EXPECT_EQ(parseUnitAssignment("t=degC,h=%"), (UnitAssignment{{"t", "degC"}, {"h", "%"}}));
}
