// The session store's schema: its version (PRAGMA user_version), the forward
// migrations that bring an older store up to date, and the checks that keep
// us from writing into a file that is not ours. docs/storage.md describes
// every table.
#pragma once

#include "core/storage/Database.h"

namespace tactiscope::core::storage {

inline constexpr int kSchemaVersion = 11;
// PRAGMA application_id of a Tactiscope store: "TSC1" in ASCII.
inline constexpr std::int64_t kApplicationId = 0x54534331;

// Makes `db` a current Tactiscope store: creates the schema in an empty
// file, migrates an older one (read-write, or a private copy read in its
// place; a read-only connection to an older store is left as it is, for
// SessionStore to read through such a copy). Rows a delete outside
// Tactiscope left without their session are removed before a migration,
// and said in the database's note. Throws StorageError, and leaves the file
// untouched, when it is another program's SQLite file, is not an SQLite
// file, or has a newer schema than this build and is opened read-write
// (read-only works: tables are only ever added to). Returns the version
// the file had (0 for a new file). `targetVersion` below the current one
// is for tests that need an old store.
int prepareSchema(Database& db, int targetVersion = kSchemaVersion);

}  // namespace tactiscope::core::storage
