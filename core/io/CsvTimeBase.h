// A CSV file's time base, as import and the signal tools read it: which
// column holds the time (t, time, time_s or timestamp; s, ms or us), the
// file's sample rate from it, and where each row falls on the sample grid
// (a missing row is a gap; a time off the grid is refused).
#pragma once

#include "core/io/CsvReader.h"

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tactiscope::core::io {

// The first column named t, time, time_s or timestamp (any case, unit aside).
std::optional<std::size_t> findTimeColumn(const std::vector<std::string>& header);

// Seconds per unit of a time column's header unit. Throws CsvError for a
// unit other than s, ms or us.
double timeScale(const std::string& header, const std::string& path);

// The file's rate from its time column: the median step (robust to
// missing rows) tells how many sample steps the file spans, and the span
// over that many steps is the rate, exact to the times' rounding over the
// whole file. Throws CsvError.
double measureRate(const std::string& path, std::size_t timeColumn);

// Where each row goes on the sample grid.
class RowIndexer {
public:
    RowIndexer(double rate_hz, double timeScale)
        : m_rate_hz(rate_hz),
          m_scale(timeScale)
    {
    }

    // The sample index of the next row without a time column.
    std::uint64_t next() { return m_rows++; }
    // The sample index of a row at `time`. Throws CsvError for a time off
    // the grid or going back.
    std::uint64_t next(double time, const CsvReader& reader)
    {
        const double t_s = time * m_scale;
        if (m_rows == 0) m_t0_s = t_s;
        const double position = (t_s - m_t0_s) * m_rate_hz;
        const double index = std::round(position);
        if (std::abs(position - index) > 0.25 || !std::isfinite(position))
            throw CsvError("'" + reader.path() + "' line " + std::to_string(reader.lineNumber()) +
                           ": t = " + std::to_string(t_s) + " s is off the " + std::to_string(m_rate_hz) +
                           " Hz sample grid; resample the file to a fixed rate first");
        if (index < 0.0 || (m_rows > 0 && index <= static_cast<double>(m_last)))
            throw CsvError("'" + reader.path() + "' line " + std::to_string(reader.lineNumber()) +
                           ": time does not increase");
        m_last = static_cast<std::uint64_t>(index);
        ++m_rows;
        return m_last;
    }

private:
    double m_rate_hz;
    double m_scale;
    double m_t0_s = 0.0;       // time of the first row
    std::uint64_t m_last = 0;  // index of the last row
    std::uint64_t m_rows = 0;
};

}  // namespace tactiscope::core::io
