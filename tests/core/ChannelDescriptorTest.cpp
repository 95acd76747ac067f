// ChannelKind names round-trip and unknown names are refused.
#include "core/ChannelDescriptor.h"

#include <gtest/gtest.h>

using namespace tactiscope::core;

TEST(ChannelDescriptor, KindNamesRoundTrip)
{
    for (ChannelKind kind : {ChannelKind::Strain, ChannelKind::Capacitance, ChannelKind::Force, ChannelKind::Position,
                             ChannelKind::Other}) {
        EXPECT_EQ(channelKindFromString(toString(kind)), kind);
    }
    EXPECT_EQ(toString(ChannelKind::Capacitance), "capacitance");
}

TEST(ChannelDescriptor, UnknownKindNameIsRefused)
{
    EXPECT_FALSE(channelKindFromString("Strain").has_value());
    EXPECT_FALSE(channelKindFromString("").has_value());
}
