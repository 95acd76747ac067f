// A panel scan's cantilevers' hum, against the notch its detector read through.
#include "core/report/DetectorHum.h"

#include "core/detector/HumRisk.h"
#include "core/modes/ModeDefinition.h"
#include "core/signal/SignalSetup.h"

#include <algorithm>
#include <stdexcept>

namespace tactiscope::core::report {

std::optional<DetectorHum> detectorHumNote(const std::vector<ChannelQuality>& channels,
                                           const std::vector<std::string>& cantilevers, double sampleRate_hz,
                                           const NotchOf& notchOf)
{
    std::optional<detector::HumRisk> worst;
    std::optional<double> worstNotch;
    const ChannelQuality* worstChannel = nullptr;
    for (const ChannelQuality& q : channels) {
        if (std::ranges::find(cantilevers, q.channel.name) == cantilevers.end()) continue;
        const std::optional<double> notch = notchOf(q.channel.name);
        const auto risk = detector::detectorHumRisk({q.channel.name}, {q.health}, sampleRate_hz, notch);
        if (risk && (!worst || risk->amplitude / risk->noise > worst->amplitude / worst->noise)) {
            worst = risk;
            worstNotch = notch;
            worstChannel = &q;
        }
    }
    if (!worst) return std::nullopt;
    const bool strain = worstChannel->channel.kind == ChannelKind::Strain && worstChannel->channel.unit.empty();
    return DetectorHum{detector::humRiskText(*worst, worstNotch, strain ? 1e6 : 1.0,
                                             strain ? std::string("µε") : worstChannel->channel.unit),
                       worst->mains_hz};
}

std::optional<DetectorHum> sessionDetectorHum(const std::vector<ChannelQuality>& channels,
                                              const storage::SessionSummary& session)
{
    if (!definitionOf(session.metadata.mode).detectsDefects) return std::nullopt;
    signal::SignalSetup setup;
    try {
        setup = signal::signalSetupFromJson(session.metadata.signalSetup);
    } catch (const std::invalid_argument&) {
        // Unreadable: the detector is taken to have read them as stored.
    }
    const auto isCantilever = [](const ChannelQuality& q) {
        return q.channel.role == ChannelRole::CantileverA || q.channel.role == ChannelRole::CantileverB;
    };
    const bool byRole = std::ranges::any_of(channels, isCantilever);
    std::vector<std::string> cantilevers;
    for (const ChannelQuality& q : channels)
        if (byRole ? isCantilever(q) : q.channel.kind == ChannelKind::Strain) cantilevers.push_back(q.channel.name);
    return detectorHumNote(channels, cantilevers, session.sampleRate_hz,
                           [&setup](const std::string& channel) -> std::optional<double> {
                               const auto* filter = setup.analysisFiltered ? setup.filterOf(channel) : nullptr;
                               return filter ? filter->notch_hz : std::nullopt;
                           });
}

}  // namespace tactiscope::core::report
