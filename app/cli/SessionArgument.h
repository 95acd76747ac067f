// The store and session named on the command line. --db is a station's
// store file or a central store's libpq connection string; a session is
// its id, its uuid (ids differ from store to store, a uuid names the same
// session in all), or "last" for the newest.
#pragma once

#include "core/storage/SessionSource.h"

#include <QString>

#include <memory>
#include <optional>

namespace tactiscope::cli {

// Whether --db names something to open: a connection string, or a file
// that exists (a reader never creates a store).
bool storeArgumentExists(const QString& db);
// Opens it and prints what the reader should know of how it was read
// (printStoreNote).
std::unique_ptr<core::storage::SessionSource> openStoreArgument(const QString& db,
                                                                core::storage::Database::Access access);
// "note: …" on standard error when the store was not read as it is (a
// private copy, an older version brought up to date, rows left out).
void printStoreNote(const core::storage::SessionSource& store);

// Nothing when `text` names no session of the store.
std::optional<std::int64_t> resolveSession(core::storage::SessionSource& store, const QString& text);

}  // namespace tactiscope::cli
