// ReadAheadTransport: the reading thread and the queue it fills.
#include "devices/transport/ReadAheadTransport.h"

#include "devices/SteadyClock.h"

#include <algorithm>
#include <cstring>

namespace tactiscope::devices::transport {

namespace {

constexpr std::size_t kReadSize = 65536;
// How long the thread waits in one read: how soon it notices a stop.
constexpr std::chrono::milliseconds kReadWait{20};

}  // namespace

ReadAheadTransport::ReadAheadTransport(std::unique_ptr<Transport> inner)
    : m_inner(std::move(inner)),
      m_description(m_inner->description()),
      m_thread([this](const std::stop_token& stop) { run(stop); })
{
}

ReadAheadTransport::~ReadAheadTransport()
{
    m_thread.request_stop();
    m_thread.join();
}

void ReadAheadTransport::run(const std::stop_token& stop)
{
    std::vector<std::uint8_t> buffer(kReadSize);
    while (!stop.stop_requested()) {
        std::size_t n = 0;
        try {
            n = m_inner->read(buffer, kReadWait);
        } catch (...) {
            const std::lock_guard lock(m_mutex);
            m_error = std::current_exception();
            m_ready.notify_all();
            return;
        }
        if (n == 0) continue;
        const double arrival_s = steadySeconds();
        const std::lock_guard lock(m_mutex);
        if (m_queued + n > kMostQueuedBytes) {
            m_dropped += n;
            continue;
        }
        m_chunks.push_back(
            {std::vector<std::uint8_t>(buffer.begin(), buffer.begin() + static_cast<long>(n)), 0, arrival_s});
        m_queued += n;
        m_ready.notify_all();
    }
}

std::size_t ReadAheadTransport::read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout)
{
    std::unique_lock lock(m_mutex);
    m_ready.wait_for(lock, timeout, [this] { return !m_chunks.empty() || m_error; });
    if (m_chunks.empty()) {
        if (m_error) std::rethrow_exception(m_error);
        return 0;
    }
    // From one chunk only, so the bytes returned share one arrival.
    Chunk& chunk = m_chunks.front();
    const std::size_t n = std::min(buffer.size(), chunk.bytes.size() - chunk.consumed);
    std::memcpy(buffer.data(), chunk.bytes.data() + chunk.consumed, n);
    chunk.consumed += n;
    m_lastArrival_s = chunk.arrival_s;
    m_queued -= n;
    if (chunk.consumed == chunk.bytes.size()) m_chunks.pop_front();
    return n;
}

std::uint64_t ReadAheadTransport::bytesDropped() const
{
    const std::lock_guard lock(m_mutex);
    return m_dropped;
}

}  // namespace tactiscope::devices::transport
