// Acquisition: the worker thread's delivery order, counters and failure
// states, driven by an in-memory scripted source and by the real simulator.
#include "devices/Acquisition.h"

#include "core/SampleBlock.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/simulator/SimulatorSource.h"

#include <gtest/gtest.h>

#include <chrono>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <thread>

using namespace std::chrono_literals;
using namespace tactiscope;
using devices::Acquisition;
using devices::AcquisitionState;
using devices::ReadStatus;

namespace {

// Replays a fixed list of blocks, then ends with the given status.
class ScriptedSource final : public devices::BlockSource {
public:
    ScriptedSource(std::deque<core::SampleBlock> blocks, ReadStatus ending, std::string error = {})
        : m_blocks(std::move(blocks)),
          m_ending(ending),
          m_error(std::move(error))
    {
    }
    std::string name() const override { return "scripted"; }
    const std::vector<core::ChannelDescriptor>& channels() const override { return m_channels; }
    double nominalSampleRate_hz() const override { return 100.0; }
    ReadStatus readBlock(core::SampleBlock& out, std::chrono::milliseconds) override
    {
        if (m_blocks.empty()) return m_ending;
        out = std::move(m_blocks.front());
        m_blocks.pop_front();
        return ReadStatus::Block;
    }
    std::string lastError() const override { return m_error; }

private:
    std::vector<core::ChannelDescriptor> m_channels{{"x", "", core::ChannelKind::Other}};
    std::deque<core::SampleBlock> m_blocks;
    ReadStatus m_ending;
    std::string m_error;
};

class CollectingSink final : public core::BlockSink {
public:
    void consume(const core::SampleBlock& block) override
    {
        const std::lock_guard lock(m_mutex);
        m_firstIndices.push_back(block.firstSampleIndex());
    }
    std::vector<std::uint64_t> firstIndices() const
    {
        const std::lock_guard lock(m_mutex);
        return m_firstIndices;
    }

private:
    mutable std::mutex m_mutex;
    std::vector<std::uint64_t> m_firstIndices;
};

class ThrowingSink final : public core::BlockSink {
public:
    void consume(const core::SampleBlock&) override { throw std::runtime_error("disk on fire"); }
};

core::SampleBlock blockAt(std::uint64_t first, std::size_t count)
{
    return core::SampleBlock(1, count, static_cast<double>(first) * 0.01, 0.01, first);
}

// Waits (bounded) until the acquisition leaves the Streaming state.
devices::AcquisitionStats waitUntilNotStreaming(const Acquisition& acquisition)
{
    const auto deadline = std::chrono::steady_clock::now() + 10s;
    while (acquisition.stats().state == AcquisitionState::Streaming && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(1ms);
    return acquisition.stats();
}

}  // namespace

TEST(Acquisition, DeliversEveryBlockInOrderAndCountsGaps)
{
    std::deque<core::SampleBlock> blocks{blockAt(0, 10), blockAt(10, 10), blockAt(27, 10), blockAt(37, 5)};
    Acquisition acquisition(std::make_unique<ScriptedSource>(std::move(blocks), ReadStatus::Finished));
    auto sink = std::make_shared<CollectingSink>();
    acquisition.addSink(sink);
    acquisition.start();
    const auto stats = waitUntilNotStreaming(acquisition);

    EXPECT_EQ(stats.state, AcquisitionState::Finished);
    EXPECT_EQ(sink->firstIndices(), (std::vector<std::uint64_t>{0, 10, 27, 37}));
    EXPECT_EQ(stats.blocks, 4u);
    EXPECT_EQ(stats.samples, 35u);
    EXPECT_EQ(stats.samplesLost, 7u);
}

TEST(Acquisition, ReportsTheSourcesErrorWhenItFails)
{
    Acquisition acquisition(std::make_unique<ScriptedSource>(std::deque<core::SampleBlock>{blockAt(0, 3)},
                                                             ReadStatus::Failed, "cable pulled"));
    acquisition.start();
    const auto stats = waitUntilNotStreaming(acquisition);
    EXPECT_EQ(stats.state, AcquisitionState::Failed);
    EXPECT_EQ(stats.error, "cable pulled");
    EXPECT_EQ(stats.samples, 3u);
}

TEST(Acquisition, StopsWithAnErrorWhenASinkFails)
{
    Acquisition acquisition(
        std::make_unique<ScriptedSource>(std::deque<core::SampleBlock>{blockAt(0, 3)}, ReadStatus::Finished));
    acquisition.addSink(std::make_shared<ThrowingSink>());
    acquisition.start();
    const auto stats = waitUntilNotStreaming(acquisition);
    EXPECT_EQ(stats.state, AcquisitionState::Failed);
    EXPECT_NE(stats.error.find("disk on fire"), std::string::npos);
}

TEST(Acquisition, StopEndsALiveStreamAndKeepsItsCounts)
{
    Acquisition acquisition(
        std::make_unique<devices::simulator::SimulatorSource>(devices::simulator::makeScenario("panel-scan")));
    auto sink = std::make_shared<CollectingSink>();
    acquisition.addSink(sink);
    acquisition.start();
    EXPECT_THROW(acquisition.addSink(sink), std::logic_error);
    const auto deadline = std::chrono::steady_clock::now() + 10s;
    while (acquisition.stats().blocks < 3 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(5ms);
    acquisition.stop();

    const auto stats = acquisition.stats();
    EXPECT_EQ(stats.state, AcquisitionState::Idle);
    EXPECT_GE(stats.blocks, 3u);
    EXPECT_EQ(stats.samplesLost, 0u);
    EXPECT_EQ(sink->firstIndices().size(), stats.blocks);
}

TEST(Acquisition, RejectsANullSource)
{
    EXPECT_THROW(Acquisition(nullptr), std::invalid_argument);
}
