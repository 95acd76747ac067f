// UncertaintyFormat: two significant digits of the uncertainty.
#include "core/text/UncertaintyFormat.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tactiscope::core::text {
namespace {

std::string fixed(double value, int decimals)
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return buffer;
}

}  // namespace

int uncertaintyDecimals(double uncertainty, int maximum)
{
    if (!(uncertainty > 0.0) || !std::isfinite(uncertainty)) return 0;
    // Two significant digits: the first is at 10^floor(log10 u).
    int decimals = 1 - static_cast<int>(std::floor(std::log10(uncertainty)));
    // 0.0995 rounds to 0.10 at three decimals: the digits are counted after rounding.
    if (std::abs(std::round(uncertainty * std::pow(10.0, decimals))) >= 100.0) --decimals;
    return std::clamp(decimals, 0, maximum);
}

std::string valueWithUncertainty(double value, double uncertainty, const std::string& unit)
{
    const std::string suffix = unit.empty() ? std::string() : " " + unit;
    if (!(uncertainty > std::abs(value) * 1e-9)) {
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%.9g", value);
        return buffer + suffix + " (no scatter)";
    }
    const int decimals = uncertaintyDecimals(uncertainty);
    return fixed(value, decimals) + " ± " + fixed(uncertainty, decimals) + suffix;
}

}  // namespace tactiscope::core::text
