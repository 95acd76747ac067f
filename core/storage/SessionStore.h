// The session store: one SQLite file holding many inspection sessions, each
// with its metadata, channels and samples (in chunks, with the gaps where
// samples were lost). One SessionStore is one connection; use one per
// thread. Writers and readers may share the file at the same time (WAL).
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/Vocabulary.h"
#include "core/storage/Database.h"
#include "core/storage/LodTable.h"
#include "core/storage/SessionRecords.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tactiscope::core {
class SampleBlock;
}

namespace tactiscope::core::storage {

// What the user and the device tell about a session before it starts.
struct SessionMetadata {
    Mode mode = Mode::PanelScan;
    std::string subject;
    std::string operatorName;
    std::string site;
    std::string notes;
    std::string deviceModel;
    std::string deviceSerial;
    std::string deviceFirmware;
    std::string profileJson;       // the sensor profile used, copied in
    std::string calibrationsJson;  // the calibration records used, copied in (a JSON array)
};

// Who a session is when it was recorded elsewhere (an import of an export):
// its identity and when and by which version it was recorded. Empty fields
// are this store's: a new uuid, now, this version.
struct SessionOrigin {
    std::string uuid;
    std::string startedUtc;
    std::string appVersion;
};

struct SessionSummary {
    std::int64_t id = 0;
    std::string uuid;
    SessionMetadata metadata;
    std::string startedUtc;  // ISO 8601, e.g. 2026-11-21T14:20:28.123Z
    std::string endedUtc;    // empty while recording or when interrupted
    SessionStatus status = SessionStatus::Recording;
    std::optional<Verdict> verdict;  // none until one is given (another word in the file reads as none)
    std::string appVersion;
    double sampleRate_hz = 0.0;
    std::uint64_t sampleCount = 0;  // per channel, including lost samples
    std::uint64_t eventCount = 0;   // live events of any kind
    double duration_s() const { return sampleRate_hz > 0.0 ? static_cast<double>(sampleCount) / sampleRate_hz : 0.0; }
};

// Which sessions to list; empty fields match everything.
struct SessionFilter {
    std::string startedFrom;    // UTC, ISO 8601 or a prefix such as "2026-11-21"; inclusive
    std::string startedBefore;  // exclusive
    std::optional<Mode> mode;
    std::string subject;       // exact
    std::string operatorName;  // exact
    std::optional<Verdict> verdict;
    std::string text;  // found in subject, operator, site, notes, verdict or device serial (any case)
};

using lod::OverviewPoint;

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
    // index is past the end of the previous one records a gap. A uuid
    // already in the store is refused by the schema (StorageError); an
    // import says so first, in its own words.
    std::int64_t beginSession(const SessionMetadata& metadata, std::span<const ChannelDescriptor> channels,
                              double sampleRate_hz, const SessionOrigin& origin = {});
    void appendBlocks(std::int64_t session, std::span<const SampleBlock> blocks);  // one transaction
    // Records samples lost after the last stored ones (e.g. at the end of a
    // recording, where no later block marks the gap). No-op when none are.
    void markLostUntil(std::int64_t session, std::uint64_t endIndex);
    // Ends it now, or at `endedUtc` (an imported session's own end; empty
    // for one that never ended).
    void endSession(std::int64_t session, SessionStatus status, std::optional<std::string> endedUtc = std::nullopt);
    // Adds a decision to the session's verdict trail, which makes it the
    // session's verdict (one transaction). Returns its id.
    std::int64_t decideVerdict(std::int64_t session, const VerdictDecision& decision);
    // Sets the verdict without a trail: only for an import of an export
    // made before verdicts had one.
    void setVerdict(std::int64_t session, Verdict verdict);
    // Deletes a session with its channels, samples and gaps. Throws
    // StorageError for an unknown id or a session still being recorded.
    void deleteSession(std::int64_t session);
    // Marks every "recording" session "interrupted"; only for the holder of
    // the RecorderLock, who knows no recording is live. Returns how many.
    int markCrashedSessionsInterrupted();

