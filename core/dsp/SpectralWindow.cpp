// Hann and flat-top windows (the flat-top's five cosine terms are the
// usual "SFT"-family ones also used by MATLAB's flattopwin and SciPy).
#include "core/dsp/SpectralWindow.h"

#include <array>
#include <cmath>
#include <numbers>
#include <span>

namespace tactiscope::core::dsp {

std::string_view toString(SpectralWindow window)
{
    return window == SpectralWindow::Hann ? "hann" : "flattop";
}

std::optional<SpectralWindow> spectralWindowFromString(std::string_view name)
{
    if (name == "hann") return SpectralWindow::Hann;
    if (name == "flattop") return SpectralWindow::FlatTop;
    return std::nullopt;
}

std::vector<double> windowCoefficients(SpectralWindow window, std::size_t length)
{
    static constexpr std::array<double, 2> hann{0.5, 0.5};
    static constexpr std::array<double, 5> flatTop{0.21557895, 0.41663158, 0.277263158, 0.083578947, 0.006947368};
    const std::span<const double> terms =
        window == SpectralWindow::Hann ? std::span<const double>(hann) : std::span<const double>(flatTop);
    std::vector<double> w(length);
    for (std::size_t i = 0; i < length; ++i) {
        const double phase = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(length);
        double value = 0.0;
        double sign = 1.0;
        for (std::size_t k = 0; k < terms.size(); ++k, sign = -sign)
            value += sign * terms[k] * std::cos(static_cast<double>(k) * phase);
        w[i] = value;
    }
    return w;
}

}  // namespace tactiscope::core::dsp
