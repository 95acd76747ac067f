// ServerChunks: a session's stored chunks joined and cut at fixed indices.
#include "core/storage/central/ServerChunks.h"

#include "core/storage/Database.h"

#include <algorithm>
#include <cstring>

namespace tactiscope::core::storage::central {

std::uint64_t serverChunkInstants(std::size_t channels)
{
    constexpr std::uint64_t kMostInstants = 4096;
    constexpr std::uint64_t kMostBytes = std::uint64_t{1} << 20;
    std::uint64_t instants = kMostInstants;
    while (instants > 1 && instants * std::max<std::uint64_t>(channels, 1) * 4 > kMostBytes) instants /= 2;
    return instants;
}

ServerChunkPacker::ServerChunkPacker(std::size_t channels, double rate_hz, Visit visit)
    : m_channels(channels),
      m_rate_hz(rate_hz),
      m_visit(std::move(visit)),
      m_capacity(serverChunkInstants(channels)),
      m_buffer(channels * m_capacity * 4)
{
}

void ServerChunkPacker::add(const SessionStore::RawChunk& chunk)
{
    if (chunk.samples.size() != chunk.count * m_channels * 4)
        throw StorageError("a stored chunk at sample " + std::to_string(chunk.firstIndex) + " holds " +
                           std::to_string(chunk.samples.size()) + " bytes, not " + std::to_string(chunk.count) +
                           " samples of " + std::to_string(m_channels) + " channels");
    // Samples that do not follow those held (a gap) start a chunk of their own.
    if (m_held > 0 && chunk.firstIndex != m_first + m_held) emit();
    std::uint64_t done = 0;
    while (done < chunk.count) {
        const std::uint64_t index = chunk.firstIndex + done;
        if (m_held == 0) {
            m_first = index;
            m_firstTime_s = chunk.firstTime_s + static_cast<double>(done) / m_rate_hz;
        }
        // Up to the next multiple of the capacity.
        const std::uint64_t room = m_capacity - index % m_capacity;
        const std::uint64_t take = std::min(room, chunk.count - done);
        for (std::size_t c = 0; c < m_channels; ++c)
            std::memcpy(m_buffer.data() + (c * m_capacity + m_held) * 4,
                        chunk.samples.data() + (c * chunk.count + done) * 4, take * 4);
        m_held += take;
        done += take;
        if (take == room) emit();
    }
}

void ServerChunkPacker::finish()
{
    if (m_held > 0) emit();
}

void ServerChunkPacker::emit()
{
    m_out.resize(m_channels * m_held * 4);
    for (std::size_t c = 0; c < m_channels; ++c)
        std::memcpy(m_out.data() + c * m_held * 4, m_buffer.data() + c * m_capacity * 4, m_held * 4);
    m_visit({m_first, m_firstTime_s, m_held, m_out});
    m_held = 0;
}

void forEachServerChunk(SessionStore& local, std::int64_t session, const ServerChunkPacker::Visit& visit)
{
    const std::vector<StoredChannel> channels = local.channels(session);
    double rate_hz = 0.0;
    for (const StoredChannel& c : channels) rate_hz = std::max(rate_hz, c.sampleRate_hz);
    ServerChunkPacker packer(channels.size(), rate_hz, visit);
    local.forEachChunk(session, [&packer](const SessionStore::RawChunk& c) { packer.add(c); });
    packer.finish();
}

}  // namespace tactiscope::core::storage::central
