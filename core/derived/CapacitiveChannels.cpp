// CapacitiveChannels: the session's readout settings and baselines, then
// the readout's formulas on exact samples or on the pyramid's extremes.
#include "core/derived/CapacitiveChannels.h"

#include "core/ModeCapability.h"
#include "core/calibration/CalibrationRecord.h"
#include "core/capacitive/LiveCapacitive.h"
#include "core/derived/ExactOverview.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace tactiscope::core::derived {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

CapacitiveChannels::CapacitiveChannels(storage::SessionSource& store, std::int64_t session,
                                       const std::optional<calibration::CalibrationRecord>& calibration)
    : m_store(store),
      m_session(session)
{
    const auto summary = store.session(session);
    if (!summary) throw storage::StorageError("there is no session " + std::to_string(session));
    if (summary->metadata.mode != Mode::Capacitive)
        throw std::invalid_argument("session " + std::to_string(session) + " is not a capacitive session");
    if (summary->metadata.profileJson.empty())
        throw std::invalid_argument("session " + std::to_string(session) +
                                    " carries no sensor profile, so its force and deflection cannot be computed");
    sensors::SensorProfile profile;
    try {
        profile = sensors::parseSensorProfile(summary->metadata.profileJson, "the session's profile");
    } catch (const sensors::ProfileError& e) {
        throw std::invalid_argument(e.what());
    }
    const auto* beam = std::get_if<sensors::CapacitiveBeamProfile>(&profile);
    if (!beam) throw std::invalid_argument("the session's profile is not a capacitive beam");
    std::vector<ChannelDescriptor> raw;
    for (const auto& channel : store.channels(session)) raw.push_back(channel.descriptor);
    const auto picked = modeChannels(Mode::Capacitive, raw);
    if (!picked) throw std::invalid_argument(*modeRefusal(Mode::Capacitive, raw));
    m_channel = picked->front();
    m_input = capacitive::capacitanceInput(raw[m_channel], beam->channels);
    const auto records =
        calibration ? std::vector{*calibration} : calibration::recordsFromJsonArray(summary->metadata.calibrationsJson);
    std::optional<std::size_t> used;
    std::string problem;
    m_sensitivity = capacitive::readoutSettings(*beam, records, &used, &problem).sensitivity;
    if (calibration && !used)
        throw std::invalid_argument(problem.empty() ? "the calibration of " + calibration->timestampUtc +
                                                          " is not one of '" + beam->name + "'"
                                                    : problem);
    m_sampleCount = summary->sampleCount;
    std::ostringstream basis;
    basis << "profile " << beam->name << "; ";
    if (used) m_calibration = records[*used];
    if (used)
        basis << "calibration of " << records[*used].timestampUtc;
    else
        basis << "the beam model (no calibration recorded with the session)";
    basis << ": " << m_sensitivity.perNewton_f * 1e9 << " pF/mN, " << m_sensitivity.perMetre_f * 1e9 << " pF/mm";
    m_basis = basis.str();

    const auto zeros = store.zeros(session);
    for (std::size_t z = 0; z < zeros.size(); ++z) {
        const auto c0 = capacitive::baselineFromJson(zeros[z].valuesJson);
        if (!c0)
            throw storage::StorageError("a baseline of session " + std::to_string(session) +
                                        " cannot be read; the store is damaged");
        const std::uint64_t end = z + 1 < zeros.size() ? zeros[z + 1].firstIndex : m_sampleCount;
        m_spans.push_back({zeros[z].firstIndex, end, *c0});
    }
    // A session recorded before baselines were stored reads on its calibration's C0.
    if (m_spans.empty()) m_spans.push_back({0, m_sampleCount, m_sensitivity.c0_f});
}

std::vector<ChannelDescriptor> CapacitiveChannels::channels() const
{
    return {{"delta_c", "F", ChannelKind::Capacitance},
            {"relative_change", "", ChannelKind::Other},
            {"force", "N", ChannelKind::Force},
            {"deflection", "m", ChannelKind::Position}};
}

std::vector<std::pair<std::uint64_t, double>> CapacitiveChannels::baselines() const
{
    std::vector<std::pair<std::uint64_t, double>> baselines;
    for (const Span& span : m_spans) baselines.emplace_back(span.first, span.c0_f);
    return baselines;
}

const CapacitiveChannels::Span* CapacitiveChannels::spanAt(std::uint64_t index) const
{
    const auto span = std::ranges::find_if(m_spans, [&](const Span& s) { return index >= s.first && index < s.end; });
    return span == m_spans.end() ? nullptr : &*span;
}

double CapacitiveChannels::value(std::size_t channel, double capacitance_f, double c0_f) const
{
    const auto r = capacitive::CapacitiveReadout::readingAt(0.0, capacitance_f, c0_f, m_sensitivity);
    switch (channel) {
    case 0:
        return r.deltaC_f;
    case 1:
        return r.relativeChange;
    case 2:
        return r.force_n;
    default:
        return r.displacement_m;
    }
}

std::vector<std::vector<double>> CapacitiveChannels::read(std::uint64_t first, std::uint64_t count)
{
    const std::uint64_t end = std::min(m_sampleCount, first + std::min(count, m_sampleCount));
    const auto c = m_store.readChannel(m_session, m_channel, first, end > first ? end - first : 0);
    std::vector<std::vector<double>> out(4, std::vector<double>(c.size(), kNaN));
    const Span* span = nullptr;
    for (std::size_t s = 0; s < c.size(); ++s) {
        if (!span || first + s < span->first || first + s >= span->end) span = spanAt(first + s);
        if (!span) continue;
        for (std::size_t k = 0; k < 4; ++k) out[k][s] = value(k, m_input.farads(c[s]), span->c0_f);
    }
    return out;
}

std::vector<storage::OverviewPoint> CapacitiveChannels::overview(std::size_t channel, std::uint64_t first,
                                                                 std::uint64_t count, std::size_t points)
{
    if (channel >= 4) throw std::out_of_range("no derived channel " + std::to_string(channel));
    std::vector<storage::OverviewPoint> result;
    for (const auto& stretch : m_store.overview(m_session, m_channel, first, count, points)) {
        const std::uint64_t stretchEnd = stretch.firstIndex + stretch.count;
        const Span* span = spanAt(stretch.firstIndex);
        if (span && stretchEnd <= span->end) {  // one C0: increasing in C, which increases with the value
            result.push_back({stretch.firstIndex, stretch.count,
                              value(channel, m_input.farads(stretch.min), span->c0_f),
                              value(channel, m_input.farads(stretch.max), span->c0_f)});
            continue;
        }
        appendExactOverview(read(stretch.firstIndex, stretch.count)[channel], stretch.firstIndex, 1, result);
    }
    return result;
}

}  // namespace tactiscope::core::derived
