// Stored UTC times read back: the form this program writes, to the
// millisecond, against seconds counted by hand; anything else is nothing.
#include "core/text/UtcTime.h"

#include <gtest/gtest.h>

#include <chrono>

using tactiscope::core::text::utcIso8601;
using tactiscope::core::text::utcSeconds;

TEST(UtcTime, ReadsTheFormItWrites)
{
    // 2026-11-25 is day 20 782 since 1970-01-01 (56 years, 14 of them leap,
    // then 328 days into 2026): 20 782 × 86 400 + 12 h 30 min 15.25 s.
    EXPECT_DOUBLE_EQ(*utcSeconds("2026-11-25T12:30:15.250Z"), 20782.0 * 86400 + 12 * 3600 + 30 * 60 + 15.25);
    EXPECT_DOUBLE_EQ(*utcSeconds("1970-01-01T00:00:00Z"), 0.0);
    EXPECT_DOUBLE_EQ(*utcSeconds("2024-02-29T00:00:01.5Z"), 19782.0 * 86400 + 1.5);
    const auto now = std::chrono::system_clock::now();
    const double written = *utcSeconds(utcIso8601(now));
    const double truth = std::chrono::duration<double>(now.time_since_epoch()).count();
    EXPECT_LE(truth - written, 0.001);
    EXPECT_GE(truth - written, 0.0);
}

TEST(UtcTime, AnythingElseIsNothing)
{
    for (const char* text : {"", "now", "2026-11-25", "2026-11-25T12:30:15", "2026-13-01T00:00:00Z",
                             "2026-02-30T00:00:00Z", "2026-11-25T24:00:00Z", "2026-11-25T12:30:15.Z",
                             "2026-11-25 12:30:15Z", "2026-11-25T12:30:15Zjunk", "+026-11-25T12:30:15Z"})
        EXPECT_FALSE(utcSeconds(text)) << text;
}
