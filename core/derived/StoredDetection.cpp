// Stored session → detector, one window of samples at a time.
#include "core/derived/StoredDetection.h"

#include <vector>

namespace tactiscope::core::derived {

std::optional<detector::StretchDetection> detectStoredSession(storage::SessionSource& store, std::int64_t session,
                                                              std::span<const std::size_t> cantilevers,
                                                              const detector::StretchSettings& settings,
                                                              const DetectionProgress& progress)
{
    detector::StreamingDetection detection(cantilevers.size(), settings);
    const std::uint64_t total = store.sampleCount(session);
    std::vector<std::vector<double>> window;  // per cantilever, reused
    std::vector<std::span<const double>> series(cantilevers.size());
    for (std::uint64_t first = 0; first < total;) {
        const std::size_t n =
            store.readChannels(session, cantilevers, first, detector::StreamingDetection::kChunk, window);
        if (n == 0) break;
        for (std::size_t c = 0; c < window.size(); ++c) series[c] = window[c];
        detection.push(series);
        first += n;
        if (progress && !progress(first, total)) return std::nullopt;
    }
    return detection.finish();
}

}  // namespace tactiscope::core::derived