    // Reading.
    std::vector<SessionSummary> sessions(const SessionFilter& filter = {});  // newest first
    std::optional<SessionSummary> session(std::int64_t id);
    std::optional<std::int64_t> sessionWithUuid(const std::string& uuid);
    std::vector<StoredChannel> channels(std::int64_t session);
    std::uint64_t sampleCount(std::int64_t session);  // per channel, including gaps and lost ones at the end
    std::vector<SampleGap> gaps(std::int64_t session);
    // Samples [firstIndex, firstIndex + count) of one channel, clipped to the
    // recording; samples inside a gap read as NaN.
    std::vector<double> readChannel(std::int64_t session, std::size_t channel, std::uint64_t firstIndex,
                                    std::uint64_t count);
    // The same for several channels at once, each chunk read and decoded
    // once, into `out` (one vector per channel, resized to the samples
    // read): a reader going through a recording in windows reuses its
    // buffers and allocates nothing after the first. Returns the count.
    std::size_t readChannels(std::int64_t session, std::span<const std::size_t> channels, std::uint64_t firstIndex,
                             std::uint64_t count, std::vector<std::vector<double>>& out);
    // The min and max of about `points` stretches of samples
    // [firstIndex, firstIndex + count) of one channel, exact, read from the
    // pyramid (see LodTable::overview) without touching most samples.
    std::vector<OverviewPoint> overview(std::int64_t session, std::size_t channel, std::uint64_t firstIndex,
                                        std::uint64_t count, std::size_t points);
    // Sample chunks decoded by this connection so far: how much reading cost.
    std::uint64_t chunksRead() const { return m_chunksRead; }

    // Events, readings and annotations (SessionStoreRecords.cpp).
    void addEvents(std::int64_t session, std::span<const SessionEvent> events);  // one transaction
    std::vector<SessionEvent> events(std::int64_t session, const std::string& analysis = kLiveAnalysis);
    // "live" and the saved re-analyses, of events or readings.
    std::vector<std::string> analyses(std::int64_t session);
    std::int64_t addReading(std::int64_t session, const SessionReading& reading);
    void addReadings(std::int64_t session, std::span<const SessionReading> readings);  // one transaction
    std::vector<SessionReading> readings(std::int64_t session, const std::string& analysis = kLiveAnalysis);
    std::int64_t addAnnotation(std::int64_t session, const Annotation& annotation);
    void updateAnnotation(std::int64_t annotation, const std::string& text);
    void deleteAnnotation(std::int64_t annotation);
    std::vector<Annotation> annotations(std::int64_t session);
    std::vector<VerdictDecision> verdicts(std::int64_t session);  // the trail, oldest first
    // The zeros, by first sample; a second one at the same sample replaces the first.
    void addZero(std::int64_t session, const SessionZero& zero);
    std::vector<SessionZero> zeros(std::int64_t session);

    // The calibration history, shared by all sessions of the store.
    std::int64_t addCalibration(const calibration::CalibrationRecord& record);
    std::optional<StoredCalibration> calibration(std::int64_t id);
    std::vector<StoredCalibration>
    calibrations(const std::string& sensor = {});  // oldest first; all sensors when empty
    // The newest record of `kind` for `sensor`: the one in use.
    std::optional<StoredCalibration> newestCalibration(std::string_view kind, const std::string& sensor);
    void linkCalibration(std::int64_t session, std::int64_t calibration);  // the session used it
    std::vector<std::int64_t> calibrationsOfSession(std::int64_t session);
    std::vector<std::int64_t> sessionsUsingCalibration(std::int64_t calibration);

    // SQLite's integrity check: "ok", or its first finding.
    std::string checkIntegrity();
    // SQLite's quick check (the pages and their structure, ~1.5 GB/s, not
    // the indexes' content), before a store is written or first shown:
    // throws StorageError saying the store is damaged and what to do.
    void refuseIfDamaged();

    Database& database() { return m_db; }

private:
    void appendChunk(std::int64_t session, std::span<const SampleBlock> run);
    void rebuildPyramids(std::int64_t session);
    lod::LodTable pyramid(std::int64_t session, std::size_t channel);
    void checkSampleEnd(std::int64_t session, std::size_t channelCount, std::uint64_t samples);
    void showCrashedRecordingsInterrupted(std::span<SessionSummary> summaries);

    Database m_db;
    std::uint64_t m_chunksRead = 0;
};

// The newest record of `kind` for `sensor` in the store at `path`, opened
// read-only: none when the store does not exist yet (no calibration has been
// made). Throws StorageError when it exists but cannot be read.
std::optional<StoredCalibration> newestCalibrationIn(const std::string& path, std::string_view kind,
                                                     const std::string& sensor);

}  // namespace tactiscope::core::storage
