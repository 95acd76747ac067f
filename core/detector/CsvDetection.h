// The detector over a CSV recording read as a stream (`tactiscope-cli
// detect`, and its benchmark): blocks of rows from the file go straight
// into StreamingDetection, each block's times checked for a uniform base,
// so a file of any size runs in the memory of one block.
#pragma once

#include "core/detector/StreamingDetection.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace tactiscope::core::detector {

// What is wrong with the file's data, naming its line (and column): one
// line for the user. (Unreadable files and cells throw io::CsvError.)
class CsvDetectionError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct CsvDetection {
    std::size_t samples = 0;
    std::size_t lags = 0;
    double interval_s = 0.0;          // the whole file's mean sampling interval
    double detectorSeconds = 0.0;     // time spent in the detector alone
    std::vector<DefectEvent> events;  // lags and speeds by interval_s
};

// Per-sample outputs, with the interval the lags were resolved with.
using CsvSampleSink = std::function<void(std::span<const ProbeOutput> outputs, double interval_s)>;

// The per-sample rows of `detect --output`: this header, then one row per
// sample with its time, decision, both best R and their lags in ms.
inline constexpr const char* kSampleRowsHeader = "t,out,rab,rba,lag_ab_ms,lag_ba_ms\n";
// Replaces `text` with the rows of `outputs` (lags in samples × interval_s).
void appendSampleRows(std::string& text, std::span<const ProbeOutput> outputs, double interval_s);

// `columns`: the time column, then the cantilevers in probe order (each
// also found under an SI unit, "t [s]"). settings.parameters'
// sampleInterval_s is ignored: the file's times give it, their mean over
// the whole file (read first, the time column alone). Throws io::CsvError,
// CsvDetectionError, std::invalid_argument (parameters).
CsvDetection detectCsv(const std::string& path, const std::vector<std::string>& columns, StretchSettings settings,
                       const CsvSampleSink& sink = {});

}  // namespace tactiscope::core::detector
