// Turning the two forces of a compliance probe into a stiffness reading, in
// the two ways a user works:
//
// Step mode (the paper's procedure): hold the probe at one displacement,
// collect N readings of both forces (default 1000), reject each force's
// readings beyond 3σ once, and compute Q and k_o from the two means.
//
// Press mode (a hand-held probe): a press starts when both forces exceed the
// contact threshold and ends when either falls below half of it (the
// hysteresis keeps a trembling hand from splitting one press into many).
// The press's Q is the ratio of its summed forces, ΣF_H/ΣF_L: the force
// noise is the same at every depth, so each sample weighs by its force,
// where a mean of per-sample k_o would weigh the shallow samples — whose k_o
// is mostly noise — as much as the deep ones (and a 3σ cut on those would
// reject the shallow end of every press). Pairs whose residual
// F_H − Q·F_L lies beyond 3σ are rejected once, as the paper rejects its
// readings. The reading carries the displacement range covered and the
// slope of k_o against displacement — near zero if, as the method
// promises, the reading does not depend on how far the probe was pressed —
// fitted on the residuals F_H − Q·F_L (whose noise is the same at every
// depth), its standard error widened for correlated neighbours and with the
// zero's part, since a zero offset tilts k_o against depth (its error goes
// as 1/force).
//
// Uncertainty: the standard error from the residuals' scatter (white force
// noise), and, when the zero's own uncertainty is known, the part a zero
// error adds: an offset δ in a force shifts every sample of the press alike,
// so it does not average away. k_o moves by (dk_o/dQ)·δ/F̄_L for an offset of
// F_H and by −(dk_o/dQ)·Q·δ/F̄_L for one of F_L (F̄_L the press's mean soft
// force); the combined standard uncertainty adds both parts in quadrature
// with the noise. Systematic terms of the beam model (E, t³, L³) are not in
// it: docs/compliance.md states them.
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

// What a press's reading is. Ok: a stiffness with its uncertainty.
// Clipped: a beam's ADC was at (or within 1 % of) its limit during the
// press, so its force — and the ratio — is not what the beam felt: no
// number. Below/above range: the ratio lies within 2u of the probe's limit
// (Q = 1, or Q = k_h/k_l), where k_o runs off to 0 or infinity and a number
// would be a bias, not a reading: the bound it is below or above instead.
// u is the ratio's whole standard uncertainty, the zero's part with the
// noise's: without it the bounds at 0.3 N/m lay on the wrong side of the
// truth for 9 of 87 presses.
enum class PressStatus { Ok, Clipped, BelowRange, AboveRange };
// "ok", "clipped", "below-range", "above-range" (the JSON's words).
const char* statusName(PressStatus status);

// Samples of a press at the ADC's limit, per beam.
struct BeamLimits {
    std::size_t high = 0;
    std::size_t low = 0;
};

// The standard uncertainty of a zero in each beam's force, N.
struct ZeroUncertainty {
    double high_n = 0.0;
    double low_n = 0.0;
};

struct PressReading {
    double start_s = 0.0;
    double end_s = 0.0;
    PressStatus status = PressStatus::Ok;
    // Out of range: the k_o the object is below (BelowRange) or above
    // (AboveRange), at 2u from the ratio; none when that is the limit itself.
    std::optional<double> bound_n_per_m;
    BeamLimits atLimit;  // samples at the ADC's limit
    // k_o of the press's force ratio ΣF_H/ΣF_L (a number only when status is Ok).
    sensors::StiffnessReading stiffness;
    double q = 0.0;
    double standardError_n_per_m = 0.0;  // from the noise of the forces
    // The ratio's standard uncertainty: its noise's, and the whole with
    // (when known) the zero's.
    double ratioStandardError = 0.0;
    double ratioUncertainty = 0.0;
    // k_o at Q − 2u and Q + 2u through the exact map (eq. 2), for a press read
    // Ok: limits of about 95 %, asymmetric near the probe's ends, where a
    // linearised ±2u would reach below zero or far short of the truth.
    double lowerLimit_n_per_m = 0.0;
    double upperLimit_n_per_m = 0.0;
    std::optional<double> zeroUncertainty_n_per_m;  // from the zero's; none when it is not known
    double offsetSensitivityHigh_per_m = 0.0;       // dk_o per N of offset in F_H, N/m per N
    double offsetSensitivityLow_per_m = 0.0;        // the same for F_L
    std::size_t samplesUsed = 0;
    std::size_t samplesRejected = 0;    // residual beyond 3σ
    std::size_t samplesOutOfRange = 0;  // Q ≤ 1 or Q ≥ k_h/k_l at that sample (kept: they are noise, not a cut)
    double displacementMin_m = 0.0;
    double displacementMax_m = 0.0;
    // d(k_o)/d(displacement) over the press and its standard error.
    double displacementSlope_n_per_m_per_m = 0.0;
    double displacementSlopeStandardError = 0.0;

