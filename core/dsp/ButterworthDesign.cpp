// liquid-dsp's Butterworth design, its sections read into doubles.
#include "core/dsp/ButterworthDesign.h"

#include "core/text/NumberFormat.h"

#include <complex>
#include <stdexcept>
#include <string>
// liquid.h takes std::complex for its complex types when compiled as C++.
#include <liquid/liquid.h>

namespace tactiscope::core::dsp {

// Above this fraction of the sample rate the pre-warping crowds the
// response against Nyquist: a cut-off there filters nothing useful.
inline constexpr double kMostCutoffCycles = 0.45;

std::vector<Biquad> butterworth(PassBand band, int order, double cutoff_hz, double sampleRate_hz)
{
    if (order < kLeastButterworthOrder || order > kMostButterworthOrder)
        throw std::invalid_argument("a Butterworth filter's order is 2 to 8, not " + std::to_string(order));
    const double cycles = cutoff_hz / sampleRate_hz;
    if (!(cycles > 0.0) || !(cycles < kMostCutoffCycles))
        throw std::invalid_argument("a cut-off must lie above 0 and below 0.45 of the sample rate (" +
                                    text::formatShortest(kMostCutoffCycles * sampleRate_hz) + " Hz)");
    const unsigned n = static_cast<unsigned>(order);
    const unsigned sections = n / 2 + n % 2;
    std::vector<float> b(3 * sections);
    std::vector<float> a(3 * sections);
    const int status =
        liquid_iirdes(LIQUID_IIRDES_BUTTER, band == PassBand::Low ? LIQUID_IIRDES_LOWPASS : LIQUID_IIRDES_HIGHPASS,
                      LIQUID_IIRDES_SOS, n, static_cast<float>(cycles), 0.0f, 1.0f, 60.0f, b.data(), a.data());
    if (status != LIQUID_OK) throw std::invalid_argument("liquid-dsp could not design the Butterworth filter");
    // The poles are liquid's. The zeros of a Butterworth low-pass lie at
    // z = −1 (a high-pass's at +1), so each numerator is (1 ± z⁻¹)² (or
    // 1 ± z⁻¹) scaled for unit gain in the pass band; scaled here in double,
    // because 1 + a1 + a2 of a section near DC is a small difference that
    // single precision leaves 0.1 % off at 1/500 of the sample rate.
    const double sign = band == PassBand::Low ? 1.0 : -1.0;
    std::vector<Biquad> result;
    result.reserve(sections);
    for (unsigned i = 0; i < sections; ++i) {
        const double a0 = static_cast<double>(a[3 * i]);
        const double a1 = static_cast<double>(a[3 * i + 1]) / a0;
        const double a2 = static_cast<double>(a[3 * i + 2]) / a0;
        const bool firstOrder = b[3 * i + 2] == 0.0f && a2 == 0.0;
        const double unit = firstOrder ? (1.0 + sign * a1) / 2.0 : (1.0 + sign * a1 + a2) / 4.0;
        result.push_back(firstOrder ? Biquad{unit, sign * unit, 0.0, a1, 0.0}
                                    : Biquad{unit, 2.0 * sign * unit, unit, a1, a2});
    }
    return result;
}

}  // namespace tactiscope::core::dsp
