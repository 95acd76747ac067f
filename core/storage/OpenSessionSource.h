// Opening a store by what the user typed: a station's store file, or a
// central store's libpq connection string.
#pragma once

#include "core/storage/SessionSource.h"

#include <memory>
#include <string>
#include <string_view>

namespace tactiscope::core::storage {

// A libpq connection string: a postgresql:// or postgres:// URI, or
// key=value pairs naming host= or dbname= (a file name has neither).
bool isCentralStoreAddress(std::string_view location);

// Throws StorageError when it cannot be opened (see SessionStore and
// CentralStore).
std::unique_ptr<SessionSource> openSessionSource(const std::string& location,
                                                 Database::Access access = Database::Access::ReadWrite);

}  // namespace tactiscope::core::storage
