// Unplug and replug over a real pseudo-terminal: the emulator hangs up, the
// source reports Lost, a new emulator appears at the same link, and the
// stream continues with the outage marked as a gap.
#include "devices/ReconnectingSource.h"

#include "core/SampleBlock.h"
#include "devices/Acquisition.h"
#include "devices/SteadyClock.h"
#include "devices/emulator/ProbeEmulator.h"

#include "support/Eventually.h"
#include "support/TempPath.h"
#include "support/TextBoard.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

using namespace tactiscope;
using namespace tactiscope::devices;

namespace {

emulator::EmulatorOptions probeAt(const std::string& link, std::optional<double> seconds, std::uint64_t seed)
{
    return {link, WireProtocol::Binary, "panel-scan", 1000.0, std::nullopt, seconds, 0.0, 10, seed};
}

// The stream time a block ended at, and the host time it was seen.
struct LastBlock final : core::BlockSink {
    void consume(const core::SampleBlock& block) override
    {
        const std::lock_guard lock(mutex);
        end_s = block.endTime_s();
        seen_s = steadySeconds();
    }
    std::mutex mutex;
    double end_s = 0.0, seen_s = 0.0;
};

// The newest block's first sample, channel by channel.
struct FirstValues final : core::BlockSink {
    void consume(const core::SampleBlock& block) override
    {
        const std::lock_guard lock(mutex);
        values.clear();
        for (std::size_t c = 0; c < block.channelCount(); ++c) values.push_back(block.channel(c)[0]);
    }
    std::vector<double> get()
    {
        const std::lock_guard lock(mutex);
        return values;
    }
    std::mutex mutex;
    std::vector<double> values;
};

// Every block's start and end on the stream's time, in order.
struct BlockTimes final : core::BlockSink {
    void consume(const core::SampleBlock& block) override
    {
        const std::lock_guard lock(mutex);
        spans.emplace_back(block.t0_s(), block.endTime_s());
    }
    std::vector<std::pair<double, double>> get()
    {
        const std::lock_guard lock(mutex);
        return spans;
    }
    std::mutex mutex;
    std::vector<std::pair<double, double>> spans;
};

// A text board's source that reopens its link when it comes back; its
// rate is given (not timed again at each connection).
std::unique_ptr<ReconnectingSource> reopeningTextBoard(const std::string& link, double rate_hz)
{
    return std::make_unique<ReconnectingSource>(
        serialOpener(link, "", 115200,
                     {WireProtocol::Text, rate_hz, std::chrono::milliseconds(4000), std::nullopt, {}}),
        std::chrono::milliseconds(100));
}

}  // namespace

TEST(ReconnectingSource, ContinuesAfterUnplugAndReplugWithTheGapMarked)
{
    const std::string link = tactiscope::testing::uniqueTempPath("replug");
    auto first = std::make_unique<emulator::ProbeEmulator>(probeAt(link, 0.5, 1));
    first->start();
    auto source = std::make_unique<ReconnectingSource>(
        serialOpener(link, "", 921600,
                     {WireProtocol::Binary, std::nullopt, std::chrono::milliseconds(2000), std::nullopt, {}}),
        std::chrono::milliseconds(100));
    auto* reconnecting = source.get();
    Acquisition acquisition(std::move(source));
    auto last = std::make_shared<LastBlock>();
    acquisition.addSink(last);
    acquisition.start();

    // The first probe streams 0.5 s, then hangs up: Lost.
    ASSERT_TRUE(tactiscope::testing::eventually([&] { return reconnecting->state() == DeviceState::Lost; }));
    const auto before = acquisition.stats();
    EXPECT_GE(before.samples, 400u);
    EXPECT_EQ(before.state, AcquisitionState::Streaming);  // the acquisition waits, it does not fail

    // Plugged back in (a new pty at the same link) 0.4 s later.
    first.reset();
    std::this_thread::sleep_for(std::chrono::milliseconds(400));
    emulator::ProbeEmulator second(probeAt(link, std::nullopt, 1));  // the same probe: its serial is its seed's
    second.start();
    ASSERT_TRUE(tactiscope::testing::eventually([&] {
        return reconnecting->state() == DeviceState::Streaming && acquisition.stats().samples > before.samples + 200;
    }));
    const auto after = acquisition.stats();
    // The reconnected probe's clock maps the stream's time (shifted past
    // the outage) onto the host's: its latest block, to when it was seen.
    ASSERT_TRUE(tactiscope::testing::eventually([&] { return reconnecting->hostClock().has_value(); }));
    {
        const std::lock_guard lock(last->mutex);
        EXPECT_NEAR(reconnecting->hostClock()->host_s(last->end_s), last->seen_s, 0.05);
    }
    acquisition.stop();
    EXPECT_EQ(reconnecting->reconnections(), 1u);
    // At least the 0.4 s away (400 samples at 1 kHz) is counted as lost.
    EXPECT_GE(after.samplesLost, 300u);
    EXPECT_LT(after.samplesLost, 3000u);
}

TEST(ReconnectingSource, TheFirstConnectionMustSucceed)
{
    EXPECT_ANY_THROW(ReconnectingSource(
        serialOpener("/dev/nonexistent-tactiscope", "", 115200,
                     {WireProtocol::Binary, std::nullopt, std::chrono::milliseconds(200), std::nullopt, {}})));
}

