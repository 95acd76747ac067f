// A calibration record's values in words, for reports and the review: each
// known field's label and unit, with its standard uncertainty beside it when
// the record holds one ("Sensitivity 1.8075 ± 0.0022 pF/mN"), never the
// record's key names ("sensitivity_pf_per_mn = 1.80751"). The keys stay
// what files and the JSON output carry; the numbers stay numbers, written
// by the one formatter of whoever shows them.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tactiscope::core::calibration {

struct CalibrationRow {
    std::string label;                  // "Sensitivity"
    double value = 0.0;                 // 1.80751
    std::optional<double> uncertainty;  // its standard uncertainty, 0.0021604, when the record has one
    std::string unit;                   // "pF/mN"; empty for a pure number
};

// The rows of `values` in their order; an uncertainty field is folded into
// the row of the value it belongs to, and a key this program does not know
// is written as its words ("new_field" → "New field").
std::vector<CalibrationRow> calibrationRows(const std::vector<std::pair<std::string, double>>& values);

}  // namespace tactiscope::core::calibration
