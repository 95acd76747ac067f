// A session named on the command line: its id, its uuid (ids differ from
// store to store, a uuid names the same session in all), or "last" for the
// newest.
#pragma once

#include "core/storage/SessionStore.h"

#include <QString>

#include <optional>

namespace tactiscope::cli {

// Nothing when `text` names no session of the store.
std::optional<std::int64_t> resolveSession(core::storage::SessionStore& store, const QString& text);

}  // namespace tactiscope::cli
