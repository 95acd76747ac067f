// Exporting a stored session for other tools:
//  - CSV: a header `t` then the channel names, one row per stored sample,
//    t in seconds from the session start (index / sample rate); samples in
//    gaps have no row. Values are written as the shortest text that reads
//    back to the same binary32, so a re-import is exact to the bit.
//  - metadata JSON (the CSV's side file, and part of the JSON export): the
//    session's fields, its channels and its gaps.
//  - JSON: the metadata plus "t" and one array per channel.
// Samples are read in windows, so memory stays small for hour-long sessions.
#pragma once

#include "core/storage/SessionStore.h"

#include <ostream>

namespace tactiscope::core::storage {

void writeSessionCsv(SessionStore& store, std::int64_t session, std::ostream& out);
void writeSessionMetadataJson(SessionStore& store, std::int64_t session, std::ostream& out);
void writeSessionJson(SessionStore& store, std::int64_t session, std::ostream& out);

}  // namespace tactiscope::core::storage
