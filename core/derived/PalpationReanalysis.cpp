// PalpationReanalysis: the stored samples chunk by chunk through the forces
// of each zero's span and one press reader.
#include "core/derived/PalpationReanalysis.h"

#include "core/compliance/PalpationForces.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tactiscope::core::derived {
namespace {

constexpr std::uint64_t kChunk = 1 << 16;  // samples per channel read at once

std::string siteOf(const std::vector<storage::SessionReading>& recorded, double start_s, double end_s,
                   const std::string& sessionSite)
{
    for (const auto& r : recorded)
        if (r.end_s >= start_s && r.start_s <= end_s && !r.site.empty()) return r.site;
    return sessionSite;
}

}  // namespace

PalpationReanalysis reanalysePalpation(storage::SessionStore& store, std::int64_t session,
                                       const sensors::CompliancePairProfile& probe,
                                       const std::vector<calibration::CalibrationRecord>& calibrations)
{
    const auto summary = store.session(session);
    if (!summary) throw storage::StorageError("there is no session " + std::to_string(session));
    if (summary->metadata.mode != Mode::Palpation)
        throw std::invalid_argument("session " + std::to_string(session) + " is not a palpation session");
    std::vector<ChannelDescriptor> raw;
    for (const auto& channel : store.channels(session)) raw.push_back(channel.descriptor);
    const double rate_hz = summary->sampleRate_hz;
    const auto settings = compliance::palpationSettings(probe, rate_hz, calibrations);
    compliance::PalpationForces forces(raw, settings);
    PalpationReanalysis result;
    result.basis = compliance::basisText(probe, settings);

    const auto zeros = store.zeros(session);
    const auto recorded = store.readings(session);
    std::vector<compliance::PressReading> presses;
    for (std::size_t z = 0; z < zeros.size(); ++z) {
        const auto zero = compliance::zeroFromJson(zeros[z].valuesJson);
        if (!zero)
            throw storage::StorageError("a zero of session " + std::to_string(session) +
                                        " cannot be read; the store is damaged");
        forces.setZero(zero->first, zero->second);
        // A new zero starts a new reader: the press in progress is dropped.
        compliance::PressReader reader(forces.pair(), settings.press);
        const std::uint64_t end = z + 1 < zeros.size() ? zeros[z + 1].firstIndex : summary->sampleCount;
        for (std::uint64_t first = zeros[z].firstIndex; first < end; first += kChunk) {
            const std::uint64_t count = std::min(kChunk, end - first);
            const auto high = store.readChannel(session, forces.highChannel(), first, count);
            const auto low = store.readChannel(session, forces.lowChannel(), first, count);
            const auto displacement = store.readChannel(session, forces.displacementChannel(), first, count);
            for (std::size_t s = 0; s < high.size(); ++s) {
                if (std::isnan(high[s]) || std::isnan(low[s]) || std::isnan(displacement[s])) {
                    reader = compliance::PressReader(forces.pair(), settings.press);  // a loss ends a press unread
                    continue;
                }
                const double t_s = static_cast<double>(first + s) / rate_hz;
                if (auto reading =
                        reader.push(t_s, displacement[s], forces.forceHigh(high[s]), forces.forceLow(low[s])))
                    presses.push_back(std::move(*reading));
            }
        }
    }
    for (const auto& press : presses) {
        if (press.stiffness.range != sensors::ComplianceRange::InRange) {
            ++result.outOfRange;
            continue;
        }
        storage::SessionReading reading;
        reading.kind = ReadingKind::Compliance;
        reading.quantity = "stiffness";
        reading.unit = "N/m";
        reading.start_s = press.start_s;
        reading.end_s = press.end_s;
        reading.value = press.stiffness.objectStiffness_n_per_m;
        reading.standardError = press.standardError_n_per_m;
        reading.site = siteOf(recorded, press.start_s, press.end_s, summary->metadata.site);
        reading.detailsJson = compliance::pressDetailsJson(press);
        result.readings.push_back(std::move(reading));
    }
    return result;
}

}  // namespace tactiscope::core::derived
