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
    // Five digits or more of uncertainty would be read as precision:
    // two significant digits times a power of ten, "(8.7 ± 1.5)·10⁶".
    if (uncertainty >= 1e4 && std::isfinite(uncertainty)) {
        const int exponent = static_cast<int>(std::floor(std::log10(uncertainty)));
        const double scale = std::pow(10.0, exponent);
        static const char* const kSuperscripts[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
        std::string power;
        for (const char digit : std::to_string(exponent)) power += kSuperscripts[digit - '0'];
        return "(" + fixed(value / scale, 1) + " ± " + fixed(uncertainty / scale, 1) + ")·10" + power + suffix;
    }
    const int decimals = uncertaintyDecimals(uncertainty);
    return fixed(value, decimals) + " ± " + fixed(uncertainty, decimals) + suffix;
}

}  // namespace tactiscope::core::text
