// Exporting a stored session for other tools:
//  - CSV: a header `t [s]` then each channel's csvHeader() (its name and
//    unit, e.g. `force [N]`, `a [strain]`), one row per stored sample,
//    t in seconds from the session start (index / sample rate); samples in
//    gaps have no row. Values are written as the shortest text that reads
//    back to the same binary32, so a re-import is exact to the bit.
//  - metadata JSON (the CSV's side file, and part of the JSON export): the
//    session's fields, its channels (each with its CSV column, unit and
//    kind) and its gaps.
//  - JSON: the metadata plus "t" and one array per channel.
// Samples are read in windows, so memory stays small for hour-long sessions.
// A CSV export may cover part of a session (a range chosen in review); its
// metadata then says which samples it holds ("exported_range").
#pragma once

#include "core/storage/SessionStore.h"

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <ostream>
#include <string>

namespace tactiscope::core::storage {

// Samples [first, first + count) of each channel, clipped to the session.
struct ExportRange {
    std::uint64_t first = 0;
    std::uint64_t count = std::numeric_limits<std::uint64_t>::max();
};

// Columns computed from a session's stored samples (a mode's physical
// quantities, core/derived), written after the stored channels of a CSV
// export and named in its metadata ("computed_columns"), so an import of
// the export leaves them out.
class ComputedColumns {
public:
    virtual ~ComputedColumns() = default;
    virtual std::vector<ChannelDescriptor> channels() const = 0;
    // What they were computed with, in words (profile, calibrations).
    virtual std::string basis() const = 0;
    // Samples [first, first + count) of each column, clipped to the session.
    virtual std::vector<std::vector<double>> read(std::uint64_t first, std::uint64_t count) = 0;
};

// A channel's CSV column: "name [unit]"; a strain, dimensionless, says
// "[strain]" (an import reads that back as a strain channel); any other
// dimensionless channel is its name alone.
std::string csvHeader(const ChannelDescriptor& channel);

// For a session of several devices, each part's own computed columns (its
// recorded filters and math channels, on its own samples), or none: written
// after the part's stored channels as DEVICE/NAME, and in the metadata's
// "computed_columns" likewise. A session's `computed` columns are one
// device's and go with a session of one.
using PartColumns = std::function<std::unique_ptr<ComputedColumns>(std::int64_t part)>;

void writeSessionCsv(SessionSource& store, std::int64_t session, std::ostream& out, const ExportRange& range = {},
                     ComputedColumns* computed = nullptr, const PartColumns& partColumns = {});
void writeSessionMetadataJson(SessionSource& store, std::int64_t session, std::ostream& out,
                              const ExportRange& range = {}, ComputedColumns* computed = nullptr,
                              const PartColumns& partColumns = {});
void writeSessionJson(SessionSource& store, std::int64_t session, std::ostream& out);

// The side file a CSV export's metadata goes to (and an import reads it
// from): X.csv → X.meta.json.
std::string metadataSidePath(const std::string& csvPath);

enum class ExportFormat { Csv, Json };

// Writes a session to `path`: CSV with its metadata side file, or JSON.
// Each file goes through a temporary one renamed into place, so a failed
// export never leaves half a file under the requested name. Throws
// StorageError ("cannot write P", "writing P failed (disk full?)").
// The range and computed columns (a session's or its parts') apply to CSV only; JSON is always the
// whole session as stored.
void exportSession(SessionSource& store, std::int64_t session, ExportFormat format, const std::string& path,
                   const ExportRange& range = {}, ComputedColumns* computed = nullptr,
                   const PartColumns& partColumns = {});

}  // namespace tactiscope::core::storage
