// Stored session → detector, one window of samples at a time.
#include "core/derived/StoredDetection.h"

#include <cmath>
#include <vector>

namespace tactiscope::core::derived {

std::optional<detector::StretchDetection> detectStoredSession(storage::SessionSource& store, std::int64_t session,
                                                              std::span<const std::size_t> cantilevers,
                                                              const detector::StretchSettings& settings,
                                                              const DetectionProgress& progress,
                                                              std::optional<std::size_t> probeOut)
{
    // The probe's decisions come with the cantilevers, in the same window.
    std::vector<std::size_t> read(cantilevers.begin(), cantilevers.end());
    if (probeOut) read.push_back(*probeOut);
    std::vector<std::vector<double>> window;  // per channel read, reused
    std::uint64_t first = 0;

    // Each run of outputs against the probe's word, after the warm-up of
    // each stretch (a run that does not follow the last began one).
    std::optional<detector::ProbeAgreement> agreement;
    if (probeOut) agreement = detector::ProbeAgreement{};
    const auto warmUp = static_cast<std::uint64_t>(
        std::ceil(detector::ProbeDecisionCheck::kWarmUp_s / settings.parameters.sampleInterval_s));
    std::uint64_t stretchStart = 0, expected = 0;
    detector::StreamingDetection::SampleSink compare;
    if (probeOut)
        compare = [&](std::uint64_t firstIndex, std::span<const detector::ProbeOutput> outputs) {
            if (firstIndex != expected) stretchStart = firstIndex;
            expected = firstIndex + outputs.size();
            for (std::size_t i = 0; i < outputs.size(); ++i) {
                const std::uint64_t index = firstIndex + i;
                if (index - stretchStart < warmUp) continue;
                ++agreement->compared;
                agreement->agreeing +=
                    detector::probeDecisionOf(window.back()[index - first]) == outputs[i].combined.decision;
            }
        };

    detector::StreamingDetection detection(cantilevers.size(), settings, 0.0, compare);
    const std::uint64_t total = store.sampleCount(session);
    std::vector<std::span<const double>> series(cantilevers.size());
    while (first < total) {
        const std::size_t n = store.readChannels(session, read, first, detector::StreamingDetection::kChunk, window);
        if (n == 0) break;
        for (std::size_t c = 0; c < cantilevers.size(); ++c) series[c] = window[c];
        detection.push(series);
        first += n;
        if (progress && !progress(first, total)) return std::nullopt;
    }
    auto result = detection.finish();
    result.probeAgreement = agreement;
    return result;
}

}  // namespace tactiscope::core::derived
