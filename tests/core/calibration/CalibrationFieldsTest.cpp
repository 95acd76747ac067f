// A calibration record's values in words (issue 37): labels and units for
// the keys the calibrations write, the standard uncertainty folded into its
// value's row, unknown keys in words; never a key name.
#include "core/calibration/CalibrationFields.h"

#include <gtest/gtest.h>

using tactiscope::core::calibration::calibrationRows;

TEST(CalibrationFields, ACapacitiveRecordReadsAsLabelledRowsWithUnits)
{
    const auto rows = calibrationRows({{"c0_pf", 51.459},
                                       {"baseline_sigma_pf", 0.004578},
                                       {"sensitivity_pf_per_mn", 1.80751},
                                       {"sensitivity_standard_error_pf_per_mn", 0.0021604},
                                       {"detection_limit_mn", 0.0076}});
    ASSERT_EQ(rows.size(), 4U);  // the uncertainty is no row of its own
    EXPECT_EQ(rows[0].label, "Baseline C0");
    EXPECT_EQ(rows[0].value, 51.459);
    EXPECT_FALSE(rows[0].uncertainty);
    EXPECT_EQ(rows[0].unit, "pF");
    EXPECT_EQ(rows[1].label, "Baseline noise σ");
    EXPECT_EQ(rows[2].label, "Sensitivity");
    EXPECT_EQ(rows[2].value, 1.80751);
    EXPECT_EQ(rows[2].uncertainty, 0.0021604);  // folded into its value's row
    EXPECT_EQ(rows[2].unit, "pF/mN");
    EXPECT_EQ(rows[3].label, "Detection limit (3σ)");
    EXPECT_EQ(rows[3].unit, "mN");
}

TEST(CalibrationFields, UnknownKeysAreWordsAndALoneUncertaintyStays)
{
    const auto rows = calibrationRows({{"gauge_factor_standard_error", 0.01}, {"new_field", 3.0}});
    ASSERT_EQ(rows.size(), 2U);
    EXPECT_EQ(rows[0].label, "Gauge factor standard error");  // its value is missing: shown alone
    EXPECT_EQ(rows[1].label, "New field");
    EXPECT_EQ(rows[1].value, 3.0);
    for (const auto& row : rows) EXPECT_EQ(row.label.find('_'), std::string::npos) << row.label;
}
