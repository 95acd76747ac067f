// The trigger's gate on a stream with known crossings, into real recorders
// on a real SQLite file: each session holds exactly its span of the stream
// (pre-trigger samples from the held blocks, post time after the level
// clears), whatever the block size and however late the owner attaches its
// recorder; the trigger instant's stream time is the crossing sample's;
// nothing is lost or doubled at the seams (a second channel carries each
// sample's own index).
#include "devices/session/TriggerGate.h"
#include "core/storage/Recorder.h"
#include "core/storage/SessionStore.h"

#include "support/TempDirectory.h"

#include <gtest/gtest.h>

#include <memory>

using namespace tactiscope;
using namespace tactiscope::core;
using devices::session::QuantityReader;
using devices::session::TriggerGate;

namespace {

constexpr double kRate_hz = 100.0;

// High (1) on [100, 150) and [300, 320), else 0; channel 1 is the index.
double level(std::uint64_t i)
{
    return (i >= 100 && i < 150) || (i >= 300 && i < 320) ? 1.0 : 0.0;
}

SampleBlock blockAt(std::uint64_t first, std::size_t count)
{
    SampleBlock block(2, count, static_cast<double>(first) / kRate_hz, 1.0 / kRate_hz, first);
    for (std::size_t s = 0; s < count; ++s) {
        block.channel(0)[s] = level(first + s);
        block.channel(1)[s] = static_cast<double>(first + s);
    }
    return block;
}

class TriggerGateTest : public tactiscope::testing::TempDirectoryTest {
protected:
    std::shared_ptr<storage::Recorder> recorder()
    {
        const std::vector<ChannelDescriptor> channels{{"a", "", ChannelKind::Other}, {"i", "", ChannelKind::Other}};
        return std::make_shared<storage::Recorder>(m_store, storage::SessionMetadata{}, channels, kRate_hz, 1u << 20);
    }
    // Feeds the stream in blocks of `size` from `next` up to `end`.
    void feed(TriggerGate& gate, std::uint64_t& next, std::uint64_t end, std::size_t size)
    {
        while (next < end) {
            const auto count = static_cast<std::size_t>(std::min<std::uint64_t>(size, end - next));
            gate.consume(blockAt(next, count));
            next += count;
        }
    }
    // The indices a session holds, from its index channel.
    std::vector<double> storedIndices(std::int64_t session)
    {
        storage::SessionStore store(m_store, storage::Database::Access::ReadOnly);
        return store.readChannel(session, 1, 0, store.sampleCount(session));
    }
    static trigger::TriggerSettings settings(unsigned sessions)
    {
        trigger::TriggerSettings s;
        s.condition = *trigger::parseTrigger("a>0.5").condition;
        s.pre_s = 0.3;   // 30 samples
        s.post_s = 0.2;  // 20 samples
        s.sessions = sessions;
        return s;
    }
    // In the test's own folder, which SetUp makes: a member initialiser
    // ran before it and named a file in the working directory.
    void SetUp() override
    {
        TempDirectoryTest::SetUp();
        m_store = file("t.tactiscope");
    }
    std::string m_store;

    static std::vector<double> range(std::uint64_t first, std::uint64_t end)
    {
        std::vector<double> r;
        for (auto i = first; i < end; ++i) r.push_back(static_cast<double>(i));
        return r;
    }
};

}  // namespace

TEST_F(TriggerGateTest, EachSessionHoldsExactlyItsSpanHoweverLateItsRecorderComes)
{
    for (const std::size_t size : {1u, 7u, 64u}) {
        SCOPED_TRACE("blocks of " + std::to_string(size));
        m_store = file("t" + std::to_string(size) + ".tactiscope");
        TriggerGate gate;
        gate.arm(settings(2), QuantityReader::deviceChannel(0, ""), kRate_hz, 30.0);
        std::uint64_t next = 0;
        feed(gate, next, 99, size);
        EXPECT_FALSE(gate.pendingStart());
        EXPECT_EQ(gate.status().state, trigger::TriggerState::Armed);
        // Triggered at 100; the owner attaches 30 samples later.
        feed(gate, next, 131, size);
        const auto pending = gate.pendingStart();
        ASSERT_TRUE(pending);
        EXPECT_EQ(pending->span.first, 70u);
        EXPECT_EQ(pending->span.trigger, 100u);
        EXPECT_DOUBLE_EQ(pending->triggerTime_s, 1.0);
        auto first = recorder();
        gate.attach(first);
        feed(gate, next, 250, size);
        auto finished = gate.takeFinished();
        ASSERT_TRUE(finished);
        EXPECT_EQ(finished->session.span.end, 170u);  // 20 samples after it cleared at 150
        EXPECT_EQ(finished->recorder, first);
        const auto one = first->sessionId();
        first->finish(SessionStatus::Complete);
        first.reset();
        finished.reset();  // the store's recorder lock goes with the last reference
        // The second: attached at once.
        feed(gate, next, 301, size);
        ASSERT_TRUE(gate.pendingStart());
        auto second = recorder();
        gate.attach(second);
        feed(gate, next, 500, size);
        finished = gate.takeFinished();
        ASSERT_TRUE(finished);
        EXPECT_EQ(gate.status().state, trigger::TriggerState::Finished);
        const auto two = second->sessionId();
        second->finish(SessionStatus::Complete);
        EXPECT_EQ(storedIndices(one), range(70, 170));
        EXPECT_EQ(storedIndices(two), range(270, 340));
    }
}

TEST_F(TriggerGateTest, AnOwnerTooLateForTheBacklogGetsTheNewestSamplesAndTheSessionStartsThere)
{
    TriggerGate gate;
    gate.arm(settings(1), QuantityReader::deviceChannel(0, ""), kRate_hz, 0.5);  // 30 pre + 50 held at most
    std::uint64_t next = 0;
    feed(gate, next, 200, 10);
    const auto pending = gate.pendingStart();
    ASSERT_TRUE(pending);
    // Held: the newest 80 samples, [120, 200): the session starts at 120.
    EXPECT_EQ(pending->span.first, 120u);
    auto late = recorder();
    gate.attach(late);
    ASSERT_TRUE(gate.takeFinished());
    const auto id = late->sessionId();
    late->finish(SessionStatus::Complete);
    EXPECT_EQ(storedIndices(id), range(120, 170));
}

TEST_F(TriggerGateTest, DetachingAnOpenSessionStopsItsSamplesAndDisarmingForgetsTheRest)
{
    TriggerGate gate;
    gate.arm(settings(2), QuantityReader::deviceChannel(0, ""), kRate_hz, 30.0);
    std::uint64_t next = 0;
    feed(gate, next, 120, 8);
    auto open = recorder();
    gate.attach(open);
    EXPECT_EQ(gate.detach(), open);  // a stop while it is open
    feed(gate, next, 200, 8);
    EXPECT_FALSE(gate.takeFinished());
    const auto id = open->sessionId();
    open->finish(SessionStatus::Complete);
    EXPECT_EQ(storedIndices(id), range(70, 120));
    gate.disarm();
    EXPECT_FALSE(gate.armed());
    feed(gate, next, 400, 8);
    EXPECT_FALSE(gate.pendingStart());
}
