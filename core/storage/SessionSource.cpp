// SessionSource: what every store does the same way.
#include "core/storage/SessionSource.h"

namespace tactiscope::core::storage {

std::string textSearchPattern(const std::string& text)
{
    std::string pattern = "%";
    for (const char c : text) {
        if (c == '%' || c == '_' || c == '\\') pattern += '\\';
        pattern += c;
    }
    return pattern + "%";
}

std::optional<std::string> oneDeviceRefusal(SessionSource& store, std::int64_t session, const std::string& what)
{
    const auto parts = store.parts(session);
    if (parts.empty()) return std::nullopt;
    std::string named;
    for (const auto& part : parts)
        named += (named.empty() ? "" : ", ") + part.deviceName + ": session " + std::to_string(part.id);
    return "session " + std::to_string(session) + " holds " + std::to_string(parts.size()) + " devices (" + named +
           "); name one device's session for " + what;
}

std::optional<std::string> partDeletionRefusal(const SessionSummary& session)
{
    if (session.metadata.partOf == 0) return std::nullopt;
    return "session " + std::to_string(session.id) + " is the part of device " + session.metadata.deviceName +
           " in session " + std::to_string(session.metadata.partOf) + "; delete session " +
           std::to_string(session.metadata.partOf) + ", which goes with all its parts";
}

std::vector<double> SessionSource::readChannel(std::int64_t session, std::size_t channel, std::uint64_t firstIndex,
                                               std::uint64_t count)
{
    std::vector<std::vector<double>> out(1);
    readChannels(session, std::span(&channel, 1), firstIndex, count, out);
    return std::move(out.front());
}

std::optional<StoredCalibration> SessionSource::newestCalibration(std::string_view kind, const std::string& sensor)
{
    auto all = calibrations(sensor);
    for (auto it = all.rbegin(); it != all.rend(); ++it)
        if (it->record.kind == kind) return std::move(*it);
    return std::nullopt;
}

// A session of several devices lasts as long as its longest part: its
// rate and count stand for the session's in a list.
void SessionSource::fillFromLongestPart(SessionSummary& summary)
{
    if (summary.devices == 0) return;
    for (const SessionPart& part : parts(summary.id)) {
        const auto own = session(part.id);
        if (!own || !(own->sampleRate_hz > 0.0)) continue;
        if (summary.sampleRate_hz <= 0.0 || own->duration_s() > summary.duration_s()) {
            summary.sampleRate_hz = own->sampleRate_hz;
            summary.sampleCount = own->sampleCount;
        }
    }
}

}  // namespace tactiscope::core::storage
