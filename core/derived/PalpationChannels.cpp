// PalpationChannels: the session's probe and zeros, then per-sample forces
// on exact samples, or the pyramid mapped through the forces.
#include "core/derived/PalpationChannels.h"

#include "core/calibration/CalibrationRecord.h"
#include "core/derived/ExactOverview.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace tactiscope::core::derived {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

PalpationChannels::PalpationChannels(storage::SessionSource& store, std::int64_t session)
    : m_store(store),
      m_session(session)
{
    const auto summary = store.session(session);
    if (!summary) throw storage::StorageError("there is no session " + std::to_string(session));
    if (summary->metadata.mode != Mode::Palpation)
        throw std::invalid_argument("session " + std::to_string(session) + " is not a palpation session");
    if (summary->metadata.profileJson.empty())
        throw std::invalid_argument("session " + std::to_string(session) +
                                    " carries no sensor profile, so its forces cannot be computed");
    sensors::SensorProfile profile;
    try {
        profile = sensors::parseSensorProfile(summary->metadata.profileJson, "the session's profile");
    } catch (const sensors::ProfileError& e) {
        throw std::invalid_argument(e.what());
    }
    const auto* probe = std::get_if<sensors::CompliancePairProfile>(&profile);
    if (!probe) throw std::invalid_argument("the session's profile is not a compliance pair");
    std::vector<ChannelDescriptor> raw;
    for (const auto& channel : store.channels(session)) raw.push_back(channel.descriptor);
    const auto records = calibration::recordsFromJsonArray(summary->metadata.calibrationsJson);
    const auto settings = compliance::palpationSettings(*probe, summary->sampleRate_hz, raw, records);
    m_forces = std::make_unique<compliance::PalpationForces>(raw, settings);
    m_sampleCount = summary->sampleCount;
    m_basis = compliance::basisText(*probe, settings);

    const auto zeros = store.zeros(session);
    for (std::size_t z = 0; z < zeros.size(); ++z) {
        const auto zero = compliance::zeroFromJson(zeros[z].valuesJson);
        if (!zero)
            throw storage::StorageError("a zero of session " + std::to_string(session) +
                                        " cannot be read; the store is damaged");
        const std::uint64_t end = z + 1 < zeros.size() ? zeros[z + 1].firstIndex : m_sampleCount;
        m_spans.push_back({zeros[z].firstIndex, end, zero->high, zero->low});
    }
}

std::vector<ChannelDescriptor> PalpationChannels::channels() const
{
    return {{"force_high", "N", ChannelKind::Force},
            {"force_low", "N", ChannelKind::Force},
            {"Q", "", ChannelKind::Other},
            {"stiffness", "N/m", ChannelKind::Other}};
}

const compliance::PalpationForces* PalpationChannels::forcesAt(std::uint64_t index)
{
    if (m_current && index >= m_current->first && index < m_current->end) return m_forces.get();
    const auto span = std::ranges::find_if(m_spans, [&](const Span& s) { return index >= s.first && index < s.end; });
    if (span == m_spans.end()) return nullptr;
    m_current = &*span;
    m_forces->setZero({span->rawHigh, span->rawLow, std::nullopt});
    return m_forces.get();
}

std::vector<std::vector<double>> PalpationChannels::read(std::uint64_t first, std::uint64_t count)
{
    const std::uint64_t end = std::min(m_sampleCount, first + std::min(count, m_sampleCount));
    const std::uint64_t n = end > first ? end - first : 0;
    const auto high = m_store.readChannel(m_session, m_forces->highChannel(), first, n);
    const auto low = m_store.readChannel(m_session, m_forces->lowChannel(), first, n);
    std::vector<std::vector<double>> out(4, std::vector<double>(high.size(), kNaN));
    for (std::size_t s = 0; s < high.size(); ++s) {
        const auto* forces = forcesAt(first + s);
        if (!forces) continue;
        const double fHigh = forces->forceHigh(high[s]), fLow = forces->forceLow(low[s]);
        out[0][s] = fHigh;
        out[1][s] = fLow;
        out[2][s] = forces->q(fHigh, fLow);
        out[3][s] = forces->stiffness(out[2][s]);
    }
    return out;
}

std::vector<storage::OverviewPoint> PalpationChannels::overview(std::size_t channel, std::uint64_t first,
                                                                std::uint64_t count, std::size_t points)
{
    if (channel >= 4) throw std::out_of_range("no derived channel " + std::to_string(channel));
    const std::uint64_t end = std::min(m_sampleCount, first + std::min(count, m_sampleCount));
    if (end <= first || points == 0) return {};
    std::vector<storage::OverviewPoint> result;
    // Exact samples: Q and k_o always (within the limit), forces when zoomed in.
    const auto fromExact = [&](std::uint64_t from, std::uint64_t to, std::size_t stretches) {
        appendExactOverview(read(from, to - from)[channel], from, stretches, result);
    };
    if (channel >= 2) {
        if (end - first <= kExactLimit) fromExact(first, end, points);
        return result;
    }
    if (end - first <= 2 * static_cast<std::uint64_t>(points)) {
        fromExact(first, end, points);
        return result;
    }
    // Forces: the raw pyramid through the force of the zero of each stretch
    // (increasing, so min ↦ min and max ↦ max); a stretch across a zero
    // change is read exactly.
    const std::size_t raw = channel == 0 ? m_forces->highChannel() : m_forces->lowChannel();
    for (const auto& stretch : m_store.overview(m_session, raw, first, end - first, points)) {
        const std::uint64_t stretchEnd = stretch.firstIndex + stretch.count;
        const auto* forces = forcesAt(stretch.firstIndex);
        const bool oneZero = forces && stretchEnd <= m_current->end;
        if (!oneZero) {
            fromExact(stretch.firstIndex, stretchEnd, 1);
            continue;
        }
        const auto force = [&](double value) {
            return channel == 0 ? forces->forceHigh(value) : forces->forceLow(value);
        };
        result.push_back({stretch.firstIndex, stretch.count, force(stretch.min), force(stretch.max)});
    }
    return result;
}

}  // namespace tactiscope::core::derived
