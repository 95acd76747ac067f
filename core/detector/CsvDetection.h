// The detector over a CSV recording read as a stream (`tactiscope-cli
// detect`, and its benchmark): blocks of rows from the file go straight
// into StreamingDetection, each block's times checked for a uniform base,
// so a file of any size runs in the memory of one block.
#pragma once

#include "core/detector/StreamingDetection.h"
#include "core/dsp/SignalHealth.h"
#include "core/io/CsvColumns.h"
#include "core/io/UniformTimeBase.h"

#include <memory>
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

// Where a file's times skip whole intervals: the times of the rows either
// side, and the file's line of the row after it.
struct TimeGap {
    double before_s = 0.0;
    double after_s = 0.0;
    std::size_t lineAfter = 0;
};

struct CsvDetection {
    std::size_t samples = 0;    // rows of the file, each a sample
    std::vector<TimeGap> gaps;  // where its times skip whole intervals: the detector restarted after each
    std::uint64_t samplesMissing = 0;
    std::size_t lags = 0;
    double interval_s = 0.0;          // the whole file's mean sampling interval
    double detectorSeconds = 0.0;     // time spent in the detector alone
    std::vector<DefectEvent> events;  // lags and speeds by interval_s
    // Each cantilever's health over the file's first kHumJudged_s, as read
    // (before a notch): the hum it may carry (HumRisk.h).
    std::vector<dsp::ChannelHealth> cantileverHealth;
};

// Per-sample outputs, with the interval the lags were resolved with.
using CsvSampleSink = std::function<void(std::span<const ProbeOutput> outputs, double interval_s)>;

// The per-sample rows of `detect --output`: this header, then one row per
// sample with its time, decision, both best R and their lags in ms.
inline constexpr const char* kSampleRowsHeader = "t,out,rab,rba,lag_ab_ms,lag_ba_ms\n";
// Replaces `text` with the rows of `outputs` (lags in samples × interval_s).
void appendSampleRows(std::string& text, std::span<const ProbeOutput> outputs, double interval_s);

// A scan read as `detect` reads it, with every check and message of its:
// the time column first, through the whole file (the forgetting factors
// depend on the interval to the last bit, so it is the whole file's mean
// before the first sample is detected), then blocks of rows, each value
// checked for one the detector can use. The emulated probe's files are
// written and read through it too (ProbeScanFiles), so the probe refuses
// what detect refuses, in the same words. Throws io::CsvError and
// CsvDetectionError.
class CheckedScan {
public:
    // `columns`: the time column, then the cantilevers in probe order (each
    // also found under an SI unit, "t [s]"). With gaps allowed, a time step
    // of a whole number of intervals is a gap (an export of a session that
    // lost samples leaves their rows out): read() puts one sample with no
    // value (NaN) where it lies, which the detector restarts after, never
    // bridging it; else it is refused as an irregular time base.
    CheckedScan(std::string path, std::vector<std::string> columns,
                io::UniformTimeBaseCheck::Gaps gaps = io::UniformTimeBaseCheck::Gaps::Refused);
    double interval_s() const { return m_interval_s; }
    std::size_t rows() const { return m_rows; }
    std::size_t gaps() const { return m_afterGaps.size(); }
    // The gaps read() has passed, in the file's order.
    const std::vector<TimeGap>& gapsRead() const { return m_gapsRead; }
    std::uint64_t samplesMissing() const { return m_missing; }
    // The next rows into `block` (the times, then the cantilevers), with a
    // NaN sample at each gap among them; 0 at the end, where a file that
    // changed while it was read is refused.
    std::size_t read(std::vector<std::vector<double>>& block);

private:
    std::string m_path;
    std::vector<std::string> m_columns;
    double m_interval_s = 0.0;
    std::size_t m_rows = 0;
    std::size_t m_read = 0;
    std::vector<std::size_t> m_lines;
    std::vector<std::uint64_t> m_afterGaps;  // the rows that follow a gap
    std::uint64_t m_missing = 0;
    double m_lastTime_s = 0.0;  // the last row read's, for a gap at a block's start
    std::vector<TimeGap> m_gapsRead;
    std::unique_ptr<io::CsvColumnReader> m_reader;
};

// `columns`: the time column, then the cantilevers in probe order (each
// also found under an SI unit, "t [s]"). settings.parameters'
// sampleInterval_s is ignored: the file's times give it, their mean over
// the whole file (read first, the time column alone), gaps left out; the
// detector restarts after each gap (CheckedScan). Throws io::CsvError,
// CsvDetectionError, std::invalid_argument (parameters).
CsvDetection detectCsv(const std::string& path, const std::vector<std::string>& columns, StretchSettings settings,
                       const CsvSampleSink& sink = {});

// Each event's position_m at its crossing from the rig's position column
// (`detect --position`, in metres along the stroke), read in a second pass
// with the time column a block at a time, so the file's size does not
// matter. Returns how far the column spans (m): a span beyond any stroke
// is a column in another unit. Throws io::CsvError.
double stampCsvPositions(const std::string& path, const std::string& timeColumn, const std::string& positionColumn,
                         double interval_s, std::vector<DefectEvent>& events);

}  // namespace tactiscope::core::detector
