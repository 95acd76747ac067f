// CSV blocks → time-base check → streaming detector.
#include "core/detector/CsvDetection.h"

#include "core/detector/HumRisk.h"
#include "core/detector/OfflineDetection.h"
#include "core/detector/PositionTrail.h"
#include "core/detector/SiteArithmetic.h"
#include "core/io/UniformTimeBase.h"
#include "core/text/NumberFormat.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

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

CheckedScan::CheckedScan(std::string path, std::vector<std::string> columns, io::UniformTimeBaseCheck::Gaps gaps)
    : m_path(std::move(path)),
      m_columns(std::move(columns))
{
    std::vector<std::vector<double>> block;
    io::UniformTimeBaseCheck timeBase(0.01, gaps);
    io::CsvColumnReader times(m_path, {m_columns.front()});
    while (const std::size_t n = times.read(StreamingDetection::kChunk, block, m_lines)) {
        try {
            timeBase.add(block.front());
        } catch (const io::TimeBaseError& e) {
            throw CsvDetectionError("'" + m_path + "' line " + std::to_string(m_lines[e.row()]) + ": " + e.what());
        }
        m_rows += n;
    }
    if (m_rows == 0) throw io::CsvError("'" + m_path + "' has a header but no data rows");
    m_interval_s = timeBase.interval_s();
    m_afterGaps = timeBase.samplesAfterGaps();
    m_missing = timeBase.samplesMissing();
    m_reader = std::make_unique<io::CsvColumnReader>(m_path, m_columns);
}

std::size_t CheckedScan::read(std::vector<std::vector<double>>& block)
{
    const std::size_t n = m_reader->read(StreamingDetection::kChunk, block, m_lines);
    if (n == 0) {
        if (m_read != m_rows) throw CsvDetectionError("'" + m_path + "' changed while it was read");
        return 0;
    }
    const SeriesInput series{0.0, {block.begin() + 1, block.end()}, block.front()};
    if (const auto bad = firstUnusableSample(series)) {
        const auto [cantilever, index] = *bad;
        throw CsvDetectionError("'" + m_path + "' line " + std::to_string(m_lines[index]) + ", column '" +
                                m_columns[cantilever + 1] + "': " + shortNumber(series.cantilevers[cantilever][index]) +
                                " is beyond what the detector can use (|value| ≤ " + shortNumber(kLargestUsableValue) +
                                ")");
    }
    // A sample with no value where each gap lies (the last first, so the
    // rows before it keep their place), halfway between its neighbours;
    // none before the file's first row.
    const auto from = std::ranges::lower_bound(m_afterGaps, std::max<std::uint64_t>(m_read, 1));
    const auto to = std::ranges::lower_bound(m_afterGaps, m_read + n);
    const std::size_t known = m_gapsRead.size();
    for (auto gap = to; gap != from;) {
        const auto row = static_cast<std::ptrdiff_t>(*--gap - m_read);
        auto& t = block.front();
        const double before_s = row > 0 ? t[static_cast<std::size_t>(row) - 1] : m_lastTime_s;
        const double after_s = t[static_cast<std::size_t>(row)];
        m_gapsRead.push_back({before_s, after_s, m_lines[static_cast<std::size_t>(row)]});
        t.insert(t.begin() + row, (before_s + after_s) / 2.0);
        for (std::size_t c = 1; c < block.size(); ++c)
            block[c].insert(block[c].begin() + row, std::numeric_limits<double>::quiet_NaN());
    }
    std::reverse(m_gapsRead.begin() + static_cast<std::ptrdiff_t>(known), m_gapsRead.end());  // found last first
    m_lastTime_s = block.front().back();
    m_read += n;
    return n;
}

CsvDetection detectCsv(const std::string& path, const std::vector<std::string>& columns, StretchSettings settings,
                       const CsvSampleSink& sink)
{
    CheckedScan scan(path, columns, io::UniformTimeBaseCheck::Gaps::Allowed);
    settings.parameters.sampleInterval_s = scan.interval_s();
    CsvDetection result;
    result.interval_s = settings.parameters.sampleInterval_s;
    StreamingDetection detection(columns.size() - 1, settings, 0.0,
                                 [&](std::uint64_t, std::span<const ProbeOutput> outputs) {
                                     if (sink) sink(outputs, result.interval_s);
                                 });
    result.lags = detection.lagCount();
    const double rate_hz = 1.0 / result.interval_s;
    const auto judged = std::min<std::uint64_t>(scan.rows(), static_cast<std::uint64_t>(kHumJudged_s * rate_hz));
    std::vector<dsp::HealthAccumulator> health;
    for (std::size_t c = 1; c < columns.size(); ++c) health.emplace_back(rate_hz, judged);
    std::uint64_t healthRead = 0;
    std::vector<std::vector<double>> block;  // time, then the cantilevers; reused
    while (scan.read(block) > 0) {
        const auto started = std::chrono::steady_clock::now();
        const std::vector<std::span<const double>> cantilevers(block.begin() + 1, block.end());
        detection.push(cantilevers, block.front());
        result.detectorSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        const std::size_t take =
            static_cast<std::size_t>(std::min<std::uint64_t>(judged - healthRead, block[0].size()));
        for (std::size_t c = 0; c < health.size() && take > 0; ++c) health[c].push(cantilevers[c].first(take));
        healthRead += take;
    }
    for (const auto& accumulator : health) result.cantileverHealth.push_back(accumulator.result());
    result.samples = static_cast<std::size_t>(detection.samplesPushed()) - scan.gaps();  // not the NaN at each gap
    result.gaps = scan.gapsRead();
    result.samplesMissing = scan.samplesMissing();
    result.events = detection.finish().events;
    return result;
}

double stampCsvPositions(const std::string& path, const std::string& timeColumn, const std::string& positionColumn,
                         double interval_s, std::vector<DefectEvent>& events)
{
    double lowest = std::numeric_limits<double>::infinity();
    double highest = -lowest;
    std::vector<std::size_t> order(events.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::ranges::sort(order, {}, [&](std::size_t i) { return sites::crossingTime(events[i]); });
    constexpr std::size_t kRows = 4096;
    // Two blocks: a crossing just before a block's first row is still held.
    PositionTrail trail(2 * kRows, interval_s);
    io::CsvColumnReader reader(path, {timeColumn, positionColumn});
    std::vector<std::vector<double>> block;
    std::vector<std::size_t> lines;
    auto next = order.begin();
    const auto stampUpTo = [&](double until_s) {
        for (; next != order.end() && sites::crossingTime(events[*next]) <= until_s; ++next)
            events[*next].position_m = trail.at(sites::crossingTime(events[*next]));
    };
    while (const std::size_t n = reader.read(kRows, block, lines)) {
        for (std::size_t r = 0; r < n; ++r) {
            trail.push(block[0][r], block[1][r]);
            lowest = std::min(lowest, block[1][r]);
            highest = std::max(highest, block[1][r]);
        }
        stampUpTo(block[0][n - 1]);
    }
    stampUpTo(std::numeric_limits<double>::infinity());  // past the last row: none
    return highest >= lowest ? highest - lowest : 0.0;
}

}  // namespace tactiscope::core::detector
