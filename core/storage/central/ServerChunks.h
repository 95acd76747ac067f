// The chunks a session's samples reach the central store in. A station
// commits every 250 ms and a chunk never spans a commit, so its own store
// holds a 60 s palpation in 239 chunks of 250 instants; a server holding a
// site's year of sessions would hold hundreds of millions of such rows and
// their index. The sync re-chunks instead: each server chunk holds the
// instants from one multiple of serverChunkInstants() to the next (fewer
// at the session's start and end, and where samples stop at a gap), cut
// by the samples' indices alone. So the server's chunks, and the checksum
// over them, are the same whatever commits the station made.
#pragma once

#include "core/storage/SessionStore.h"

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace tactiscope::core::storage::central {

// Instants per server chunk: 4 096, fewer for a session of more than 64
// channels so that no chunk's samples pass 1 MiB (a power of two, so the
// cuts stay on multiples of 4 096).
std::uint64_t serverChunkInstants(std::size_t channels);

// Joins a session's stored chunks, in order, into server chunks. The
// span in each visited chunk is valid during the call only.
class ServerChunkPacker {
public:
    using Visit = std::function<void(const SessionStore::RawChunk&)>;

    // `rate_hz` dates an instant inside a stored chunk (its first instant's
    // time plus its offset at that rate), as the store's readers do.
    ServerChunkPacker(std::size_t channels, double rate_hz, Visit visit);

    // The next stored chunk (channel-major, `channels` channels), after the
    // ones added before it.
    void add(const SessionStore::RawChunk& chunk);
    // Sends what is held.
    void finish();

private:
    void emit();

    std::size_t m_channels;
    double m_rate_hz;
    Visit m_visit;
    std::uint64_t m_capacity;
    std::vector<std::uint8_t> m_buffer;  // channel c's instants at [c·capacity·4, …)
    std::uint64_t m_first = 0;           // index of the first instant held
    double m_firstTime_s = 0.0;
    std::uint64_t m_held = 0;  // instants held
    std::vector<std::uint8_t> m_out;
};

// Visits session's samples as server chunks.
void forEachServerChunk(SessionStore& local, std::int64_t session, const ServerChunkPacker::Visit& visit);

}  // namespace tactiscope::core::storage::central