// A text board unplugged and plugged back in is timed again when it comes
// back: a rate a hair apart (within the two timings' uncertainty) is the
// same board, not "another rate" that ends the stream.
TEST(ReconnectingSource, ATextBoardTimedAgainWhenItComesBackContinues)
{
    const std::string link = tactiscope::testing::uniqueTempPath("text-replug");
    const tactiscope::testing::TextBoardOptions printing{
        200.0, [](std::uint64_t n) { return "a:" + std::to_string(n % 10) + " b:1\n"; }, 4, 2e-3, false};
    auto board = std::make_unique<tactiscope::testing::TextBoard>(link, printing);
    auto source = std::make_unique<ReconnectingSource>(
        serialOpener(link, "", 115200,
                     {WireProtocol::Text, std::nullopt, std::chrono::milliseconds(4000), std::nullopt, {}}),
        std::chrono::milliseconds(100));
    auto* reconnecting = source.get();
    ASSERT_TRUE(reconnecting->rateUncertainty_hz());
    Acquisition acquisition(std::move(source));
    auto times = std::make_shared<BlockTimes>();
    acquisition.addSink(times);
    acquisition.start();
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const double unplugged_s = steadySeconds();
    board.reset();  // unplugged
    ASSERT_TRUE(tactiscope::testing::eventually([&] { return reconnecting->state() != DeviceState::Streaming; }));
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    board = std::make_unique<tactiscope::testing::TextBoard>(link, printing);
    const double away_s = steadySeconds() - unplugged_s;
    ASSERT_TRUE(tactiscope::testing::eventually(
        [&] { return reconnecting->reconnections() == 1 && reconnecting->state() == DeviceState::Streaming; },
        std::chrono::seconds(10)))
        << reconnecting->lastError();
    EXPECT_FALSE(reconnecting->failedForGood());
    // The gap is the time it was away, not that and the 2.5 s it took to
    // be timed again (its lines of that time are in the stream).
    EXPECT_NEAR(static_cast<double>(acquisition.stats().samplesLost), away_s * 200.0, 0.3 * 200.0);
    acquisition.stop();
    // Its stream goes on after the last line before the unplug by the time
    // it was away: its first connection's stream began with the lines it
    // was timed on, 2.5 s before the connection was made, and the second
    // was placed on the host's clock as if it had begun with it, which
    // set its lines before the first's.
    const auto spans = times->get();
    const auto gap =
        std::ranges::adjacent_find(spans, [](const auto& a, const auto& b) { return b.first - a.second > 0.1; });
    ASSERT_NE(gap, spans.end());
    EXPECT_NEAR(std::next(gap)->first - gap->second, away_s, 0.3);
    EXPECT_TRUE(std::ranges::is_sorted(spans)) << "the stream's time went back";
}

// A board whose sketch changed while it was unplugged comes back printing
// c and a: the stream goes on with a matched by its name, c a new channel
// and b (no longer printed) holes, and says so. Before, any other channels
// ended the stream. One that comes back printing a in another unit is
// another device.
TEST(ReconnectingSource, ATextBoardThatComesBackPrintingOtherChannelsContinuesByTheirNames)
{
    const std::string link = tactiscope::testing::uniqueTempPath("text-relayout");
    const auto printing = [](std::function<std::string(std::uint64_t)> line) {
        return tactiscope::testing::TextBoardOptions{200.0, std::move(line), 4, 1e-3, false};
    };
    auto board = std::make_unique<tactiscope::testing::TextBoard>(
        link, printing([](std::uint64_t n) { return "a:" + std::to_string(n % 10) + " b:1\n"; }));
    auto source = reopeningTextBoard(link, 200.0);
    auto* reconnecting = source.get();
    Acquisition acquisition(std::move(source));
    auto first = std::make_shared<FirstValues>();
    acquisition.addSink(first);
    acquisition.start();
    board.reset();
    ASSERT_TRUE(tactiscope::testing::eventually([&] { return reconnecting->state() != DeviceState::Streaming; }));
    board = std::make_unique<tactiscope::testing::TextBoard>(
        link, printing([](std::uint64_t n) { return "c:7 a:" + std::to_string(n % 10) + "\n"; }));
    ASSERT_TRUE(tactiscope::testing::eventually([&] { return first->get().size() == 3; }, std::chrono::seconds(10)))
        << reconnecting->lastError();
    const auto values = first->get();
    EXPECT_GE(values[0], 0.0);
    EXPECT_LE(values[0], 9.0);
    EXPECT_TRUE(std::isnan(values[1]));
    EXPECT_EQ(values[2], 7.0);
    const auto grown = acquisition.takeGrownChannels();
    ASSERT_TRUE(grown);
    ASSERT_EQ(grown->size(), 3u);
    EXPECT_EQ((*grown)[2].name, "c");
    bool told = false;
    for (const auto& notice : acquisition.takeNotices())
        told = told || (notice.text.starts_with("the device was lost and came back: no samples for ") &&
                        notice.text.ends_with("; it now prints c (holes before); it no longer prints b (holes from "
                                              "here)"));
    EXPECT_TRUE(told);

    board.reset();
    ASSERT_TRUE(tactiscope::testing::eventually([&] { return reconnecting->state() != DeviceState::Streaming; }));
    board = std::make_unique<tactiscope::testing::TextBoard>(
        link, printing([](std::uint64_t n) { return "a[mN]:" + std::to_string(n % 10) + "\n"; }));
    ASSERT_TRUE(
        tactiscope::testing::eventually([&] { return reconnecting->failedForGood(); }, std::chrono::seconds(10)));
    EXPECT_EQ(reconnecting->lastError(),
              "the device came back printing a in another unit (N, where it was none); reconnect it by hand");
    acquisition.stop();
}
