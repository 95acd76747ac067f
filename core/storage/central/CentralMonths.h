// The central store's months: chunks and the pyramid are partitioned by the
// month of their session's start (schema 11), each month a table of each
// in the schema `months`. What `server maintain` does with them, as the
// store's owner: make the coming months before any station needs them,
// detach the old ones so they can be archived apart from the store, and
// attach one again.
#pragma once

#include "core/storage/central/PgConnection.h"

#include <string>
#include <vector>

namespace tactiscope::core::storage::central {

// A month as "YYYY-MM".
struct StoreMonth {
    std::string month;
    bool attached = false;   // in the store; else detached, its tables still in the database
    std::int64_t bytes = 0;  // of its tables and their indexes (0 when they were dropped)
};

// Every month the store has made, oldest first.
std::vector<StoreMonth> storeMonths(PgConnection& owner);

// Makes this month's (by the server's clock) and the next `ahead` months'
// tables where missing; returns those made now.
std::vector<std::string> makeComingMonths(PgConnection& owner, int ahead);

// Detaches every attached month before `before` ("YYYY-MM", not after the
// current month): its sessions stay listed, their samples are out of the
// store until attached again. Returns the months detached.
std::vector<std::string> detachMonthsBefore(PgConnection& owner, const std::string& before);

// Attaches a detached month again; false when it is in the store already.
// Throws StorageError when the store never held it, or its tables are gone
// (archived and dropped: restore them first).
bool attachMonth(PgConnection& owner, const std::string& month);

// Whether `text` is a month as "YYYY-MM".
bool isMonthText(const std::string& text);

}  // namespace tactiscope::core::storage::central
