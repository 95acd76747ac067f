// The signal-quality section: health per channel, the setup in words, and
// a capacitive beam's detection limits.
#include "core/report/SignalQuality.h"

#include "core/signal/SignalColumns.h"
#include "core/signal/SignalSetup.h"

#include <algorithm>
#include <cmath>

namespace tactiscope::core::report {
namespace {

// Samples per channel read at a time.
constexpr std::uint64_t kWindow = std::uint64_t{1} << 16;

}  // namespace

bool isBeamChannel(const ChannelDescriptor& channel)
{
    return channel.role == ChannelRole::Capacitance || (!channel.role && channel.kind == ChannelKind::Capacitance);
}

std::vector<ChannelQuality> channelQuality(storage::SessionSource& store, std::int64_t session, std::uint64_t first,
                                           std::uint64_t end, std::size_t most)
{
    const auto stored = store.channels(session);
    std::vector<std::size_t> read;
    std::vector<dsp::HealthAccumulator> accumulators;
    std::vector<ChannelQuality> channels;
    for (std::size_t c = 0; c < stored.size(); ++c) {
        const auto& descriptor = stored[c].descriptor;
        if (descriptor.kind == ChannelKind::Decision) continue;  // a probe's −1/0/+1
        if (read.size() == most) break;
        // A position dwelling at an end stop is not a clipped converter.
        const bool position = descriptor.kind == ChannelKind::Position;
        read.push_back(c);
        accumulators.emplace_back(stored[c].sampleRate_hz, end > first ? end - first : 0, std::nullopt, !position);
        channels.push_back({descriptor, {}, !position});
    }
    // A capacitance channel is held whole for its creep, where it fits.
    std::vector<std::vector<double>> whole(read.size());
    for (std::size_t i = 0; i < read.size(); ++i) {
        channels[i].creepJudged = isBeamChannel(channels[i].channel) && end > first && end - first <= kMostCreepSamples;
        if (channels[i].creepJudged) whole[i].reserve(end - first);
    }
    std::vector<std::vector<double>> window;
    for (std::uint64_t from = first; from < end; from += kWindow) {
        store.readChannels(session, read, from, std::min(kWindow, end - from), window);
        for (std::size_t i = 0; i < read.size(); ++i) {
            accumulators[i].push(window[i]);
            if (channels[i].creepJudged) whole[i].insert(whole[i].end(), window[i].begin(), window[i].end());
        }
    }
    for (std::size_t i = 0; i < channels.size(); ++i) {
        channels[i].health = accumulators[i].result();
        if (channels[i].creepJudged) channels[i].creep = dsp::findStepCreep(whole[i], stored[read[i]].sampleRate_hz);
    }
    return channels;
}

std::vector<ChannelQuality> recordedSignalQuality(storage::SessionSource& store, std::int64_t session,
                                                  std::uint64_t first, std::uint64_t end, std::size_t most,
                                                  std::string& problem)
{
    auto columns = signal::withRecordedSignal(store, session, nullptr, problem);
    const auto stored = store.channels(session);
    if (!columns || stored.empty() || most == 0) return {};
    const double rate_hz = stored.front().sampleRate_hz;
    const auto computed = columns->channels();
    std::vector<dsp::HealthAccumulator> accumulators;
    std::vector<std::pair<double, double>> spans;  // each column's least and greatest value
    for (std::size_t c = 0; c < computed.size(); ++c) {
        accumulators.emplace_back(rate_hz, end > first ? end - first : 0, std::nullopt, false);
        spans.emplace_back(INFINITY, -INFINITY);
    }
    for (std::uint64_t from = first; from < end; from += kWindow) {
        const auto window = columns->read(from, std::min(kWindow, end - from));
        for (std::size_t c = 0; c < computed.size() && c < window.size(); ++c) {
            accumulators[c].push(window[c]);
            for (const double v : window[c])
                if (std::isfinite(v)) spans[c] = {std::min(spans[c].first, v), std::max(spans[c].second, v)};
        }
    }
    std::vector<ChannelQuality> channels;
    for (std::size_t c = 0; c < computed.size() && channels.size() < most; ++c) {
        // A math channel that is a constant (c0[pF]=51.44) has no health to judge.
        if (!(spans[c].first < spans[c].second)) continue;
        channels.push_back({computed[c], accumulators[c].result(), true});
    }
    return channels;
}

SignalQuality gatherSignalQuality(storage::SessionSource& store, const storage::SessionSummary& session,
                                  std::uint64_t first, std::uint64_t end, std::optional<double> perNewton_f,
                                  std::optional<double> calibrationLimit_n, std::size_t most)
{
    SignalQuality quality;
    quality.channels = channelQuality(store, session.id, first, end, most);
    // The filtered and math channels beside them: what the notch left of the hum.
    quality.computed = recordedSignalQuality(store, session.id, first, end, most, quality.computedProblem);
    const auto stored = store.channels(session.id);
    const auto judged = static_cast<std::size_t>(std::ranges::count_if(
        stored, [](const storage::StoredChannel& c) { return c.descriptor.kind != ChannelKind::Decision; }));
    quality.channelsLeftOut = judged - quality.channels.size();
    quality.setup = signal::signalSetupText(session.metadata.signalSetup);
    if (!perNewton_f || !(*perNewton_f > 0.0)) return quality;
    const auto beam =
        std::ranges::find_if(quality.channels, [](const ChannelQuality& q) { return isBeamChannel(q.channel); });
    if (beam == quality.channels.end() || !std::isfinite(beam->health.noiseFloor_per_sqrt_hz)) return quality;
    const double rate_hz = stored.empty() ? 0.0 : stored.front().sampleRate_hz;
    quality.detection = DetectionLimits{
        3.0 * beam->health.noiseFloor_per_sqrt_hz * std::sqrt(rate_hz / 2.0) / *perNewton_f, calibrationLimit_n};
    return quality;
}

}  // namespace tactiscope::core::report
