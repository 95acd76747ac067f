// The session store: one SQLite file holding many inspection sessions, each
// with its metadata, channels and samples (in chunks, with the gaps where
// samples were lost). One SessionStore is one connection; use one per
// thread. Writers and readers may share the file at the same time (WAL).
#pragma once

#include "core/storage/SessionLayout.h"
#include "core/storage/SessionSource.h"

#include <functional>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tactiscope::core {
class SampleBlock;
}

namespace tactiscope::core::storage {

class SessionStore : public SessionSource {
public:
    // Opens or (read-write) creates the store; see prepareSchema() for the
    // files it refuses. Read-write and with no recorder running (see
    // RecorderLock), sessions a crash left "recording" become "interrupted",
    // with every committed sample kept. Throws StorageError.
    // Read-only, an older store is read through a private copy brought up
    // to date (see readNote()).
    SessionStore(const std::string& path, Database::Access access = Database::Access::ReadWrite);
    // The store version the file had when it was opened (0 for a new file).
    int versionFound() const { return m_versionFound; }

    std::string location() const override { return m_db.path(); }
    std::unique_ptr<Snapshot> snapshot() override;

    // Writing. Blocks are stored as they come; a block whose first sample
    // index is past the end of the previous one records a gap. A uuid
    // already in the store is refused by the schema (StorageError); an
    // import says so first, in its own words.
    std::int64_t beginSession(const SessionMetadata& metadata, std::span<const ChannelDescriptor> channels,
                              double sampleRate_hz, const SessionOrigin& origin = {});
    // A session of several devices: a row with no channels of its own,
    // whose parts are begun with beginSession() and SessionMetadata::partOf.
    std::int64_t beginSessionOfDevices(const SessionMetadata& metadata, const SessionOrigin& origin = {});
    // The mapping of a part's clock onto its session's
    // (core/timing/ClockMappingJson), replacing the one before.
    void setClockMapping(std::int64_t part, const std::string& clockJson);
    // Its signal setup (SessionMetadata::signalSetup), once its filters'
    // state at its first sample is known.
    void setSignalSetup(std::int64_t session, const std::string& setupJson);
    // One transaction. A block may hold fewer channels than the session
    // (it came before the session gained some): the rest are holes.
    void appendBlocks(std::int64_t session, std::span<const SampleBlock> blocks);
    // Channels the session gains while recorded, after its others: holes
    // (NaN) in every sample stored before.
    void addChannels(std::int64_t session, std::span<const ChannelDescriptor> added);
    // Records samples lost after the last stored ones (e.g. at the end of a
    // recording, where no later block marks the gap). No-op when none are.
    void markLostUntil(std::int64_t session, std::uint64_t endIndex);
    // Ends it now, or at `endedUtc` (an imported session's own end; empty
    // for one that never ended).
    void endSession(std::int64_t session, SessionStatus status, std::optional<std::string> endedUtc = std::nullopt);
    std::int64_t decideVerdict(std::int64_t session, const VerdictDecision& decision) override;
    // Dates its start (a triggered session's first sample came before its recorder).
    void setStartedUtc(std::int64_t session, const std::string& startedUtc);
    // Why its mode gave it no automatic verdict (SessionSummary::unjudged).
    void markUnjudged(std::int64_t session, const std::string& why);
    // Sets the verdict without a trail: only for an import of an export
    // made before verdicts had one.
    void setVerdict(std::int64_t session, Verdict verdict);
    void deleteSession(std::int64_t session) override;
    // Marks every "recording" session "interrupted"; only for the holder of
    // the RecorderLock, who knows no recording is live. Returns how many.
    int markCrashedSessionsInterrupted();

