// Step and press readings of the compliance probe.
#include "core/compliance/StiffnessReadings.h"

#include "core/calibration/LinearFit.h"
#include "core/text/JsonWriter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tactiscope::core::compliance {

StepReader::StepReader(const sensors::CompliancePair& pair, std::size_t readings)
    : m_pair(pair),
      m_readings(readings)
{
    if (readings < 2) throw std::invalid_argument("a step reading needs at least two readings");
    m_high.reserve(readings);
    m_low.reserve(readings);
}

std::optional<StepReading> StepReader::push(double forceHigh_n, double forceLow_n)
{
    m_high.push_back(forceHigh_n);
    m_low.push_back(forceLow_n);
    if (m_high.size() < m_readings) return std::nullopt;
    StepReading reading;
    reading.forceHigh = robustMean(m_high);
    reading.forceLow = robustMean(m_low);
    reading.q = reading.forceLow.mean != 0.0 ? reading.forceHigh.mean / reading.forceLow.mean : 0.0;
    reading.stiffness = m_pair.objectStiffness(reading.q);
    m_high.clear();
    m_low.clear();
    return reading;
}

PressReading readPress(const sensors::CompliancePair& pair, std::span<const double> displacement,
                       std::span<const double> forceHigh, std::span<const double> forceLow)
{
    if (displacement.empty() || displacement.size() != forceHigh.size() || forceHigh.size() != forceLow.size())
        throw std::invalid_argument("a press needs equal, non-empty series of displacement and forces");
    std::vector<double> stiffness, where;
    std::size_t below = 0, above = 0;
    for (std::size_t i = 0; i < displacement.size(); ++i) {
        const sensors::StiffnessReading k = pair.objectStiffness(forceHigh[i] / forceLow[i]);
        if (k.range == sensors::ComplianceRange::InRange) {
            stiffness.push_back(k.objectStiffness_n_per_m);
            where.push_back(displacement[i]);
        } else {
            ++(k.range == sensors::ComplianceRange::Below ? below : above);
        }
    }
    PressReading r;
    r.samplesOutOfRange = below + above;
    if (stiffness.size() * 2 < displacement.size()) {
        // Mostly out of range: no number, but which way it is out.
        r.stiffness.range = above > below ? sensors::ComplianceRange::Above : sensors::ComplianceRange::Below;
        return r;
    }
    std::vector<bool> kept;
    const RobustMean mean = robustMean(stiffness, 3.0, &kept);
    r.stiffness = {sensors::ComplianceRange::InRange, mean.mean};
    r.standardError_n_per_m = mean.standardError;
    r.samplesUsed = mean.used;
    r.samplesRejected = mean.rejected;
    // Range and slope over the kept samples only: a rejected spike must not
    // tilt the displacement check either.
    std::vector<double> keptStiffness, keptWhere;
    for (std::size_t i = 0; i < stiffness.size(); ++i) {
        if (kept[i]) {
            keptStiffness.push_back(stiffness[i]);
            keptWhere.push_back(where[i]);
        }
    }
    const auto [lo, hi] = std::minmax_element(keptWhere.begin(), keptWhere.end());
    r.displacementMin_m = *lo;
    r.displacementMax_m = *hi;
    if (*hi > *lo && keptStiffness.size() >= 3) {
        const calibration::LinearFit slope = calibration::fitLine(keptWhere, keptStiffness);
        r.displacementSlope_n_per_m_per_m = slope.slope;
        r.displacementSlopeStandardError = slope.slopeStandardError;
    }
    return r;
}

PressReader::PressReader(const sensors::CompliancePair& pair, PressSettings settings)
    : m_pair(pair),
      m_settings(settings)
{
    if (!(settings.contactThreshold_n > 0.0)) throw std::invalid_argument("contact threshold must be positive");
}

std::optional<PressReading> PressReader::push(double t_s, double displacement_m, double forceHigh_n, double forceLow_n)
{
    const double threshold = m_settings.contactThreshold_n;
    std::optional<PressReading> ended;
    if (m_pressing && (forceHigh_n < 0.5 * threshold || forceLow_n < 0.5 * threshold)) ended = close();
    if (!m_pressing && forceHigh_n > threshold && forceLow_n > threshold) {
        m_pressing = true;
        m_start_s = t_s;
    }
    if (m_pressing) {
        m_last_s = t_s;
        m_displacement.push_back(displacement_m);
        m_forceHigh.push_back(forceHigh_n);
        m_forceLow.push_back(forceLow_n);
        const sensors::StiffnessReading k = m_pair.objectStiffness(forceHigh_n / forceLow_n);
        if (k.range == sensors::ComplianceRange::InRange) {
            ++m_count;
            m_sum += k.objectStiffness_n_per_m;
            m_sumSquares += k.objectStiffness_n_per_m * k.objectStiffness_n_per_m;
        }
    }
    return ended;
}

std::optional<std::pair<double, double>> PressReader::current() const
{
    if (!m_pressing || m_count < 2) return std::nullopt;
    const auto n = static_cast<double>(m_count);
    const double mean = m_sum / n;
    const double variance = std::max(0.0, (m_sumSquares - n * mean * mean) / (n - 1.0));
    return std::pair{mean, std::sqrt(variance / n)};
}

std::optional<PressReading> PressReader::finish()
{
    return m_pressing ? close() : std::nullopt;
}

std::optional<PressReading> PressReader::close()
{
    m_pressing = false;
    std::optional<PressReading> result;
    if (m_displacement.size() >= m_settings.minimumSamples) {
        result = readPress(m_pair, m_displacement, m_forceHigh, m_forceLow);
        result->start_s = m_start_s;
        result->end_s = m_last_s;
    }
    m_displacement.clear();
    m_forceHigh.clear();
    m_forceLow.clear();
    m_count = 0;
    m_sum = m_sumSquares = 0.0;
    return result;
}

std::string pressDetailsJson(const PressReading& reading)
{
    text::JsonWriter json;
    json.beginObject();
    json.key("displacement_min_m").value(reading.displacementMin_m);
    json.key("displacement_max_m").value(reading.displacementMax_m);
    json.key("displacement_slope_n_per_m_per_m").value(reading.displacementSlope_n_per_m_per_m);
    json.key("displacement_slope_standard_error").value(reading.displacementSlopeStandardError);
    json.key("samples_used").value(static_cast<long long>(reading.samplesUsed));
    json.key("samples_rejected").value(static_cast<long long>(reading.samplesRejected));
    json.key("samples_out_of_range").value(static_cast<long long>(reading.samplesOutOfRange));
    json.endObject();
    return json.str();
}

PressSettings pressSettingsAt(double sampleRate_hz)
{
    PressSettings settings;
    settings.minimumSamples = std::max<std::size_t>(20, static_cast<std::size_t>(0.1 * sampleRate_hz));
    return settings;
}

}  // namespace tactiscope::core::compliance
