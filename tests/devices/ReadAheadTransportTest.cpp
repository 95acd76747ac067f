// ReadAheadTransport over a scripted inner transport: what it read comes
// out in order, stamped with when its thread read it (not when its caller
// came round), the inner error after everything before it, and beyond its
// bound new bytes are dropped and counted, never reordered.
#include "devices/transport/ReadAheadTransport.h"

#include "devices/SteadyClock.h"

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <numeric>
#include <thread>
#include <vector>

using tactiscope::devices::steadySeconds;
using tactiscope::devices::transport::ReadAheadTransport;
using tactiscope::devices::transport::Transport;
using tactiscope::devices::transport::TransportError;

namespace {

// Gives `total` bytes 0, 1, 2, … in reads of `step`, then fails if asked.
class Script final : public Transport {
public:
    Script(std::size_t total, std::size_t step, bool failAtEnd)
        : m_total(total),
          m_step(step),
          m_failAtEnd(failAtEnd)
    {
    }
    std::string description() const override { return "script"; }
    std::size_t read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override
    {
        if (m_given >= m_total) {
            if (m_failAtEnd) throw TransportError("script: unplugged");
            std::this_thread::sleep_for(timeout);
            return 0;
        }
        const std::size_t n = std::min({m_step, buffer.size(), m_total - m_given});
        for (std::size_t i = 0; i < n; ++i) buffer[i] = static_cast<std::uint8_t>((m_given + i) & 0xFF);
        m_given += n;
        return n;
    }
    void write(std::span<const std::uint8_t> bytes) override { written += bytes.size(); }
    std::atomic<std::size_t> written{0};

private:
    std::size_t m_total, m_step;
    bool m_failAtEnd;
    std::size_t m_given = 0;
};

}  // namespace

TEST(ReadAheadTransport, GivesWhatItReadInOrderStampedWhenItWasReadThenTheError)
{
    auto script = std::make_unique<Script>(100000, 1000, true);
    ReadAheadTransport transport(std::move(script));
    // The thread reads all of it while nobody asks.
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    const double asked_s = steadySeconds();
    std::vector<std::uint8_t> got, buffer(333);
    std::optional<double> firstArrival;
    try {
        for (;;) {
            const std::size_t n = transport.read(buffer, std::chrono::milliseconds(100));
            if (!firstArrival) firstArrival = transport.arrival_s();
            got.insert(got.end(), buffer.begin(), buffer.begin() + static_cast<long>(n));
        }
    } catch (const TransportError& e) {
        EXPECT_STREQ(e.what(), "script: unplugged");
    }
    ASSERT_EQ(got.size(), 100000u);
    for (std::size_t i = 0; i < got.size(); ++i) ASSERT_EQ(got[i], static_cast<std::uint8_t>(i & 0xFF)) << i;
    ASSERT_TRUE(firstArrival);
    EXPECT_LT(*firstArrival, asked_s - 0.1);  // read a good while before it was asked for
    EXPECT_EQ(transport.bytesDropped(), 0u);
}

TEST(ReadAheadTransport, BeyondItsBoundDropsNewBytesAndCountsThem)
{
    const std::size_t total = ReadAheadTransport::kMostQueuedBytes + 5 * 65536;
    ReadAheadTransport transport(std::make_unique<Script>(total, 65536, false));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (transport.bytesDropped() == 0 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    EXPECT_EQ(transport.bytesDropped(), 5u * 65536u);
    // What was kept is the beginning, in order.
    std::vector<std::uint8_t> buffer(4096);
    ASSERT_EQ(transport.read(buffer, std::chrono::milliseconds(100)), 4096u);
    for (std::size_t i = 0; i < buffer.size(); ++i) ASSERT_EQ(buffer[i], static_cast<std::uint8_t>(i & 0xFF));
}

TEST(ReadAheadTransport, WritesGoStraightThrough)
{
    auto script = std::make_unique<Script>(0, 1, false);
    auto* inner = script.get();
    ReadAheadTransport transport(std::move(script));
    const std::vector<std::uint8_t> command{1, 2, 3};
    transport.write(command);
    EXPECT_EQ(inner->written.load(), 3u);
    std::vector<std::uint8_t> buffer(16);
    EXPECT_EQ(transport.read(buffer, std::chrono::milliseconds(30)), 0u);  // nothing came: a timeout
    EXPECT_EQ(transport.description(), "script");
}