    // Reading (see SessionSource).
    std::vector<SessionSummary> sessions(const SessionFilter& filter = {}) override;
    std::optional<SessionSummary> session(std::int64_t id) override;
    std::optional<std::int64_t> sessionWithUuid(const std::string& uuid) override;
    std::optional<std::int64_t> lastSession() override;
    std::vector<StoredChannel> channels(std::int64_t session) override;
    std::vector<SessionPart> parts(std::int64_t session) override;
    std::uint64_t sampleCount(std::int64_t session) override;
    std::vector<SampleGap> gaps(std::int64_t session) override;
    std::size_t readChannels(std::int64_t session, std::span<const std::size_t> channels, std::uint64_t firstIndex,
                             std::uint64_t count, std::vector<std::vector<double>>& out) override;
    std::vector<OverviewPoint> overview(std::int64_t session, std::size_t channel, std::uint64_t firstIndex,
                                        std::uint64_t count, std::size_t points) override;
    // The rows as stored, for a copy that must be bit-identical (the sync
    // to a central store): chunks by first sample, then the pyramid's rows.
    // The spans are valid during the call only.
    struct RawChunk {
        std::uint64_t firstIndex = 0;
        double firstTime_s = 0.0;
        std::uint64_t count = 0;
        std::span<const std::uint8_t> samples;
    };
    struct RawLodRow {
        std::int64_t channel = 0;
        std::int64_t level = 0;
        std::uint64_t firstBucket = 0;
        std::uint64_t count = 0;
        std::span<const std::uint8_t> buckets;
    };
    void forEachChunk(std::int64_t session, const std::function<void(const RawChunk&)>& visit);
    void forEachLodRow(std::int64_t session, const std::function<void(const RawLodRow&)>& visit);

    // Events, readings and annotations (SessionStoreRecords.cpp).
    void addEvents(std::int64_t session, std::span<const SessionEvent> events) override;
    std::vector<SessionEvent> events(std::int64_t session, const std::string& analysis = kLiveAnalysis) override;
    std::vector<std::string> analyses(std::int64_t session) override;
    std::int64_t addReading(std::int64_t session, const SessionReading& reading);
    void addReadings(std::int64_t session, std::span<const SessionReading> readings) override;
    std::vector<SessionReading> readings(std::int64_t session, const std::string& analysis = kLiveAnalysis) override;
    std::int64_t addAnnotation(std::int64_t session, const Annotation& annotation) override;
    void updateAnnotation(std::int64_t annotation, const std::string& text) override;
    void deleteAnnotation(std::int64_t annotation) override;
    std::vector<Annotation> annotations(std::int64_t session) override;
    std::vector<VerdictDecision> verdicts(std::int64_t session) override;
    // A second zero at the same sample replaces the first.
    void addZero(std::int64_t session, const SessionZero& zero);
    std::vector<SessionZero> zeros(std::int64_t session) override;

    // The calibration history, shared by all sessions of the store.
    std::int64_t addCalibration(const calibration::CalibrationRecord& record) override;
    std::optional<StoredCalibration> calibration(std::int64_t id) override;
    std::vector<StoredCalibration> calibrations(const std::string& sensor = {}) override;
    void linkCalibration(std::int64_t session, std::int64_t calibration);  // the session used it
    std::vector<std::int64_t> calibrationsOfSession(std::int64_t session) override;
    std::vector<std::int64_t> sessionsUsingCalibration(std::int64_t calibration) override;

    // SQLite's integrity check: "ok", or its first finding.
    std::string checkIntegrity();
    // SQLite's quick check (the pages and their structure, ~1.5 GB/s, not
    // the indexes' content), before a store is written or first shown:
    // throws StorageError saying the store is damaged and what to do.
    void refuseIfDamaged() override;
    std::optional<std::string> readNote() const override { return m_db.note(); }
    Rights rights() const override;

    Database& database() { return m_db; }

private:
    void appendChunk(std::int64_t session, std::span<const SampleBlock> run);
    void rebuildPyramids(std::int64_t session);
    void buildPyramidsOfVersion1();
    lod::LodTable pyramid(std::int64_t session, std::size_t channel);
    void showCrashedRecordingsInterrupted(std::span<SessionSummary> summaries);
    std::int64_t insertSessionRow(const SessionMetadata& metadata, const SessionOrigin& origin);
    void insertChannelRows(std::int64_t session, std::span<const ChannelDescriptor> channels, std::size_t firstPosition,
                           double sampleRate_hz);
    // Channels [from, from + added) of every stored chunk and their
    // pyramids, as holes (SessionGrowth.cpp).
    void padChunks(std::int64_t session, std::size_t from, std::size_t added);
    void refuseUnknownParent(std::int64_t session);

    Database m_db;
    int m_versionFound = 0;
    SessionLayout m_layout{m_db};  // checked before any count read sizes anything
};

// The newest record of `kind` for `sensor` in the store at `path`, opened
// read-only: none when the store does not exist yet (no calibration has been
// made). Throws StorageError when it exists but cannot be read.
std::optional<StoredCalibration> newestCalibrationIn(const std::string& path, std::string_view kind,
                                                     const std::string& sensor);

}  // namespace tactiscope::core::storage
