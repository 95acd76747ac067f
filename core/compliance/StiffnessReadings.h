// Turning the two forces of a compliance probe into a stiffness reading, in
// the two ways a user works:
//
// Step mode (the paper's procedure): hold the probe at one displacement,
// collect N readings of both forces (default 1000), reject each force's
// readings beyond 3σ, and compute Q and k_o from the two robust means.
//
// Press mode (a hand-held probe): a press starts when both forces exceed the
// contact threshold and ends when either falls below half of it (the
// hysteresis keeps a trembling hand from splitting one press into many).
// During the press k_o is computed for every sample; at the end the reading
// is the robust mean of those values with its standard error, the
// displacement range covered, and the slope of k_o against displacement —
// near zero if, as the method promises, the reading does not depend on how
// far the probe was pressed.
#pragma once

#include "core/compliance/RobustMean.h"
#include "core/sensors/CompliancePair.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tactiscope::core::compliance {

struct StepReading {
    sensors::StiffnessReading stiffness;
    double q = 0.0;
    RobustMean forceHigh;
    RobustMean forceLow;
};

class StepReader {
public:
    StepReader(const sensors::CompliancePair& pair, std::size_t readings = 1000);

    // Adds one pair of forces; returns the reading when N have been collected
    // (and starts over).
    std::optional<StepReading> push(double forceHigh_n, double forceLow_n);
    std::size_t collected() const { return m_high.size(); }

private:
    sensors::CompliancePair m_pair;
    std::size_t m_readings;
    std::vector<double> m_high, m_low;
};

struct PressReading {
    double start_s = 0.0;
    double end_s = 0.0;
    // In range: the robust mean of the press's per-sample stiffness.
    sensors::StiffnessReading stiffness;
    double standardError_n_per_m = 0.0;
    std::size_t samplesUsed = 0;
    std::size_t samplesRejected = 0;    // beyond 3σ
    std::size_t samplesOutOfRange = 0;  // Q ≤ 1 or Q ≥ k_h/k_l at that sample
    // When most samples were out of range, stiffness.range says which way.
    double displacementMin_m = 0.0;
    double displacementMax_m = 0.0;
    // d(k_o)/d(displacement) over the press and its standard error.
    double displacementSlope_n_per_m_per_m = 0.0;
    double displacementSlopeStandardError = 0.0;
};

// The reading of samples that all belong to one press: per-sample k_o from
// the force ratio, the robust mean of those in range, the displacement range
// and the slope of k_o against displacement. When most samples are out of
// range, the reading is that state instead of a number. Spans of equal
// length; throws std::invalid_argument when they differ or are empty.
PressReading readPress(const sensors::CompliancePair& pair, std::span<const double> displacement_m,
                       std::span<const double> forceHigh_n, std::span<const double> forceLow_n);

// A press's details beyond its value, as one JSON object for the session
// store: displacement_min_m, displacement_max_m,
// displacement_slope_n_per_m_per_m, displacement_slope_standard_error,
// samples_used, samples_rejected, samples_out_of_range.
std::string pressDetailsJson(const PressReading& reading);

struct PressSettings {
    double contactThreshold_n = 0.01;
    std::size_t minimumSamples = 20;  // shorter presses are taps, not readings
};
// At a stream's rate: a tenth of a second at least (a shorter contact is a
// tap, not a press), and never fewer than 20 samples.
PressSettings pressSettingsAt(double sampleRate_hz);

class PressReader {
public:
    explicit PressReader(const sensors::CompliancePair& pair, PressSettings settings = {});

    // One sample; returns a reading when a press has just ended.
    std::optional<PressReading> push(double t_s, double displacement_m, double forceHigh_n, double forceLow_n);
    // Ends the stream: returns the reading of a press still in progress.
    std::optional<PressReading> finish();

    bool pressing() const { return m_pressing; }
    // While pressing: the plain mean and standard error so far (for display).
    std::optional<std::pair<double, double>> current() const;

private:
    std::optional<PressReading> close();

    sensors::CompliancePair m_pair;
    PressSettings m_settings;
    bool m_pressing = false;
    double m_start_s = 0.0;
    double m_last_s = 0.0;
    std::vector<double> m_displacement, m_forceHigh, m_forceLow;
    // Running sums of the in-range k_o, for current().
    std::size_t m_count = 0;
    double m_sum = 0.0;
    double m_sumSquares = 0.0;
};

}  // namespace tactiscope::core::compliance
