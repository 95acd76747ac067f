// CSV blocks → time-base check → streaming detector.
#include "core/detector/CsvDetection.h"

#include "core/detector/OfflineDetection.h"
#include "core/io/CsvColumns.h"
#include "core/io/UniformTimeBase.h"
#include "core/text/NumberFormat.h"

#include <chrono>
#include <cmath>
#include <cstdio>

namespace tactiscope::core::detector {
namespace {

// A number as a message shows it: six significant digits ("1e+308").
std::string shortNumber(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

// A lag in milliseconds, rounded to 1 ns so that k·Δt prints as "52", not
// "52.00000000000001".
double lag_ms(std::uint32_t samples, double interval_s)
{
    return std::round(static_cast<double>(samples) * interval_s * 1e9) / 1e6;
}

}  // namespace

void appendSampleRows(std::string& text, std::span<const ProbeOutput> outputs, double interval_s)
{
    text.clear();
    for (const ProbeOutput& p : outputs) {
        const auto& o = p.combined;
        text::appendShortest(text, p.t_s);
        text += ',';
        text += std::to_string(o.decision);
        text += ',';
        text::appendShortest(text, o.rab);
        text += ',';
        text::appendShortest(text, o.rba);
        text += ',';
        text::appendShortest(text, lag_ms(o.lagAb, interval_s));
        text += ',';
        text::appendShortest(text, lag_ms(o.lagBa, interval_s));
        text += '\n';
    }
}

CsvDetection detectCsv(const std::string& path, const std::vector<std::string>& columns, StretchSettings settings,
                       const CsvSampleSink& sink)
{
    std::vector<std::vector<double>> block;  // time, then the cantilevers; reused
    std::vector<std::size_t> lines;
    const auto timeBaseError = [&](const io::TimeBaseError& e) {
        return CsvDetectionError("'" + path + "' line " + std::to_string(lines[e.row()]) + ": " + e.what());
    };
    // First the time column alone, through the whole file: the forgetting
    // factors depend on the interval to the last bit, so it must be the
    // whole file's mean before the first sample is detected.
    io::UniformTimeBaseCheck timeBase;
    std::size_t rows = 0;
    {
        io::CsvColumnReader times(path, {columns.front()});
        while (const std::size_t n = times.read(StreamingDetection::kChunk, block, lines)) {
            try {
                timeBase.add(block.front());
            } catch (const io::TimeBaseError& e) {
                throw timeBaseError(e);
            }
            rows += n;
        }
    }
    if (rows == 0) throw io::CsvError("'" + path + "' has a header but no data rows");
    settings.parameters.sampleInterval_s = timeBase.interval_s();

    io::CsvColumnReader reader(path, columns);
    CsvDetection result;
    result.interval_s = settings.parameters.sampleInterval_s;
    StreamingDetection detection(columns.size() - 1, settings, 0.0,
                                 [&](std::uint64_t, std::span<const ProbeOutput> outputs) {
                                     if (sink) sink(outputs, result.interval_s);
                                 });
    result.lags = detection.lagCount();
    while (reader.read(StreamingDetection::kChunk, block, lines) > 0) {
        const SeriesInput series{0.0, {block.begin() + 1, block.end()}, block.front()};
        if (const auto bad = firstUnusableSample(series)) {
            const auto [cantilever, index] = *bad;
            throw CsvDetectionError(
                "'" + path + "' line " + std::to_string(lines[index]) + ", column '" + columns[cantilever + 1] +
                "': " + shortNumber(series.cantilevers[cantilever][index]) +
                " is beyond what the detector can use (|value| ≤ " + shortNumber(kLargestUsableValue) + ")");
        }
        const auto started = std::chrono::steady_clock::now();
        detection.push(series.cantilevers, block.front());
        result.detectorSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    }
    result.samples = static_cast<std::size_t>(detection.samplesPushed());
    if (result.samples != rows) throw CsvDetectionError("'" + path + "' changed while it was read");
    result.events = detection.finish().events;
    return result;
}

}  // namespace tactiscope::core::detector
