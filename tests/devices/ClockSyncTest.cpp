// Device-to-host clock mapping under drift and random transport delays.
#include "devices/ClockSync.h"

#include <gtest/gtest.h>

#include <random>

using tactiscope::devices::ClockSync;

TEST(ClockSync, RecoversOffsetAndDriftUnderRandomDelays)
{
    // The device clock runs 100 ppm fast and started 3.2 s after the host's;
    // each block arrives 0.5–10 ms late (USB polling, scheduling).
    std::mt19937 random(4);
    std::exponential_distribution<double> delay(1.0 / 0.002);
    ClockSync sync;
    const double drift = -1e-4 / (1 + 1e-4);  // host time per device second − 1
    const auto host = [&](double device) { return 3.2 + device * (1 + drift); };
    for (double device = 0.0; device < 90.0; device += 0.02)
        sync.observe(device, host(device) + 0.0005 + std::min(delay(random), 0.0095));
    EXPECT_NEAR(sync.drift(), drift, 5e-6);
    // Mapped times within half a millisecond of the truth (plus the 0.5 ms
    // floor of the delay, which no receiver can tell from an offset).
    for (double device : {60.0, 75.0, 89.0}) EXPECT_NEAR(sync.hostTime_s(device), host(device) + 0.0005, 0.0005);
}

TEST(ClockSync, UsesTheSmallestDelaySeenBeforeDriftIsKnown)
{
    ClockSync sync;
    EXPECT_DOUBLE_EQ(sync.hostTime_s(1.0), 1.0);
    sync.observe(0.1, 10.105);
    sync.observe(0.2, 10.201);
    sync.observe(0.3, 10.309);
    EXPECT_NEAR(sync.hostTime_s(0.5), 10.501, 1e-12);  // offset 10.001 from the least-delayed block
}
