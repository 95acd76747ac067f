// Decides when a signal has settled: over a sliding time window it fits a
// straight line and calls the signal stable when both the drift (the line's
// slope) and the noise (the scatter about the line) are below limits. A
// wizard's zero step, a capacitive baseline (C0) and each calibration load
// wait for this instead of a fixed delay.
#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <span>
#include <utility>

namespace tactiscope::core::calibration {

struct StabilitySettings {
    double window_s = 2.0;
    double maxDrift_per_s = 0.0;  // |slope| limit, in the signal's unit per second
    double maxNoise = 0.0;        // residual σ limit, in the signal's unit

    friend bool operator==(const StabilitySettings&, const StabilitySettings&) = default;
};

struct WindowStatistics {
    double mean = 0.0;
    double sigma = 0.0;  // scatter about the fitted line (n − 2)
    // Standard uncertainty of `mean` (k = 1): σ/√n widened for correlated
    // neighbouring samples (meanStandardError); 0 where not known.
    double meanStandardError = 0.0;
    double drift_per_s = 0.0;
    double start_s = 0.0;
    double end_s = 0.0;
    std::size_t count = 0;
    bool stable = false;

    double middle_s() const { return 0.5 * (start_s + end_s); }
};

class StabilityMonitor {
public:
    // Throws std::invalid_argument for a non-positive window or negative limits.
    explicit StabilityMonitor(StabilitySettings settings);

    // Adds a sample (times increasing); returns the statistics of the last
    // window once it spans window_s.
    std::optional<WindowStatistics> push(double t_s, double value);
    // The same in two halves, for a reader that takes samples in batches
    // and needs the statistics once per batch, not once per sample (each
    // evaluation fits a line through the whole window).
    void add(double t_s, double value);
    std::optional<WindowStatistics> statistics() const;
    void reset() { m_samples.clear(); }

private:
    StabilitySettings m_settings;
    std::deque<std::pair<double, double>> m_samples;
};

// Standard error of the mean of samples whose scatter about their trend is
// `residuals`: σ/√n for independent samples, widened by √((1+ρ)/(1−ρ)) for
// a lag-1 autocorrelation ρ > 0 (an AR(1) model of a filtered or wandering
// signal; ρ is capped at 0.95). Never narrowed for ρ < 0: a negative ρ from
// a few hundred samples is chance more often than physics.
double meanStandardError(std::span<const double> residuals);

// The first stable window of a recorded series at or after `from` (an
// index), or nothing.
std::optional<WindowStatistics> firstStableWindow(std::span<const double> t_s, std::span<const double> values,
                                                  const StabilitySettings& settings, std::size_t from = 0);

}  // namespace tactiscope::core::calibration
