// A CSV file's time column, rate and sample grid.
#include "core/io/CsvTimeBase.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace tactiscope::core::io {
namespace {

std::string lower(std::string text)
{
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

// The simplest rate (fewest significant digits) that puts the last of
// `steps` sample steps over `span_s` within 1 % of a sample of where the
// measured rate puts it: 500 Hz, not 499.999999999, for an hour written
// with rounded times, while a true 499.9 Hz stays 499.9.
double simplestRate(double steps, double span_s)
{
    const double measured = steps / span_s;
    for (int digits = 1; digits < 17; ++digits) {
        char text[32];
        std::snprintf(text, sizeof text, "%.*g", digits, measured);
        const double rate = std::strtod(text, nullptr);
        if (std::abs(rate - measured) * span_s <= 0.01) return rate;
    }
    return measured;
}

}  // namespace

std::optional<std::size_t> findTimeColumn(const std::vector<std::string>& header)
{
    for (std::size_t c = 0; c < header.size(); ++c) {
        const std::string name = lower(splitColumnHeader(header[c]).name);
        if (name == "t" || name == "time" || name == "time_s" || name == "timestamp") return c;
    }
    return std::nullopt;
}

double timeScale(const std::string& header, const std::string& path)
{
    const std::string unit = io::splitColumnHeader(header).unit;
    if (unit.empty() || unit == "s") return 1.0;
    if (unit == "ms") return 1e-3;
    if (unit == "us" || unit == "µs") return 1e-6;
    throw CsvError("'" + path + "': the time column '" + header + "' is in '" + unit + "'; use s, ms or us");
}

double measureRate(const std::string& path, std::size_t timeColumn)
{
    CsvReader reader(path);
    const double scale = timeScale(reader.header()[timeColumn], path);
    std::vector<double> steps;
    std::vector<std::string_view> fields;
    std::optional<double> first, previous;
    while (reader.next(fields)) {
        const double t = reader.number(fields[timeColumn], timeColumn) * scale;
        if (previous) steps.push_back(t - *previous);
        if (!first) first = t;
        previous = t;
    }
    if (steps.empty()) throw CsvError("'" + path + "' needs at least two rows to tell its sample rate");
    auto middle = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
    std::nth_element(steps.begin(), middle, steps.end());
    const double span_s = *previous - *first;
    if (!(*middle > 0.0) || !(span_s > 0.0)) throw CsvError("'" + path + "': the time column does not increase");
    return simplestRate(std::round(span_s / *middle), span_s);
}

}  // namespace tactiscope::core::io
