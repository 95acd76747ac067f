// Where sessions are read from: a station's own SQLite store
// (SessionStore) or a site's central PostgreSQL store (CentralStore). The
// browser, the review window, export, report and analyze read through this
// interface, so they work on either; recording and import write to a
// station's store only. One object is one connection; use one per thread.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/Vocabulary.h"
#include "core/storage/Database.h"
#include "core/storage/LodTable.h"
#include "core/storage/SessionRecords.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

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
    // What cut a triggered recording (core/trigger): "a>2e-05, pre 0.5 s,
    // post 1 s, hold-off 0 s"; empty for a recording started by hand.
    std::string trigger;
    // A session of several devices records each into a part of it: the
    // session's id and the device's name in it ("load-cell"); 0 and empty
    // for a session of its own.
    std::int64_t partOf = 0;
    std::string deviceName;
    // Its signal setup (core/signal/SignalSetup.h: filters, math
    // channels), as JSON; empty for none.
    std::string signalSetup = {};
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
    std::string unjudged;            // why its mode gave no automatic verdict; empty when it gave one or judges nothing
    std::string appVersion;
    double sampleRate_hz = 0.0;
    std::uint64_t sampleCount = 0;  // per channel, including lost samples
    std::uint64_t eventCount = 0;   // live events of any kind
    std::string station;            // the station it came from, on a central store; empty on a station's own
    std::int64_t stationId = 0;     // its id in that station's store (0 on a station's own: `id`)
    std::size_t devices = 0;        // its parts, for a session of several devices (then the longest part's
                                    // rate and count above); 0 for a session of one
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
    std::optional<SessionStatus> status;  // as listed: a crashed recording is interrupted
    std::string station;                  // exact; a central store's (a station's file names none)
    std::string text;       // found in subject, operator, site, notes, verdict, why none, or device serial (any case)
    std::size_t limit = 0;  // only the newest this many; 0: all
    // The next page: only those listed after this session, in the list's
    // order (older by start, then by id): keyset paging, which stays as
    // fast on the last page as on the first.
    std::optional<std::int64_t> after;
};

// Why `what` ("a report"), which reads one device's samples, cannot take
// `session`: it holds several devices. Names each part's session, which
// it can take. None for a session of one device.
class SessionSource;
std::optional<std::string> oneDeviceRefusal(SessionSource& store, std::int64_t session, const std::string& what);

// Why `session` may not be deleted alone: it is one device's part of a
// session of several, whose verdict and events count it. None otherwise.
std::optional<std::string> partDeletionRefusal(const SessionSummary& session);

// The LIKE pattern (escaped by a backslash) that finds SessionFilter::text
// anywhere in a column: its own '%' and '_' are literal, so "10%" finds "10%".
std::string textSearchPattern(const std::string& text);

using lod::OverviewPoint;

struct StoredChannel {
    ChannelDescriptor descriptor;
    double sampleRate_hz = 0.0;
};

// One device's part of a session of several: a session of its own (its
// channels, samples and gaps are read through `id`), at the device's rate
// and on its clock, with the mapping of that clock onto the session's.
struct SessionPart {
    std::int64_t id = 0;
    std::string deviceName;
    std::string deviceModel;
    std::string deviceSerial;
    std::string deviceFirmware;
    // core/timing/ClockMappingJson: the part's session time → the
    // session's, with its uncertainty; empty until one was found.
    std::string clockJson;
    SessionStatus status = SessionStatus::Recording;
};

struct SampleGap {
    std::uint64_t firstIndex = 0;
    std::uint64_t count = 0;
};

class SessionSource {
public:
    virtual ~SessionSource() = default;

    // What to call it in a message: the store file, or the server and
    // database (never a password).
    virtual std::string location() const = 0;
    // Throws StorageError saying the store is damaged and what to do,
    // before a store is written or first shown.
    virtual void refuseIfDamaged() = 0;
    // What a reader should be told about how the store was read (see
    // Database::note()); none when it was read as it is.
    virtual std::optional<std::string> readNote() const { return std::nullopt; }

    // What this connection may change, each with the reason it may not
    // (empty: it may), so a window disables an action, and says why, before
    // the store would refuse it. A central store's role decides; a station's
    // file allows everything unless it is open read-only.
    struct Rights {
        std::string noDelete;           // deleting sessions
        std::string noReviewerVerdict;  // adding a reviewer's decision
        std::string noNotes;            // adding, changing and deleting notes
        std::string noAnalyses;         // saving a re-analysis
    };
    virtual Rights rights() const { return {}; }

    // One consistent state of the store for as long as it lives, for a
    // reader going through a session while another connection writes.
    class Snapshot {
    public:
        virtual ~Snapshot() = default;
    };
    virtual std::unique_ptr<Snapshot> snapshot() = 0;

