// A site's central store on PostgreSQL, read as a station's store is: the
// sessions the stations synced (CentralSync), each with the station it came
// from. What a connection may see and add is the server's to decide (roles
// and row-level security, see CentralSchema): a station sees its own
// sessions, a reviewer all finished ones. Only finished uploads are listed:
// a session a sync is still sending is not there yet.
#pragma once

#include "core/storage/SessionSource.h"
#include "core/storage/central/PgConnection.h"

#include <map>
#include <memory>
#include <set>

namespace tactiscope::core::storage::central {

class CentralStore : public SessionSource {
public:
    // Connects with a libpq connection string. Read-only makes every
    // transaction of the connection read-only on the server too. Throws
    // StorageError when the server cannot be reached or has no Tactiscope
    // schema ("run server init"). A string naming a read replica (a hot
    // standby) reads there and writes on the primary it names beside it
    // (host=replica,primary target_session_attrs=prefer-standby), each
    // write read back once the replica has it; naming none, every write
    // says how to name one (rights() too).
    CentralStore(const std::string& conninfo, Database::Access access = Database::Access::ReadWrite);

    std::string location() const override { return m_connection.location(); }
    // A session on the central store is whole and its samples never change
    // (it is listed only once complete): each read is consistent alone.
    std::unique_ptr<Snapshot> snapshot() override { return std::make_unique<Snapshot>(); }
    PgConnection& connection() { return m_connection; }
    // Whether the store read is a read replica (a hot standby).
    bool isReplica() const;
    // The server keeps its own pages whole (checksums, WAL): nothing to check here.
    void refuseIfDamaged() override {}
    // What the login's role may do (read once, at connecting).
    Rights rights() const override { return m_rights; }

    std::vector<SessionSummary> sessions(const SessionFilter& filter = {}) override;
    // The server's plan for sessions(filter) (EXPLAIN, JSON): how a list is
    // answered at scale, for the test that every filter has an index path.
    std::string listingPlan(const SessionFilter& filter);
    std::optional<SessionSummary> session(std::int64_t id) override;
    std::optional<std::int64_t> sessionWithUuid(const std::string& uuid) override;
    std::optional<std::int64_t> lastSession() override;
    std::vector<std::string> stations() override;
    std::vector<StoredChannel> channels(std::int64_t session) override;
    std::vector<SessionPart> parts(std::int64_t session) override;
    std::uint64_t sampleCount(std::int64_t session) override;
    std::vector<SampleGap> gaps(std::int64_t session) override;
    std::size_t readChannels(std::int64_t session, std::span<const std::size_t> channels, std::uint64_t firstIndex,
                             std::uint64_t count, std::vector<std::vector<double>>& out) override;
    std::vector<OverviewPoint> overview(std::int64_t session, std::size_t channel, std::uint64_t firstIndex,
                                        std::uint64_t count, std::size_t points) override;

    std::vector<SessionEvent> events(std::int64_t session, const std::string& analysis = kLiveAnalysis) override;
    std::vector<std::string> analyses(std::int64_t session) override;
    std::vector<SessionReading> readings(std::int64_t session, const std::string& analysis = kLiveAnalysis) override;
    std::vector<Annotation> annotations(std::int64_t session) override;
    std::vector<VerdictDecision> verdicts(std::int64_t session) override;
    std::vector<SessionZero> zeros(std::int64_t session) override;
    std::optional<StoredCalibration> calibration(std::int64_t id) override;
    std::vector<StoredCalibration> calibrations(const std::string& sensor = {}) override;
    std::int64_t addCalibration(const calibration::CalibrationRecord& record) override;
    std::vector<std::int64_t> calibrationsOfSession(std::int64_t session) override;
    std::vector<std::int64_t> sessionsUsingCalibration(std::int64_t calibration) override;

    std::int64_t decideVerdict(std::int64_t session, const VerdictDecision& decision) override;
    std::int64_t addAnnotation(std::int64_t session, const Annotation& annotation) override;
    void updateAnnotation(std::int64_t annotation, const std::string& text) override;
    void deleteAnnotation(std::int64_t annotation) override;
    void addEvents(std::int64_t session, std::span<const SessionEvent> events) override;
    void addReadings(std::int64_t session, std::span<const SessionReading> readings) override;
    void deleteSession(std::int64_t session) override;

    // For a copy of a station's session (CentralSync): a decision added to
    // the trail as it was decided, without making it the session's verdict
    // (the copied session row holds that); and a zero.
    std::int64_t addToVerdictTrail(std::int64_t session, const VerdictDecision& decision);
    void addZero(std::int64_t session, const SessionZero& zero);

private:
    // A list's SQL and its parameters.
    struct Listing {
        std::string sql;
        PgParams values;
    };
    static Listing listing(const SessionFilter& filter);
    std::vector<std::int64_t> ids(const std::string& sql, std::int64_t parameter);
    // A listed session's rows checked against its own bounds (SessionBounds)
    // before any count read from the server sizes anything: the server's
    // constraints hold for rows added since schema 5, not for older ones or
    // the owner's. Once per session: a listed session never changes.
    void checkLayout(std::int64_t session);
    // Throws where a session's samples went when its month was detached.
    void refuseIfDetached(std::int64_t session);

    // Where writes go: the connection, or a replica's primary; throws the
    // reason when a replica names no primary.
    PgConnection& writer();
    // Waits until the replica has replayed what was written on the primary.
    void caughtUp();

    PgConnection m_connection;
    std::unique_ptr<PgConnection> m_primary;  // a replica's primary, for writes
    std::string m_noPrimary;                  // why a replica takes no write
    Rights m_rights;
    std::set<std::int64_t> m_checked;
    std::map<std::int64_t, std::string> m_detached;  // why a session's samples are not here
};

}  // namespace tactiscope::core::storage::central
