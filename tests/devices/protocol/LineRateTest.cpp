// A text board's rate measured from the lines' arrivals (and from its own
// clock), against boards whose true rate is known: the stated ± covers
// the truth as a standard uncertainty should, for a slow board timed on a
// few lines and a fast one timed on many, on links that deliver at random,
// in USB bursts and on the host itself (each on a host whose delays
// wander), and with a backlog read at once.
#include "devices/protocol/LineRate.h"

#include "tests/support/Coverage.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>

using tactiscope::devices::protocol::BoardTime;
using tactiscope::devices::protocol::LineRate;

namespace {

// Random: the OS and the link delay each line, 0.2 ms and more; Bursts:
// USB frames; Pty: a board on the host itself, its lines read within a
// hundred µs or so. On every link the level of the delays wanders over
// seconds (the host's scheduler, its CPU's power states): an
// Ornstein–Uhlenbeck level of kWander_s, correlated over 2 s, as on this
// workstation's ptys (LineRate::kHostWander_s).
enum class Link { Random, Bursts, Pty };
constexpr double kWander_s = LineRate::kHostWander_s;

const char* nameOf(Link link)
{
    return link == Link::Random ? "random" : link == Link::Bursts ? "bursts" : "pty";
}

// A board printing at `rate_hz`, delivered over `link`; the estimate once
// the rate has settled.
tactiscope::devices::protocol::LineRateEstimate timeBoard(double rate_hz, Link link, unsigned seed,
                                                          std::size_t backlog = 0)
{
    std::mt19937_64 random(seed);
    std::exponential_distribution<double> delay(1.0 / 0.8e-3);  // the OS and the link: 0.8 ms on average
    std::uniform_real_distribution<double> phase(0.0, 1.0);
    std::normal_distribution<double> normal;
    double level_s = kWander_s * normal(random);
    LineRate rate;
    const double start_s = 100.0 + phase(random);
    // A backlog that waited in the port arrives at once with the first line.
    for (std::size_t i = 0; i < backlog; ++i) rate.add(start_s, std::nullopt);
    // The link is read 50 times a second; the rate is looked at after each read.
    const auto linesPerRead = static_cast<std::size_t>(std::max(1.0, rate_hz / 50.0));
    const double period_s = 1.0 / rate_hz, correlation_s = 2.0;
    for (std::size_t i = 0; i % linesPerRead != 0 || !rate.settled(); ++i) {
        const double sent_s = start_s + static_cast<double>(i) * period_s;
        level_s += -level_s * period_s / correlation_s +
                   kWander_s * std::sqrt(2.0 * period_s / correlation_s) * normal(random);
        double arrival_s = sent_s + (link == Link::Pty ? 100e-6 + 0.11 * delay(random) : 0.2e-3 + delay(random));
        // USB full speed: the board's bytes leave in 1 ms frames.
        if (link == Link::Bursts) arrival_s = std::ceil(arrival_s * 1000.0) / 1000.0 + 0.1e-3 * phase(random);
        // The host reads them when its scheduler gets to it.
        arrival_s += level_s;
        rate.add(arrival_s, std::nullopt);
    }
    return *rate.estimate();
}

// Over `seeds` boards at `rate_hz` on each link: the stated ± covers the
// truth as a standard uncertainty should; `check` looks at each estimate.
void expectCoverage(double rate_hz, unsigned seeds,
                    const std::function<void(const tactiscope::devices::protocol::LineRateEstimate&)>& check)
{
    for (const Link link : {Link::Random, Link::Bursts, Link::Pty}) {
        tactiscope::testing::Coverage coverage;
        for (unsigned seed = 1; seed <= seeds; ++seed) {
            const auto rate = timeBoard(rate_hz, link, seed);
            ASSERT_TRUE(rate.u_hz);
            check(rate);
            coverage.add(rate.rate_hz - rate_hz, *rate.u_hz);
        }
        EXPECT_TRUE(coverage.isGaussian()) << nameOf(link) << " at " << rate_hz << " Hz";
    }
}

}  // namespace

TEST(LineRate, ASlowBoardsRateOnAFewLinesIsCoveredByItsUncertainty)
{
    expectCoverage(10.0, 400, [](const auto& rate) {
        // Timed until its ± is within 100 ppm, or for 5 s at most.
        EXPECT_TRUE(*rate.u_hz <= LineRate::kSettledU * rate.rate_hz || rate.span_s >= LineRate::kLongestWindow_s);
        EXPECT_LE(rate.lines, 60u);
    });
}