    virtual std::vector<SessionSummary> sessions(const SessionFilter& filter = {}) = 0;  // newest first
    virtual std::optional<SessionSummary> session(std::int64_t id) = 0;
    virtual std::optional<std::int64_t> sessionWithUuid(const std::string& uuid) = 0;
    // The session stored last (the store's ids count up, whatever the host's
    // clock said when it began: a clock set back, an import of an old
    // export), of one device or of several (never a part): one indexed row
    // however large the store. None in an empty store.
    virtual std::optional<std::int64_t> lastSession() = 0;
    // The stations whose whole sessions this login may see, by name (a
    // central store's; a station's own store names none).
    virtual std::vector<std::string> stations() { return {}; }
    virtual std::vector<StoredChannel> channels(std::int64_t session) = 0;
    // A session of several devices' parts, in the order they were begun;
    // none for a session of one device (its channels are its own).
    virtual std::vector<SessionPart> parts(std::int64_t session) = 0;
    // A session of several devices lasts as long as its longest part: its
    // rate and count stand for the session's in a list.
    void fillFromLongestPart(SessionSummary& summary);
    // Per channel, including gaps and lost ones at the end.
    virtual std::uint64_t sampleCount(std::int64_t session) = 0;
    virtual std::vector<SampleGap> gaps(std::int64_t session) = 0;
    // Samples [firstIndex, firstIndex + count) of one channel, clipped to the
    // recording; samples inside a gap read as NaN.
    std::vector<double> readChannel(std::int64_t session, std::size_t channel, std::uint64_t firstIndex,
                                    std::uint64_t count);
    // The same for several channels at once, each chunk read and decoded
    // once, into `out` (one vector per channel, resized to the samples
    // read): a reader going through a recording in windows reuses its
    // buffers and allocates nothing after the first. Returns the count.
    virtual std::size_t readChannels(std::int64_t session, std::span<const std::size_t> channels,
                                     std::uint64_t firstIndex, std::uint64_t count,
                                     std::vector<std::vector<double>>& out) = 0;
    // The min and max of about `points` stretches of samples
    // [firstIndex, firstIndex + count) of one channel, exact, read from the
    // pyramid (see LodTable::overview) without touching most samples.
    virtual std::vector<OverviewPoint> overview(std::int64_t session, std::size_t channel, std::uint64_t firstIndex,
                                                std::uint64_t count, std::size_t points) = 0;
    // Sample chunks decoded by this connection so far: how much reading cost.
    std::uint64_t chunksRead() const { return m_chunksRead; }

    virtual std::vector<SessionEvent> events(std::int64_t session, const std::string& analysis = kLiveAnalysis) = 0;
    // "live" and the saved re-analyses, of events or readings.
    virtual std::vector<std::string> analyses(std::int64_t session) = 0;
    virtual std::vector<SessionReading> readings(std::int64_t session, const std::string& analysis = kLiveAnalysis) = 0;
    virtual std::vector<Annotation> annotations(std::int64_t session) = 0;
    virtual std::vector<VerdictDecision> verdicts(std::int64_t session) = 0;  // the trail, oldest first
    // The zeros, by first sample.
    virtual std::vector<SessionZero> zeros(std::int64_t session) = 0;
    virtual std::optional<StoredCalibration> calibration(std::int64_t id) = 0;
    // Oldest first; all sensors when empty.
    virtual std::vector<StoredCalibration> calibrations(const std::string& sensor = {}) = 0;
    // The newest record of `kind` for `sensor`: the one in use.
    std::optional<StoredCalibration> newestCalibration(std::string_view kind, const std::string& sensor);
    // Adds to the calibration history; returns its id.
    virtual std::int64_t addCalibration(const calibration::CalibrationRecord& record) = 0;
    virtual std::vector<std::int64_t> calibrationsOfSession(std::int64_t session) = 0;
    virtual std::vector<std::int64_t> sessionsUsingCalibration(std::int64_t calibration) = 0;

    // What a reviewer adds (each refused with StorageError where the
    // store's rights do not allow it).
    // Adds a decision to the session's verdict trail, which makes it the
    // session's verdict (one transaction). Returns its id.
    virtual std::int64_t decideVerdict(std::int64_t session, const VerdictDecision& decision) = 0;
    virtual std::int64_t addAnnotation(std::int64_t session, const Annotation& annotation) = 0;
    virtual void updateAnnotation(std::int64_t annotation, const std::string& text) = 0;
    virtual void deleteAnnotation(std::int64_t annotation) = 0;
    // A saved re-analysis (one transaction each).
    virtual void addEvents(std::int64_t session, std::span<const SessionEvent> events) = 0;
    virtual void addReadings(std::int64_t session, std::span<const SessionReading> readings) = 0;
    // Deletes a session with everything it holds. Throws StorageError for an
    // unknown id or a session still being recorded.
    virtual void deleteSession(std::int64_t session) = 0;

protected:
    std::uint64_t m_chunksRead = 0;
};

}  // namespace tactiscope::core::storage
