// SessionStore: SQL for events, readings, annotations and calibrations.
#include "core/storage/SessionStore.h"

#include "core/text/UtcTime.h"

#include <filesystem>
#include <stdexcept>

namespace tactiscope::core::storage {
namespace {

Statement& bindOptional(Statement& statement, int index, std::optional<double> value)
{
    return value ? statement.bind(index, *value) : statement.bindNull(index);
}

std::optional<double> optionalReal(const Statement& row, int column)
{
    if (row.isNull(column)) return std::nullopt;
    return row.real(column);
}

StoredCalibration calibrationFrom(const Statement& row)
{
    try {
        return {row.int64(0), calibration::CalibrationRecord::fromJson(row.text(1))};
    } catch (const std::invalid_argument& e) {
        throw StoreInputError("calibration " + std::to_string(row.int64(0)) + " cannot be read (" + e.what() +
                              "); the store is damaged");
    }
}

// The ids a one-parameter query returns.
std::vector<std::int64_t> ids(Database& db, std::string_view sql, std::int64_t parameter)
{
    std::vector<std::int64_t> result;
    auto query = db.prepare(sql);
    query.bind(1, parameter);
    while (query.step()) result.push_back(query.int64(0));
    return result;
}

}  // namespace

void SessionStore::addEvents(std::int64_t session, std::span<const SessionEvent> events)
{
    Transaction transaction(m_db);
    auto insert = m_db.prepare("INSERT INTO events (session_id, analysis, kind, start_s, end_s, direction, peak_r, "
                               "lag_s, speed_m_per_s, note) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    for (const SessionEvent& e : events) {
        insert.bind(1, session)
            .bind(2, e.analysis)
            .bind(3, toString(e.kind))
            .bind(4, e.start_s)
            .bind(5, e.end_s)
            .bind(6, std::int64_t{e.direction});
        bindOptional(insert, 7, e.peakR);
        bindOptional(insert, 8, e.lag_s);
        bindOptional(insert, 9, e.speed_m_per_s);
        insert.bind(10, e.note).run();
    }
    transaction.commit();
}

std::vector<SessionEvent> SessionStore::events(std::int64_t session, const std::string& analysis)
{
    std::vector<SessionEvent> result;
    auto query = m_db.prepare("SELECT id, analysis, kind, start_s, end_s, direction, peak_r, lag_s, speed_m_per_s, "
                              "note FROM events WHERE session_id = ? AND analysis = ? ORDER BY start_s, id");
    query.bind(1, session).bind(2, analysis);
    while (query.step()) {
        // The schema's CHECK admits only the vocabulary's kinds.
        result.push_back({query.int64(0), query.text(1), eventKindFromString(query.text(2)).value_or(EventKind::Marker),
                          query.real(3), query.real(4), static_cast<int>(query.int64(5)), optionalReal(query, 6),
                          optionalReal(query, 7), optionalReal(query, 8), query.text(9)});
    }
    return result;
}

std::vector<std::string> SessionStore::analyses(std::int64_t session)
{
    std::vector<std::string> result{kLiveAnalysis};
    auto query = m_db.prepare("SELECT analysis FROM events WHERE session_id = ?1 AND analysis <> ?2 UNION "
                              "SELECT analysis FROM readings WHERE session_id = ?1 AND analysis <> ?2 ORDER BY 1");
    query.bind(1, session).bind(2, std::string_view(kLiveAnalysis));
    while (query.step()) result.push_back(query.text(0));
    return result;
}

std::int64_t SessionStore::addReading(std::int64_t session, const SessionReading& r)
{
    auto insert =
        m_db.prepare("INSERT INTO readings (session_id, kind, start_s, end_s, quantity, value, unit, "
                     "standard_error, site, details_json, analysis) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    insert.bind(1, session).bind(2, toString(r.kind)).bind(3, r.start_s).bind(4, r.end_s).bind(5, r.quantity);
    insert.bind(6, r.value).bind(7, r.unit);
    bindOptional(insert, 8, r.standardError);
    insert.bind(9, r.site).bind(10, r.detailsJson).bind(11, r.analysis).run();
    return m_db.lastInsertId();
}

void SessionStore::addReadings(std::int64_t session, std::span<const SessionReading> readings)
{
    Transaction transaction(m_db);
    for (const auto& reading : readings) addReading(session, reading);
    transaction.commit();
}

std::vector<SessionReading> SessionStore::readings(std::int64_t session, const std::string& analysis)
{
    std::vector<SessionReading> result;
    auto query = m_db.prepare("SELECT id, kind, start_s, end_s, quantity, value, unit, standard_error, site, "
                              "details_json, analysis FROM readings WHERE session_id = ? AND analysis = ? "
                              "ORDER BY start_s, id");
    query.bind(1, session).bind(2, analysis);
    while (query.step()) {
        result.push_back({query.int64(0), readingKindFromString(query.text(1)).value_or(ReadingKind::Compliance),
                          query.real(2), query.real(3), query.text(4), query.real(5), query.text(6),
                          optionalReal(query, 7), query.text(8), query.text(9), query.text(10)});
    }
    return result;
}

std::int64_t SessionStore::addAnnotation(std::int64_t session, const Annotation& a)
{
    const std::string now = text::utcNow();
    m_db.prepare("INSERT INTO annotations (session_id, time_s, author, text, created_utc, modified_utc) "
                 "VALUES (?, ?, ?, ?, ?, ?)")
        .bind(1, session)
        .bind(2, a.time_s)
        .bind(3, a.author)
        .bind(4, a.text)
        .bind(5, a.createdUtc.empty() ? now : a.createdUtc)
        .bind(6, a.modifiedUtc.empty() ? now : a.modifiedUtc)
        .run();
    return m_db.lastInsertId();
}

void SessionStore::updateAnnotation(std::int64_t annotation, const std::string& text)
{
    m_db.prepare("UPDATE annotations SET text = ?, modified_utc = ? WHERE id = ?")
        .bind(1, text)
        .bind(2, text::utcNow())
        .bind(3, annotation)
        .run();
    if (m_db.changes() == 0) throw StorageError("there is no annotation " + std::to_string(annotation));
}

void SessionStore::deleteAnnotation(std::int64_t annotation)
{
    m_db.prepare("DELETE FROM annotations WHERE id = ?").bind(1, annotation).run();
    if (m_db.changes() == 0) throw StorageError("there is no annotation " + std::to_string(annotation));
}

std::vector<Annotation> SessionStore::annotations(std::int64_t session)
{
    std::vector<Annotation> result;
    auto query = m_db.prepare("SELECT id, time_s, author, text, created_utc, modified_utc FROM annotations "
                              "WHERE session_id = ? ORDER BY time_s, id");
    query.bind(1, session);
    while (query.step())
        result.push_back({query.int64(0), query.real(1), query.text(2), query.text(3), query.text(4), query.text(5)});
    return result;
}

std::int64_t SessionStore::decideVerdict(std::int64_t session, const VerdictDecision& d)
{
    Transaction transaction(m_db);
    setVerdict(session, d.verdict);
    m_db.prepare("INSERT INTO verdicts (session_id, role, verdict, decided_by, decided_utc, note, basis_json) "
                 "VALUES (?, ?, ?, ?, ?, ?, ?)")
        .bind(1, session)
        .bind(2, toString(d.role))
        .bind(3, toString(d.verdict))
        .bind(4, d.decidedBy)
        .bind(5, d.decidedUtc.empty() ? text::utcNow() : d.decidedUtc)
        .bind(6, d.note)
        .bind(7, d.basisJson)
        .run();
    const std::int64_t id = m_db.lastInsertId();
    transaction.commit();
    return id;
}

std::vector<VerdictDecision> SessionStore::verdicts(std::int64_t session)
{
    std::vector<VerdictDecision> result;
    auto query = m_db.prepare("SELECT id, role, verdict, decided_by, decided_utc, note, basis_json FROM verdicts "
                              "WHERE session_id = ? ORDER BY id");
    query.bind(1, session);
    while (query.step()) {
        // The schema's CHECKs admit only the vocabulary's words.
        result.push_back({query.int64(0), verdictRoleFromString(query.text(1)).value_or(VerdictRole::Reviewer),
                          verdictFromString(query.text(2)).value_or(Verdict::DefectsFound), query.text(3),
                          query.text(4), query.text(5), query.text(6)});
    }
    return result;
}

void SessionStore::addZero(std::int64_t session, const SessionZero& zero)
{
    m_db.prepare("INSERT OR REPLACE INTO zeros (session_id, first_index, values_json) VALUES (?, ?, ?)")
        .bind(1, session)
        .bind(2, static_cast<std::int64_t>(zero.firstIndex))
        .bind(3, zero.valuesJson)
        .run();
}

std::vector<SessionZero> SessionStore::zeros(std::int64_t session)
{
    std::vector<SessionZero> result;
    auto query = m_db.prepare("SELECT first_index, values_json FROM zeros WHERE session_id = ? ORDER BY first_index");
    query.bind(1, session);
    while (query.step()) result.push_back({static_cast<std::uint64_t>(query.int64(0)), query.text(1)});
    return result;
}

std::int64_t SessionStore::addCalibration(const calibration::CalibrationRecord& record)
{
    m_db.prepare("INSERT INTO calibrations (kind, sensor, operator, created_utc, r_squared, points, record_json) "
                 "VALUES (?, ?, ?, ?, ?, ?, ?)")
        .bind(1, record.kind)
        .bind(2, record.sensorName)
        .bind(3, record.operatorName)
        .bind(4, record.timestampUtc)
        .bind(5, record.fit.rSquared)
        .bind(6, static_cast<std::int64_t>(record.fit.points))
        .bind(7, record.toJson())
        .run();
    return m_db.lastInsertId();
}

std::optional<StoredCalibration> SessionStore::calibration(std::int64_t id)
{
    auto query = m_db.prepare("SELECT id, record_json FROM calibrations WHERE id = ?");
    query.bind(1, id);
    if (!query.step()) return std::nullopt;
    return calibrationFrom(query);
}

std::vector<StoredCalibration> SessionStore::calibrations(const std::string& sensor)
{
    std::vector<StoredCalibration> result;
    auto query = m_db.prepare("SELECT id, record_json FROM calibrations WHERE ?1 = '' OR sensor = ?1 "
                              "ORDER BY created_utc, id");
    query.bind(1, sensor);
    while (query.step()) result.push_back(calibrationFrom(query));
    return result;
}

std::optional<StoredCalibration> newestCalibrationIn(const std::string& path, std::string_view kind,
                                                     const std::string& sensor)
{
    if (!std::filesystem::exists(path)) return std::nullopt;
    return SessionStore(path, Database::Access::ReadOnly).newestCalibration(kind, sensor);
}

void SessionStore::linkCalibration(std::int64_t session, std::int64_t calibration)
{
    m_db.prepare("INSERT OR IGNORE INTO session_calibrations VALUES (?, ?)")
        .bind(1, session)
        .bind(2, calibration)
        .run();
}

std::vector<std::int64_t> SessionStore::calibrationsOfSession(std::int64_t session)
{
    return ids(m_db, "SELECT calibration_id FROM session_calibrations WHERE session_id = ? ORDER BY calibration_id",
               session);
}

std::vector<std::int64_t> SessionStore::sessionsUsingCalibration(std::int64_t calibration)
{
    return ids(m_db, "SELECT session_id FROM session_calibrations WHERE calibration_id = ? ORDER BY session_id",
               calibration);
}

}  // namespace tactiscope::core::storage