    // The combined standard uncertainty: noise and, when known, the zero.
    double uncertainty_n_per_m() const;
};

// The reading of samples that all belong to one press (see above). When
// most samples are out of range, the reading is that state instead of a
// number. Spans of equal length; throws std::invalid_argument when they
// differ or are empty.
PressReading readPress(const sensors::CompliancePair& pair, std::span<const double> displacement_m,
                       std::span<const double> forceHigh_n, std::span<const double> forceLow_n,
                       std::optional<ZeroUncertainty> zero = std::nullopt, BeamLimits atLimit = {});

// Whether limits about a value are lopsided: one side half again the
// other's or more (near k_h/k_l), where "± u" says too little and the
// limits are shown beside it.
bool lopsidedLimits(double value, double lower, double upper);

// A beam read in ADC counts: the force of one count and of its full scale
// (from its zero count to where it clips).
struct BeamResolution {
    double step_n = 0.0;
    double fullScale_n = 0.0;
};

// The k_o range the probe can read at all, from its profile (k_h, k_l) and
// its converters: a ratio taken at the deepest press its ADCs allow (the
// first beam at full scale), with each force known to one count's
// quantization (step/√12), must lie 2u inside Q = 1 and Q = k_h/k_l. A
// property of the probe, not of a session's presses (which gave 0.018 to
// 5.3·10⁶ N/m for one 117 N/m phantom and another range for the next);
// none when a beam's counts or range are not known (a device that sends
// strain or force). Noise and the zero narrow it further for any one press.
std::optional<std::pair<double, double>>
usableRange(const sensors::CompliancePair& pair, std::optional<BeamResolution> high, std::optional<BeamResolution> low);

// A press's details beyond its value, as one JSON object for the session
// store: q, noise_standard_error_n_per_m, zero_uncertainty_n_per_m (when
// known), displacement_min_m, displacement_max_m,
// displacement_slope_n_per_m_per_m,
// displacement_slope_standard_error_n_per_m_per_m, samples_used,
// samples_rejected, samples_out_of_range.
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

    // One sample (with whether each beam's ADC is at its limit); returns a
    // reading when a press has just ended.
    std::optional<PressReading> push(double t_s, double displacement_m, double forceHigh_n, double forceLow_n,
                                     BeamLimits atLimit = {});
    // Ends the stream: returns the reading of a press still in progress.
    std::optional<PressReading> finish();
    // Drops a press in progress unread (a lost sample, a new zero).
    void dropPress();
    // The uncertainty of the zero the forces are read on, for the readings
    // to come; none: not known.
    void setZeroUncertainty(std::optional<ZeroUncertainty> zero) { m_zero = zero; }

    bool pressing() const { return m_pressing; }
    double pressStart_s() const { return m_start_s; }  // while pressing
    // The samples of the press in progress at the ADC's limit, per beam.
    const BeamLimits& pressAtLimit() const { return m_atLimit; }
    // While pressing: k_o of the force ratio so far and its standard error
    // (for display); none before two samples or out of range.
    std::optional<std::pair<double, double>> current() const;

private:
    std::optional<PressReading> close();

    sensors::CompliancePair m_pair;
    PressSettings m_settings;
    std::optional<ZeroUncertainty> m_zero;
    bool m_pressing = false;
    double m_start_s = 0.0;
    double m_last_s = 0.0;
    std::vector<double> m_displacement, m_forceHigh, m_forceLow;
    BeamLimits m_atLimit;
    // Running sums of the press's forces, for current().
    std::size_t m_count = 0;
    double m_sumHigh = 0.0, m_sumLow = 0.0, m_sumHighHigh = 0.0, m_sumHighLow = 0.0, m_sumLowLow = 0.0;
};

}  // namespace tactiscope::core::compliance
