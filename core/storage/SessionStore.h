// The session store: one SQLite file holding many inspection sessions, each
// with its metadata, channels and samples (in chunks, with the gaps where
// samples were lost). One SessionStore is one connection; use one per
// thread. Writers and readers may share the file at the same time (WAL).
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/storage/Database.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tactiscope::core {
class SampleBlock;
}

namespace tactiscope::core::storage {

enum class SessionStatus { Recording, Complete, Interrupted };
std::string_view toString(SessionStatus status);

// What the user and the device tell about a session before it starts.
struct SessionMetadata {
    std::string mode;  // "panel-scan", "palpation" or "capacitive"
    std::string subject;
    std::string operatorName;
    std::string site;
    std::string notes;
    std::string deviceModel;
    std::string deviceSerial;
    std::string deviceFirmware;
    std::string profileJson;  // the sensor profile used, copied in
};

struct SessionSummary {
    std::int64_t id = 0;
    std::string uuid;
    SessionMetadata metadata;
    std::string startedUtc;  // ISO 8601, e.g. 2026-11-21T14:20:28.123Z
    std::string endedUtc;    // empty while recording or when interrupted
    std::string status;
    std::string verdict;
    std::string appVersion;
};

struct StoredChannel {
    ChannelDescriptor descriptor;
    double sampleRate_hz = 0.0;
};

struct SampleGap {
    std::uint64_t firstIndex = 0;
    std::uint64_t count = 0;
};

class SessionStore {
public:
    // Opens or (read-write) creates the store; see prepareSchema() for the
    // files it refuses. Read-write and with no recorder running (see
    // RecorderLock), sessions a crash left "recording" become "interrupted",
    // with every committed sample kept. Throws StorageError.
    SessionStore(const std::string& path, Database::Access access = Database::Access::ReadWrite);

    // Writing. Blocks are stored as they come; a block whose first sample
    // index is past the end of the previous one records a gap.
    std::int64_t beginSession(const SessionMetadata& metadata, std::span<const ChannelDescriptor> channels,
                              double sampleRate_hz);
    void appendBlocks(std::int64_t session, std::span<const SampleBlock> blocks);  // one transaction
    // Records samples lost after the last stored ones (e.g. at the end of a
    // recording, where no later block marks the gap). No-op when none are.
    void markLostUntil(std::int64_t session, std::uint64_t endIndex);
    void endSession(std::int64_t session, SessionStatus status);
    // Deletes a session with its channels, samples and gaps. Throws
    // StorageError for an unknown id or a session still being recorded.
    void deleteSession(std::int64_t session);
    // Marks every "recording" session "interrupted"; only for the holder of
    // the RecorderLock, who knows no recording is live. Returns how many.
    int markCrashedSessionsInterrupted();

    // Reading.
    std::vector<SessionSummary> sessions();  // newest first
    std::optional<SessionSummary> session(std::int64_t id);
    std::vector<StoredChannel> channels(std::int64_t session);
    std::uint64_t sampleCount(std::int64_t session);  // per channel, including gaps and lost ones at the end
    std::vector<SampleGap> gaps(std::int64_t session);
    // Samples [firstIndex, firstIndex + count) of one channel, clipped to the
    // recording; samples inside a gap read as NaN.
    std::vector<double> readChannel(std::int64_t session, std::size_t channel, std::uint64_t firstIndex,
                                    std::uint64_t count);

    // SQLite's integrity check: "ok", or its first finding.
    std::string checkIntegrity();

    Database& database() { return m_db; }

private:
    Database m_db;
};

}  // namespace tactiscope::core::storage
