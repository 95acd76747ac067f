// The windows a spectrum is taken through: Hann for the power spectral
// density (low leakage, good resolution), flat-top for reading a line's
// amplitude (its main lobe is flat to 0.01 dB, so a sine between two bins
// reads its true amplitude). Periodic forms, as Welch's segments want.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace tactiscope::core::dsp {

enum class SpectralWindow { Hann, FlatTop };

std::string_view toString(SpectralWindow window);                               // "hann", "flattop"
std::optional<SpectralWindow> spectralWindowFromString(std::string_view name);  // none for another word

std::vector<double> windowCoefficients(SpectralWindow window, std::size_t length);

}  // namespace tactiscope::core::dsp
