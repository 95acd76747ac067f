// The bounds every number of a stored session must keep before it sizes a
// buffer or a loop, whichever store it comes from (a station's SQLite file,
// the site's central store): a damaged or hostile store (a chunk count of
// 2⁴⁰, a first index of 4·10¹⁸, a gap of 2⁶² samples, a negative count, the
// channel rows gone) is "damaged", said once, in bounded time and memory,
// instead of a reader allocating for it, writing NaN rows until the disk is
// full, or crashing.
//
// What is checked, per session:
//  - it has channel rows, with rates in kSampleRateRange;
//  - every chunk: first index ≥ 0, 1 ≤ count ≤ kMostChunkSamples, a blob of
//    count × channels × 4 bytes, a finite time, after the chunk before;
//  - the samples skipped between two chunks (lost ones) at most what the
//    time between them allows at the session's rate (twice, plus 2 s);
//  - every gap: first index ≥ 0, count ≥ 1, ending no later than the last
//    chunk plus what the session's own duration (started to ended) allows;
//  - every sample up to the last in a chunk or a gap (no chunk missing).
#pragma once

#include <cstdint>
#include <string>
#include <utility>

namespace tactiscope::core::storage {

inline constexpr std::int64_t kMostChunkSamples = std::int64_t{1} << 26;
// The most samples one read may ask for (8 GiB of doubles a channel).
inline constexpr std::uint64_t kMostSamplesPerRead = std::uint64_t{1} << 30;

// One session's rows, checked as a reader meets them: the session, then its
// chunks in index order, then its gaps in index order. The object keeps what
// it has checked, so a session another connection is still writing is
// checked again only as far as it is new (rows from chunkEnd() and
// gapsFrom()). Every check throws StoreInputError naming `store`, the
// session and what is damaged.
class SessionBounds {
public:
    SessionBounds(std::string store, std::int64_t session)
        : m_store(std::move(store)),
          m_session(session)
    {
    }

    // Its duration (started to ended; to now while recording; 0 when
    // unknown), and its channel rows: how many, their lowest and highest rate.
    void session(double duration_s, std::int64_t channels, double lowestRate_hz, double highestRate_hz);
    void chunk(std::int64_t first, std::int64_t count, std::int64_t bytes, double time_s);
    void gap(std::int64_t first, std::int64_t count);
    // After the chunks and gaps read so far: every sample up to the last is
    // in one of them.
    void whole() const;

    std::int64_t chunkEnd() const { return m_chunkEnd; }
    std::int64_t gapsFrom() const { return m_gapsFrom; }

private:
    [[noreturn]] void damaged(const std::string& what) const;
    double mostLost(double seconds) const;

    std::string m_store;
    std::int64_t m_session;
    double m_duration_s = 0.0;
    std::int64_t m_channels = 0;
    double m_rate_hz = 0.0;       // the highest: the most samples a second can hold
    std::int64_t m_chunkEnd = 0;  // one past the last chunk checked
    double m_chunkEndTime_s = 0.0;
    double m_firstTime_s = 0.0;  // of the first chunk: times are measured from it
    std::int64_t m_chunks = 0;
    std::int64_t m_gapsFrom = 0;  // gaps starting before this index are checked
    std::int64_t m_gapEnd = 0;    // one past the last gap checked
    std::int64_t m_covered = 0;   // samples in the chunks and gaps checked
};

}  // namespace tactiscope::core::storage
