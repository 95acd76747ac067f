// A device clock that drifts from the host's: ClockAlignment fits the
// drift from the blocks' least-delayed arrivals, DriftWatch says so beyond
// 500 ppm — with arrivals jittered by up to 5 ms, as a USB adapter's are.
#include "devices/DriftWatch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

using tactiscope::core::timing::ClockAlignment;
using tactiscope::devices::DriftWatch;

namespace {

// Blocks of 10 ms of stream time from a device whose clock runs `ppm`
// fast, arriving after 1–6 ms; the notices DriftWatch gave, and when.
std::vector<std::pair<double, std::string>> watch(double ppm, double seconds)
{
    ClockAlignment clock;
    DriftWatch drift;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> delay(0.001, 0.006);
    std::vector<std::pair<double, std::string>> notices;
    for (double device = 0.01; device <= seconds; device += 0.01) {
        const double host = device / (1.0 + ppm * 1e-6) + delay(random);
        clock.add(device, host);
        if (auto notice = drift.check(clock, device)) notices.emplace_back(device, *notice);
    }
    return notices;
}

// "… runs 1030 ppm fast …" → 1030; NaN when it does not say `way`.
double ppmIn(const std::string& notice, const std::string& way)
{
    const auto at = notice.find("runs ");
    if (at == std::string::npos || notice.find(" ppm " + way) == std::string::npos) return std::nan("");
    return std::stod(notice.substr(at + 5));
}

}  // namespace

TEST(DriftWatch, AClockAThousandPpmFastIsSaidOnceInTenMinutes)
{
    const auto notices = watch(1000.0, 60.0);
    ASSERT_EQ(notices.size(), 1u);
    EXPECT_LE(notices.front().first, 16.3);  // once 15 s of arrivals are mapped, looked at each second
    EXPECT_NEAR(ppmIn(notices.front().second, "fast"), 1000.0, 70.0) << notices.front().second;
    const auto slow = watch(-800.0, 30.0);
    ASSERT_EQ(slow.size(), 1u);
    EXPECT_NEAR(ppmIn(slow.front().second, "slow"), 800.0, 70.0) << slow.front().second;
}

TEST(DriftWatch, ACrystalsOwnErrorIsNoAlarm)
{
    EXPECT_TRUE(watch(50.0, 120.0).empty());
    EXPECT_TRUE(watch(-200.0, 120.0).empty());
}
