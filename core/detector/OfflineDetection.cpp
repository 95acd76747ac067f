// Whole-series detection through the streaming detector.
#include "core/detector/OfflineDetection.h"

#include "core/detector/EventSegmenter.h"

#include <cmath>
#include <stdexcept>

namespace tactiscope::core::detector {
std::optional<std::pair<std::size_t, std::size_t>> firstUnusableSample(const SeriesInput& input)
{
    for (std::size_t c = 0; c < input.cantilevers.size(); ++c)
        for (std::size_t i = 0; i < input.cantilevers[c].size(); ++i)
            if (!(std::abs(input.cantilevers[c][i]) <= kLargestUsableValue)) return std::pair(c, i);
    return std::nullopt;
}

std::vector<ProbeOutput> detectSeries(const SeriesInput& input, const DetectorParameters& parameters, unsigned threads)
{
    if (input.cantilevers.size() < 2) throw std::invalid_argument("a probe needs at least two cantilevers");
    const std::size_t n = input.cantilevers.front().size();
    std::vector<ProbeOutput> outputs;
    outputs.reserve(n);
    StreamingDetection detection(input.cantilevers.size(), {parameters, 0.0, std::nullopt, threads}, input.t0_s,
                                 [&](std::uint64_t, std::span<const ProbeOutput> run) {
                                     outputs.insert(outputs.end(), run.begin(), run.end());
                                 });
    detection.push(input.cantilevers, input.times);
    if (outputs.size() != n) throw std::invalid_argument("a cantilever sample has no value (NaN)");
    return outputs;
}

std::vector<DefectEvent> segmentEvents(std::span<const ProbeOutput> outputs, double sampleInterval_s, double hold_s,
                                       std::optional<double> spacing_m)
{
    EventSegmenter segmenter(hold_s, spacing_m);
    std::vector<DefectEvent> events;
    for (const ProbeOutput& o : outputs) segmenter.push(o.t_s, o.combined, sampleInterval_s, events);
    segmenter.finish(events);
    return events;
}

StretchDetection detectStretches(std::span<const std::vector<double>> cantilevers, const StretchSettings& settings)
{
    if (cantilevers.empty()) return {};
    StreamingDetection detection(cantilevers.size(), settings);
    std::vector<std::span<const double>> series(cantilevers.begin(), cantilevers.end());
    detection.push(series);
    return detection.finish();
}

}  // namespace tactiscope::core::detector
