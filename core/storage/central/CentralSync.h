// Store-and-forward: a station's finished and interrupted sessions copied
// to the central store, each in one transaction that ends by comparing the
// checksum of what arrived with the station's and only then marking the
// session complete. So a sync killed, cut off or refused half way leaves
// nothing behind (the server rolls the transaction back), and the next one
// sends the session again; a session already there with the same checksum
// is skipped (but verdicts and notes decided at the station since are
// added), one with another is refused and never overwritten. The station's
// store is only read.
#pragma once

#include "core/storage/SessionStore.h"
#include "core/storage/central/CentralStore.h"

#include <functional>
#include <stop_token>
#include <string>
#include <vector>

namespace tactiscope::core::storage::central {

struct SyncOutcome {
    int sent = 0;
    int alreadyThere = 0;
    int updated = 0;                   // of those already there: verdicts or notes decided since added
    std::uint64_t samplesSent = 0;     // values, over all channels
    std::vector<std::string> refused;  // one sentence per session the server would not take
    // Reviewer decisions made at the station: a station's rows are its
    // own facts, so these are not sent (a reviewer decides on the central
    // store); one sentence per session holding any.
    std::vector<std::string> keptAtStation;
};

// "synced 2 sessions (1.2 M samples), 1 already there": millions with one
// decimal, or two significant digits below a million, so a small sync
// never reads "0.0 M". The sync command's contract; the GUI says it in
// full counts (CentralSyncController).
std::string syncSummary(const SyncOutcome& outcome);

struct SyncProgress {
    int done = 0;   // sessions looked at
    int total = 0;  // sessions to look at
};

// Where a session's samples are cut into the chunks a checksum is over:
// as the central store holds them (ServerChunks), or as the station's store
// does (how sessions were sent before central schema 11).
enum class ChunkCut { Server, AsStored };

// The checksum of a session's samples, as the central store computes it
// from the rows it holds: the MD5 of one line "first:count:md5(samples)"
// per chunk, in order, joined by newlines. A session of several devices
// holds no samples of its own: the MD5 of one line "device checksum" per
// part, so a session sent again with other parts is told apart.
std::string sessionChecksum(SessionStore& local, std::int64_t session, ChunkCut cut = ChunkCut::Server);

// Sends what the central store lacks. `station` names where the sessions
// come from (empty: the connection's role, which is what a station role
// must use). Throws StorageError when the server cannot be reached or
// fails part way (what was committed stays, the rest waits for the next
// sync); a session refused on its own is reported and the rest go on.
SyncOutcome syncToCentral(SessionStore& local, CentralStore& central, const std::string& station = {},
                          std::stop_token stop = {}, const std::function<void(const SyncProgress&)>& progress = {});

// Sessions of `local` that wait to be sent: finished or interrupted and
// not on the central store. Recording ones are not counted.
int sessionsToSync(SessionStore& local, CentralStore& central);

}  // namespace tactiscope::core::storage::central
