// PalpationReanalysis: the stored samples chunk by chunk through the forces
// of each zero's span and one press reader.
#include "core/derived/PalpationReanalysis.h"

#include "core/compliance/LivePalpation.h"
#include "core/compliance/PalpationForces.h"
#include "core/signal/SteadyWindow.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
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

namespace {

// The zeros a session's samples are read on: the recording's, else the
// first one taken as the live view takes it — the mean of the first
// kTare_s with its standard error, applying from the sample after.
std::vector<storage::SessionZero> zerosOf(storage::SessionSource& store, std::int64_t session,
                                          const storage::SessionSummary& summary,
                                          const compliance::PalpationForces& forces, bool& recorded)
{
    auto zeros = store.zeros(session);
    recorded = !zeros.empty();
    if (recorded) return zeros;
    const auto samples =
        static_cast<std::uint64_t>(std::lround(compliance::LivePalpation::kTare_s * summary.sampleRate_hz));
    if (samples < 2 || summary.sampleCount <= samples)
        throw std::invalid_argument("session " + std::to_string(session) + " is shorter than the first zero (" +
                                    std::to_string(compliance::LivePalpation::kTare_s) + " s)");
    // The window's mean and σ/√n as the live tare reads them (SteadyWindow).
    const auto meanAndError = [&](std::size_t channel) {
        signal::SteadyWindow window(std::max<std::size_t>(4, samples));
        for (const double v : store.readChannel(session, channel, 0, samples)) window.push(v);
        if (std::isnan(window.mean()))
            throw std::invalid_argument("session " + std::to_string(session) + " lost samples in its first zero");
        return std::pair{window.mean(), window.standardErrorOfMean()};
    };
    const auto [high, highU] = meanAndError(forces.highChannel());
    const auto [low, lowU] = meanAndError(forces.lowChannel());
    return {{samples, compliance::zeroJson({high, low, std::pair{highU, lowU}})}};
}

// Every sample with its forces, zero span by zero span: `restart` at each
// new zero (with its uncertainty) and at each lost sample, `sample` for the
// others.
void forEachForceSample(storage::SessionSource& store, std::int64_t session, const storage::SessionSummary& summary,
                        compliance::PalpationForces& forces, const std::vector<storage::SessionZero>& zeros,
                        const std::function<void(std::optional<compliance::ZeroUncertainty>)>& restart,
                        const std::function<void(const ForceSample&)>& sample)
{
    for (std::size_t z = 0; z < zeros.size(); ++z) {
        const auto zero = compliance::zeroFromJson(zeros[z].valuesJson);
        if (!zero)
            throw storage::StorageError("a zero of session " + std::to_string(session) +
                                        " cannot be read; the store is damaged");
        forces.setZero(*zero);
        restart(forces.zeroUncertainty());
        const std::uint64_t end = z + 1 < zeros.size() ? zeros[z + 1].firstIndex : summary.sampleCount;
        for (std::uint64_t first = zeros[z].firstIndex; first < end; first += kChunk) {
            const std::uint64_t count = std::min(kChunk, end - first);
            const auto high = store.readChannel(session, forces.highChannel(), first, count);
            const auto low = store.readChannel(session, forces.lowChannel(), first, count);
            const auto displacement = store.readChannel(session, forces.displacementChannel(), first, count);
            for (std::size_t s = 0; s < high.size(); ++s) {
                if (std::isnan(high[s]) || std::isnan(low[s]) || std::isnan(displacement[s])) {
                    restart(forces.zeroUncertainty());
                    continue;
                }
                sample({static_cast<double>(first + s) / summary.sampleRate_hz, forces.displacement_m(displacement[s]),
                        forces.forceHigh(high[s]), forces.forceLow(low[s]), forces.limitsOf(high[s], low[s])});
            }
        }
    }
}

// What reading a session's forces needs: its summary, the forces of its
// probe and the zeros.
struct SessionForces {
    storage::SessionSummary summary;
    compliance::LivePalpationSettings settings;
    std::unique_ptr<compliance::PalpationForces> forces;
    std::vector<storage::SessionZero> zeros;
    bool recordedZeros = false;
    std::string basis;
};

SessionForces sessionForces(storage::SessionSource& store, std::int64_t session,
                            const sensors::CompliancePairProfile& probe,
                            const std::vector<calibration::CalibrationRecord>& calibrations)
{
    const auto summary = store.session(session);
    if (!summary) throw storage::StorageError("there is no session " + std::to_string(session));
    std::vector<ChannelDescriptor> raw;
    for (const auto& channel : store.channels(session)) raw.push_back(channel.descriptor);
    SessionForces f;
    f.summary = *summary;
    f.settings = compliance::palpationSettings(probe, summary->sampleRate_hz, raw, calibrations);
    f.forces = std::make_unique<compliance::PalpationForces>(raw, f.settings);
    f.basis = compliance::basisText(probe, f.settings);
    f.zeros = zerosOf(store, session, *summary, *f.forces, f.recordedZeros);
    return f;
}

}  // namespace

