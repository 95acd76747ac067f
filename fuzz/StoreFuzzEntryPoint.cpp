// Fuzz entry point for session store files: the input is written to a file
// and opened read-only as a reviewer opens a store someone handed over,
// then every session is read the way export and review read it (summary,
// channels, gaps, sample count, the samples in windows, the overview, the
// records of every analysis, zeros and parts). A
// StorageError is the store saying it is damaged; anything else (a crash,
// std::bad_alloc, a hang) is a finding. Windows are capped, so a damaged
// count the checks let through shows as a finding, not a machine full.
#include "FuzzEntryPoints.h"

#include "core/storage/SessionStore.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace tactiscope::fuzz {
namespace {

// One session read whole, as export and review read it; a session of
// several devices, each of its parts too (one level, as the product reads
// them: a crafted store may make parts of parts, or a loop).
void readSession(core::storage::SessionStore& store, std::int64_t session, bool withParts)
{
    const auto channels = store.channels(session);
    store.gaps(session);
    const std::uint64_t samples = store.sampleCount(session);
    std::vector<std::size_t> all(channels.size());
    for (std::size_t c = 0; c < all.size(); ++c) all[c] = c;
    std::vector<std::vector<double>> window;
    constexpr std::uint64_t kWindow = 4096, kMostRead = 1 << 20;
    for (std::uint64_t first = 0; first < samples && first < kMostRead; first += kWindow)
        store.readChannels(session, all, first, kWindow, window);
    if (!channels.empty()) store.overview(session, 0, 0, std::min(samples, kMostRead), 64);
    for (const std::string& analysis : store.analyses(session)) {
        store.events(session, analysis);
        store.readings(session, analysis);
    }
    store.verdicts(session);
    store.annotations(session);
    store.zeros(session);
    if (!withParts) return;
    for (const auto& part : store.parts(session)) readSession(store, part.id, false);
}

}  // namespace

void storeFile(const std::uint8_t* data, std::size_t size)
{
    static const std::string path =
        (std::filesystem::temp_directory_path() / ("tactiscope-fuzz-" + std::to_string(::getpid()) + ".tactiscope"))
            .string();
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path + suffix);
    {
        std::ofstream file(path, std::ios::binary);
        file.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    try {
        core::storage::SessionStore store(path, core::storage::Database::Access::ReadOnly);
        for (const auto& session : store.sessions()) readSession(store, session.id, true);
    } catch (const core::storage::StorageError&) {
        // Refused or found damaged, with a message: what a bad file should get.
    }
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path + suffix);
}

}  // namespace tactiscope::fuzz