TEST(LineRate, AHundredHertzBoardsRateOnTheLinesFitIsCoveredByItsUncertainty)
{
    expectCoverage(100.0, 200, [](const auto&) {});
}

TEST(LineRate, AFastBoardsRateIsCoveredByTheClockMappingsUncertainty)
{
    expectCoverage(500.0, 200, [](const auto& rate) {
        EXPECT_LT(std::abs(rate.rate_hz / 500.0 - 1.0), 5e-4);  // the 0.05 %
    });
}

TEST(LineRate, ABacklogReadAtOnceDoesNotMoveTheRate)
{
    // Two seconds of lines that waited in the port: counted, they would
    // make a 100 Hz board 200 Hz.
    const auto rate = timeBoard(100.0, Link::Random, 7, 200);
    EXPECT_NEAR(rate.rate_hz, 100.0, 4.0 * *rate.u_hz);
    EXPECT_LT(std::abs(rate.rate_hz / 100.0 - 1.0), 1e-3);
}

TEST(LineRate, ASlowBoardIsTimedOverEightOfItsPeriods)
{
    // The first line may have waited in the port: nine after it, eight periods.
    LineRate rate;
    for (int i = 0; i < 9; ++i) {
        rate.add(10.0 + i * 1.0 + 1e-4 * (i % 3), std::nullopt);
        EXPECT_FALSE(rate.settled()) << "after " << i + 1 << " lines";
    }
    rate.add(19.0, std::nullopt);
    ASSERT_TRUE(rate.settled());
    EXPECT_NEAR(rate.estimate()->rate_hz, 1.0, 2e-3);
}

TEST(LineRate, TheBoardsOwnClockTimesItsLinesAndItsUnitIsFoundFromTheArrivals)
{
    // A board whose loop takes 101.3 ms stamps its lines with millis(),
    // unlabelled as to unit ("t"); its lines arrive late and unevenly.
    LineRate rate;
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> late(0.0, 0.02);
    for (int i = 0; i < 45; ++i) {
        const double stamp_ms = std::floor(1000.0 + i * 101.3);
        rate.add(50.0 + i * 0.1013 + late(random), BoardTime{stamp_ms, std::nullopt});
    }
    ASSERT_TRUE(rate.settled());
    const auto estimate = *rate.estimate();
    EXPECT_TRUE(estimate.boardClock);
    EXPECT_DOUBLE_EQ(estimate.boardSecondsPerUnit, 1e-3);
    // 44 periods over floor(1000 + 44·101.3) − 1000 = 4457 ms: the ± of
    // whole milliseconds, 1/(√6·4457) of the rate, is within 100 ppm.
    EXPECT_NEAR(estimate.rate_hz, 44.0 / 4.457, 1e-9);
    ASSERT_TRUE(estimate.u_hz);
    EXPECT_NEAR(*estimate.u_hz, estimate.rate_hz * 1.0 / std::sqrt(6.0) / 4457.0, 1e-12);
}

// A board's millis() stamps are whole milliseconds: the span between the
// first and the last is off by the difference of two roundings, which the
// stated ± (q/√6) covers as a standard uncertainty.
TEST(LineRate, ABoardClocksResolutionIsCoveredByItsUncertainty)
{
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> phase(0.0, 1.0);
    tactiscope::testing::Coverage coverage;
    for (int board = 0; board < 400; ++board) {
        const double period_ms = 9.0 + phase(random);  // 100–111 Hz by the board's crystal
        const double start_ms = 1000.0 * phase(random);
        LineRate rate;
        for (int i = 0; !rate.settled(); ++i) {
            const double sent_ms = start_ms + i * period_ms;
            rate.add(20.0 + sent_ms * 1e-3 + 1e-3 * phase(random), BoardTime{std::floor(sent_ms), 1e-3});
        }
        const auto estimate = *rate.estimate();
        ASSERT_TRUE(estimate.boardClock && estimate.u_hz);
        coverage.add(estimate.rate_hz - 1000.0 / period_ms, *estimate.u_hz);
    }
    EXPECT_TRUE(coverage.isGaussian());
}

TEST(LineRate, ABoardClockStepOfSeveralPeriodsIsLinesLostNotASlowerRate)
{
    LineRate rate;
    for (int i = 0; i < 40; ++i) {
        if (i == 10 || i == 11) continue;                         // two lines lost on the way
        rate.add(1.0 + i * 0.05, BoardTime{i * 50'000.0, 1e-6});  // micros
    }
    EXPECT_NEAR(rate.estimate()->rate_hz, 20.0, 1e-9);
}
