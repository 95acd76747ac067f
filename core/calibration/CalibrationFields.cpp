// CalibrationFields: the record keys' words and units.
#include "core/calibration/CalibrationFields.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string_view>

namespace tactiscope::core::calibration {
namespace {

struct Field {
    std::string_view key;
    std::string_view label;
    std::string_view unit;
    std::string_view uncertaintyKey;  // the field holding its standard uncertainty, if any
};

// Every key the calibrations write (CapacitiveCalibration, GaugeFactor…,
// the wizards): the units are those in the key's name.
constexpr Field kFields[] = {
    {"c0_pf", "Baseline C0", "pF", {}},
    {"baseline_sigma_pf", "Baseline noise σ", "pF", {}},
    {"drift_pf_per_s", "Baseline drift", "pF/s", {}},
    {"sensitivity_pf_per_mn", "Sensitivity", "pF/mN", "sensitivity_standard_error_pf_per_mn"},
    {"intercept_pf", "Intercept", "pF", {}},
    {"relative_sensitivity_per_mn", "Relative sensitivity", "per mN", {}},
    {"displacement_sensitivity_pf_per_mm", "Displacement sensitivity", "pF/mm", {}},
    {"detection_limit_mn", "Detection limit (3σ)", "mN", {}},
    {"detection_limit_mm", "Detection limit, as a tip displacement", "mm", {}},
    {"r_squared", "R²", {}, {}},
    {"gauge_factor", "Gauge factor", {}, "gauge_factor_standard_error"},
    {"nominal_gauge_factor", "Nominal gauge factor", {}, {}},
    {"counts_per_newton", "Counts per newton", "counts/N", "counts_per_newton_standard_error"},
    {"zero_counts", "Zero", "counts", {}},
    {"zero_sigma_counts", "Zero noise σ", "counts", {}},
    {"excitation_v", "Bridge excitation", "V", {}},
    {"amplifier_gain", "Amplifier gain", {}, {}},
    {"adc_reference_v", "ADC reference", "V", {}},
    {"adc_bits", "ADC resolution", "bits", {}},
    {"adc_bipolar", "ADC bipolar (1 = yes)", {}, {}},
    {"bridge_active_gauges", "Active gauges in the bridge", {}, {}},
    {"gauge_resistance_ohm", "Gauge resistance", "Ω", {}},
    {"shunt_resistance_ohm", "Shunt resistance", "Ω", {}},
    {"shunt_gauge_factor", "Gauge factor checked", {}, {}},
    {"shunt_expected_ue", "Expected step", "µε", {}},
    {"shunt_measured_ue", "Measured step", "µε", "shunt_measured_standard_error_ue"},
    {"shunt_deviation_percent", "Deviation", "%", {}},
    {"shunt_tolerance_percent", "Tolerance", "%", {}},
    {"shunt_passed", "Passed (1 = yes)", {}, {}},
};

const Field* fieldOf(std::string_view key)
{
    const auto found = std::ranges::find(kFields, key, &Field::key);
    return found == std::end(kFields) ? nullptr : &*found;
}

// The field whose standard uncertainty `key` holds, if it is one.
const Field* ownerOf(std::string_view key)
{
    const auto found = std::ranges::find(kFields, key, &Field::uncertaintyKey);
    return key.empty() || found == std::end(kFields) ? nullptr : &*found;
}

std::string words(std::string_view key)
{
    std::string text(key);
    std::ranges::replace(text, '_', ' ');
    if (!text.empty()) text[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
    return text;
}

}  // namespace

std::vector<CalibrationRow> calibrationRows(const std::vector<std::pair<std::string, double>>& values)
{
    const auto valueOf = [&values](std::string_view key) -> const double* {
        const auto found = std::ranges::find(values, key, &std::pair<std::string, double>::first);
        return found == values.end() ? nullptr : &found->second;
    };
    std::vector<CalibrationRow> rows;
    for (const auto& [key, value] : values) {
        const Field* field = fieldOf(key);
        if (!field) {
            // An uncertainty goes beside its value; alone, it is a row of its own.
            const Field* owner = ownerOf(key);
            if (!(owner && valueOf(owner->key))) rows.push_back({words(key), value, std::nullopt, {}});
            continue;
        }
        const double* uncertainty = field->uncertaintyKey.empty() ? nullptr : valueOf(field->uncertaintyKey);
        rows.push_back({std::string(field->label), value,
                        uncertainty && std::isfinite(*uncertainty) ? std::optional(*uncertainty) : std::nullopt,
                        std::string(field->unit)});
    }
    return rows;
}

}  // namespace tactiscope::core::calibration
