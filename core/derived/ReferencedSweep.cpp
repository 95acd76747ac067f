// ReferencedSweep: roles across a session's devices, and the beam's samples
// paired with the reference force on the session's clock.
#include "core/derived/ReferencedSweep.h"

#include "core/UnitScale.h"
#include "core/calibration/ReferencePairing.h"
#include "core/modes/ModeDefinition.h"
#include "core/timing/ClockMappingJson.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace tactiscope::core::derived {
namespace {

// Every channel of the session, device by device.
std::vector<SessionChannel> allChannels(storage::SessionSource& store, std::int64_t session)
{
    std::vector<std::pair<std::int64_t, const storage::SessionPart*>> sources;
    const auto parts = store.parts(session);
    if (parts.empty()) sources.emplace_back(session, nullptr);
    for (const auto& part : parts) sources.emplace_back(part.id, &part);
    std::vector<SessionChannel> channels;
    for (const auto& [source, part] : sources) {
        const auto stored = store.channels(source);
        for (std::size_t c = 0; c < stored.size(); ++c)
            channels.push_back({source, part ? part->deviceName : std::string{}, c, stored[c],
                                part ? timing::clockMappingFromJson(part->clockJson) : std::nullopt});
    }
    return channels;
}

struct Series {
    std::vector<double> t_s, value;
};

// A channel's samples with their times on the session's clock (NaN in gaps).
Series readSeries(storage::SessionSource& store, const SessionChannel& channel, double scale)
{
    const std::uint64_t count = store.sampleCount(channel.source);
    const std::vector<double> values = store.readChannel(channel.source, channel.channel, 0, count);
    Series series;
    for (std::size_t i = 0; i < values.size(); ++i) {
        const double own_s = static_cast<double>(i) / channel.stored.sampleRate_hz;
        series.t_s.push_back(channel.clock ? channel.clock->host_s(own_s) : own_s);
        series.value.push_back(values[i] * scale);
    }
    return series;
}

}  // namespace

std::string SessionChannel::label() const
{
    return device.empty() ? stored.descriptor.name : device + "/" + stored.descriptor.name;
}

std::optional<SessionChannel> channelPlaying(storage::SessionSource& store, std::int64_t session, ChannelRole role)
{
    const auto channels = allChannels(store, session);
    for (const auto& channel : channels)
        if (channel.stored.descriptor.role == role) return channel;
    for (const auto& channel : channels)
        if (!channel.stored.descriptor.role && canPlay(channel.stored.descriptor, role)) return channel;
    return std::nullopt;
}

std::optional<SessionChannel> channelNamed(storage::SessionSource& store, std::int64_t session,
                                           const std::string& label)
{
    for (auto& channel : allChannels(store, session))
        if (channel.label() == label) return std::move(channel);
    return std::nullopt;
}

ReferencedSweep referencedSweep(storage::SessionSource& store, const SessionChannel& capacitance,
                                const SessionChannel& reference)
{
    const auto farads = faradsPer(capacitance.stored.descriptor.unit);
    if (!farads)
        throw std::invalid_argument("the capacitance " + capacitance.label() + " is in '" +
                                    capacitance.stored.descriptor.unit + "', not F, nF, pF or fF");
    const auto newtons = newtonsPer(reference.stored.descriptor.unit);
    if (!newtons)
        throw std::invalid_argument("the reference force " + reference.label() + " is in '" +
                                    reference.stored.descriptor.unit + "', not N, mN or µN");
    const Series beam = readSeries(store, capacitance, *farads);
    const Series force = readSeries(store, reference, *newtons);
    calibration::PairedSweep paired =
        calibration::pairWithReference(beam.t_s, beam.value, force.t_s, force.value, reference.stored.sampleRate_hz);
    ReferencedSweep result;
    result.recording = std::move(paired.recording);
    result.outsideReference = paired.outsideReference;
    result.steepest_n_per_s = paired.steepest_n_per_s;

    if (capacitance.source == reference.source)
        result.clockUncertainty_s = 0.0;
    else if (capacitance.clock && reference.clock)
        result.clockUncertainty_s = timing::relativeUncertainty_s(
            *capacitance.clock, *reference.clock, result.recording.t_s.front(), result.recording.t_s.back());
    return result;
}

}  // namespace tactiscope::core::derived
