// The central store's schema on PostgreSQL, and its two roles: the same
// content as a local store (sessions by uuid with the station they came
// from, channels, sample chunks as bytea in the local encoding, the min/max
// pyramid, gaps, events, readings, annotations, verdict trail, zeros,
// calibrations), with row-level security so that
//   tactiscope_station  adds sessions and their records as its own station
//                       (sessions.station = its login) and reads them, and
//                       never changes or deletes another station's rows;
//   tactiscope_reviewer reads everything and adds notes and verdicts;
//   the owner (who ran `server init`) alone deletes.
// A session is visible to reviewers only once all of it has arrived
// (sessions.complete, set by the sync's last step with its checksum).
#pragma once

#include "core/storage/central/PgConnection.h"

namespace tactiscope::core::storage::central {

inline constexpr int kCentralSchemaVersion = 12;

// The text a list's search looks in (SessionFilter::text): the searched
// columns joined by a separator nobody types (the unit separator,
// chr(31)), so one trigram index serves the search and a match never
// spans two columns. The schema indexes this very expression.
inline constexpr const char* kSessionSearchText =
    "(subject || chr(31) || operator || chr(31) || site || chr(31) || notes || chr(31) || verdict || chr(31) || "
    "CASE WHEN unjudged <> '' THEN 'not judged: ' || unjudged ELSE '' END || chr(31) || device_serial)";

// Creates or upgrades the schema and the two roles; running it again
// changes nothing. Lifts the connection's time limits (an upgrade may take
// minutes: PgConnection::allowLongStatements). Throws StorageError (e.g.
// without the right to create roles).
void initCentralStore(PgConnection& connection);

}  // namespace tactiscope::core::storage::central
