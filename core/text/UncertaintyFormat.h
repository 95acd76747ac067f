// How a measured value and its standard uncertainty are written, for the
// CLI and the GUI alike: the uncertainty to two significant digits and the
// value to the same decimal place (116.98 ± 0.034 N/m reads as 116.980 ±
// 0.034), so an uncertainty is never shown as "± 0.0".
#pragma once

#include <string>

namespace tactiscope::core::text {

// The decimal places of both: 0.034 → 3, 1.2 → 1, 56 → 0; at most
// `maximum`. 0 for an uncertainty of 0 or one that is not finite.
int uncertaintyDecimals(double uncertainty, int maximum = 9);

// "116.980 ± 0.034" (unit appended when given, after a space). An
// uncertainty below a billionth of the value — exact, synthetic data — is
// said in words: "174 (no scatter)".
std::string valueWithUncertainty(double value, double uncertainty, const std::string& unit = {});

}  // namespace tactiscope::core::text
