// Importing a CSV recording from another DAQ program, or a Tactiscope CSV
// export, as a new session, so its data can be reviewed and analysed here.
//
// Columns: a time column (seconds; "ms" or "us" in the header's brackets
// scale it) or a fixed rate, and data columns named "name", "name [unit]"
// or "name (unit)"; the unit tells the kind (N force, mm position, pF
// capacitance), and unitless columns of a panel scan are strains. With a time column the rate is the median step, and a
// missing row becomes a gap, as a lost sample does when recording; times
// off the sample grid are refused (resample the file first). The session
// starts at the first row (t = 0). A "nan" or empty cell is a sample
// without a value.
//
// A Tactiscope export's side file (X.meta.json beside X.csv) restores the
// channels' units and kinds, the exact rate, the session's metadata and
// its events, readings and annotations; options given explicitly win. An
// export of a whole session also brings back its identity: uuid, started
// and ended times, status, verdict, app version and the samples lost at
// its end. A session whose uuid is already in the store is refused.
//
// Samples are stored as binary32, like recorded ones, so an export of a
// session imported from a Tactiscope export is the same file, to the bit.
#pragma once

#include "core/UnitScale.h"
#include "core/io/CsvColumns.h"
#include "core/modes/ChannelRoles.h"
#include "core/storage/SessionStore.h"

#include <functional>
#include <optional>

namespace tactiscope::core::storage {

struct CsvImportOptions {
    std::optional<double> rate_hz;     // fixed rate: rows are consecutive samples unless timeColumn is given
    std::string timeColumn;            // empty: a column named t, time, time_s or timestamp, if any
    std::vector<std::string> columns;  // data columns, in order; empty: every column but the time column
    SessionMetadata metadata;          // its non-empty text fields win over the side file's
    // None: the side file's, else panel scan when the columns can feed it
    // (two strain columns), else general. Panel scan given for columns with
    // no unit takes them as strains (and says so). A mode given is kept
    // even where the columns cannot feed it: the samples are stored, and the
    // review says why the mode's quantities cannot be derived.
    std::optional<Mode> mode;
    RoleAssignment roles;  // by column name (after the unit is split off), over the side file's
    UnitAssignment units;  // by column name, over the header's ("left" → "µε")
};

struct CsvImportResult {
    std::int64_t session = 0;
    std::uint64_t rows = 0;
    std::uint64_t lostSamples = 0;  // rows missing from the time grid
    double rate_hz = 0.0;
    std::vector<ChannelDescriptor> channels;
    bool usedSideFile = false;
    // What was read other than as written, for people: a Latin-1 header.
    std::vector<std::string> notes;
};

// Imports `path` into `store` as a session, complete unless the side file
// says otherwise. progress(fraction of the file read) is called now and
// then; returning false cancels. Throws io::CsvError for a file that cannot
// be imported, StorageError when the store fails or another process records
// into it, and std::runtime_error("cancelled") on cancel. The import is one
// transaction: nothing of a failed, cancelled or killed import stays.
CsvImportResult importCsv(SessionStore& store, const std::string& path, const CsvImportOptions& options,
                          const std::function<bool(double)>& progress = {});

}  // namespace tactiscope::core::storage
