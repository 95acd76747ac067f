// A transport read on a thread of its own, so the device's bytes leave the
// kernel's buffer as they come, whatever its reader is busy with. A pty
// holds about 4 KB and a USB serial port's buffers little more: at 16
// channels × 10 kHz that is a few milliseconds, and the host's first
// steps (opening the store, building the processors) once took 160 ms
// while the device streamed, so the emulator lost a frame at every start.
// Here the bytes wait in memory, each chunk stamped with when it arrived
// (the clock alignment's arrival, not when its reader came round).
//
// Bounded: beyond kMostQueuedBytes (tens of seconds of the fastest stream)
// new bytes are dropped and counted; the decoder sees the hole as a broken
// frame and the recording as a gap, as with any link that loses bytes.
#pragma once

#include "devices/transport/Transport.h"

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace tactiscope::devices::transport {

class ReadAheadTransport final : public Transport {
public:
    static constexpr std::size_t kMostQueuedBytes = std::size_t{64} << 20;

    explicit ReadAheadTransport(std::unique_ptr<Transport> inner);
    ~ReadAheadTransport() override;

    std::string description() const override { return m_description; }
    // What the thread read, in order; the inner transport's error once
    // everything before it was read.
    std::size_t read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override;
    void write(std::span<const std::uint8_t> bytes) override { m_inner->write(bytes); }
    std::optional<double> arrival_s() const override { return m_lastArrival_s; }

    std::uint64_t bytesDropped() const;

private:
    void run(const std::stop_token& stop);

    struct Chunk {
        std::vector<std::uint8_t> bytes;
        std::size_t consumed = 0;
        double arrival_s = 0.0;
    };

    std::unique_ptr<Transport> m_inner;
    std::string m_description;
    mutable std::mutex m_mutex;
    std::condition_variable m_ready;
    std::deque<Chunk> m_chunks;
    std::size_t m_queued = 0;
    std::uint64_t m_dropped = 0;
    std::exception_ptr m_error;
    std::optional<double> m_lastArrival_s;  // the reader's own
    std::jthread m_thread;                  // last: stopped before the members it uses go
};

}  // namespace tactiscope::devices::transport
