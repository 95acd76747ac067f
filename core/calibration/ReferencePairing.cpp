// ReferencePairing: interpolating the reference at the beam's instants.
#include "core/calibration/ReferencePairing.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace tactiscope::core::calibration {

PairedSweep pairWithReference(std::span<const double> beam_t_s, std::span<const double> capacitance_f,
                              std::span<const double> reference_t_s, std::span<const double> force_n,
                              double referenceRate_hz)
{
    if (beam_t_s.size() != capacitance_f.size() || reference_t_s.size() != force_n.size())
        throw std::invalid_argument("every sample needs its time");
    if (!(referenceRate_hz > 0.0)) throw std::invalid_argument("the reference's rate must be positive");
    std::vector<double> t, f;  // the reference without its gaps
    for (std::size_t i = 0; i < force_n.size(); ++i)
        if (std::isfinite(force_n[i]) && std::isfinite(reference_t_s[i])) {
            t.push_back(reference_t_s[i]);
            f.push_back(force_n[i]);
        }

    PairedSweep result;
    // Neighbours further apart than two periods have a gap between them.
    const double longest_s = 2.0 / referenceRate_hz;
    std::size_t j = 0;
    for (std::size_t i = 0; i < beam_t_s.size(); ++i) {
        const double at = beam_t_s[i];
        if (!std::isfinite(capacitance_f[i]) || !std::isfinite(at)) continue;
        while (j + 1 < t.size() && t[j + 1] <= at) ++j;
        if (j + 1 >= t.size() || t[j] > at || t[j + 1] - t[j] > longest_s) {
            ++result.outsideReference;
            continue;
        }
        const double w = (at - t[j]) / (t[j + 1] - t[j]);
        result.recording.t_s.push_back(at);
        result.recording.capacitance_f.push_back(capacitance_f[i]);
        result.recording.load_n.push_back(f[j] + w * (f[j + 1] - f[j]));
    }
    if (result.recording.t_s.size() < 3)
        throw std::invalid_argument("the reference force and the capacitance share fewer than three instants");

    // A difference of single samples would be the reference's noise.
    const auto block = std::max<std::size_t>(1, static_cast<std::size_t>(0.5 * referenceRate_hz));
    std::optional<std::pair<double, double>> previous;  // mean time, mean force
    for (std::size_t k = 0; k + block <= t.size(); k += block) {
        double st = 0.0, sf = 0.0;
        for (std::size_t i = k; i < k + block; ++i) {
            st += t[i];
            sf += f[i];
        }
        const std::pair mean{st / static_cast<double>(block), sf / static_cast<double>(block)};
        if (previous && mean.first - previous->first < 1.0 + longest_s)  // not across a gap
            result.steepest_n_per_s = std::max(result.steepest_n_per_s, std::abs(mean.second - previous->second) /
                                                                            (mean.first - previous->first));
        previous = mean;
    }
    return result;
}

}  // namespace tactiscope::core::calibration