PalpationPresses readPalpationPresses(storage::SessionSource& store, std::int64_t session,
                                      const sensors::CompliancePairProfile& probe,
                                      const std::vector<calibration::CalibrationRecord>& calibrations)
{
    auto f = sessionForces(store, session, probe, calibrations);
    PalpationPresses result;
    result.basis = f.basis;
    result.recordedZeros = f.recordedZeros;
    result.usableRange_n_per_m =
        compliance::usableRange(f.forces->pair(), f.forces->resolution(true), f.forces->resolution(false));
    // As live: a new zero or a lost sample drops the press in progress, and
    // so does the end of the recording.
    compliance::PressReader reader(f.forces->pair(), f.settings.press);
    forEachForceSample(
        store, session, f.summary, *f.forces, f.zeros,
        [&reader](std::optional<compliance::ZeroUncertainty> zero) {
            reader.dropPress();
            reader.setZeroUncertainty(zero);
        },
        [&](const ForceSample& s) {
            if (auto reading = reader.push(s.t_s, s.displacement_m, s.forceHigh_n, s.forceLow_n, s.atLimit))
                result.presses.push_back(std::move(*reading));
        });
    return result;
}

PalpationForceSamples readPalpationForces(storage::SessionSource& store, std::int64_t session,
                                          const sensors::CompliancePairProfile& probe,
                                          const std::vector<calibration::CalibrationRecord>& calibrations)
{
    auto f = sessionForces(store, session, probe, calibrations);
    PalpationForceSamples result;
    result.basis = f.basis;
    result.recordedZeros = f.recordedZeros;
    result.contactThreshold_n = f.forces->contactThreshold_n();
    forEachForceSample(
        store, session, f.summary, *f.forces, f.zeros, [](std::optional<compliance::ZeroUncertainty>) {},
        [&result](const ForceSample& s) { result.samples.push_back(s); });
    return result;
}

PalpationReanalysis reanalysePalpation(storage::SessionSource& store, std::int64_t session,
                                       const sensors::CompliancePairProfile& probe,
                                       const std::vector<calibration::CalibrationRecord>& calibrations)
{
    const auto summary = store.session(session);
    if (!summary) throw storage::StorageError("there is no session " + std::to_string(session));
    if (summary->metadata.mode != Mode::Palpation)
        throw std::invalid_argument("session " + std::to_string(session) + " is not a palpation session");
    auto read = readPalpationPresses(store, session, probe, calibrations);
    PalpationReanalysis result;
    result.basis = std::move(read.basis);
    const auto recorded = store.readings(session);
    for (const auto& press : read.presses) {
        if (press.status != compliance::PressStatus::Ok) {
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
        reading.standardError = press.uncertainty_n_per_m();
        reading.site = siteOf(recorded, press.start_s, press.end_s, summary->metadata.site);
        reading.detailsJson = compliance::pressDetailsJson(press);
        result.readings.push_back(std::move(reading));
    }
    return result;
}

}  // namespace tactiscope::core::derived
