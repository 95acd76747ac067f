// The bounds every number of a stored session must keep before it sizes a
// buffer or a loop: a damaged or hostile store (a chunk count of 2⁴⁰, a
// first index of 4·10¹⁸, a gap of 2⁶² samples, a negative count, the
// channel rows gone) is "damaged", said once, in bounded time and memory,
// instead of a reader allocating for it, writing NaN rows until the disk is
// full, or crashing.
//
// What is checked, per session (incrementally: a recording another
// connection is writing is checked only as far as it is new):
//  - it has channel rows, with finite positive rates;
//  - every chunk: first index ≥ 0, 1 ≤ count ≤ kMostChunkSamples, a blob of
//    count × channels × 4 bytes, a finite time, after the chunk before;
//  - the samples skipped between two chunks (lost ones) at most what the
//    time between them allows at the session's rate (twice, plus 2 s);
//  - every gap: first index ≥ 0, count ≥ 1, ending no later than the last
//    chunk plus what the session's own duration (started to ended) allows.
#pragma once

#include "core/storage/Database.h"

#include <cstdint>
#include <map>

namespace tactiscope::core::storage {

inline constexpr std::int64_t kMostChunkSamples = std::int64_t{1} << 26;

class SessionLayout {
public:
    explicit SessionLayout(Database& db)
        : m_db(db)
    {
    }

    // Throws StorageError naming the session and what is damaged. A session
    // that does not exist passes (there is nothing of it to read).
    void check(std::int64_t session);

private:
    struct Checked {
        std::int64_t chunkEnd = 0;  // one past the last chunk checked
        double chunkEndTime_s = 0.0;
        double firstTime_s = 0.0;  // of the first chunk: times are measured from it
        std::int64_t chunks = 0;
        std::int64_t gapsFrom = 0;  // gaps starting before this index are checked
    };

    Database& m_db;
    std::map<std::int64_t, Checked> m_checked;
};

}  // namespace tactiscope::core::storage
