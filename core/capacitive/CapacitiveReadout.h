// Live readout of the capacitive beam: from each capacitance sample, ΔC,
// ΔC/C0, the force and the tip displacement, through a calibration or,
// before there is one, the beam model.
//
// Drift compensation rule: the baseline C0 follows slow drift only while the
// beam is known to be unloaded, i.e. while the signal has stayed within
// ±3σ (σ: the baseline noise) of C0 for at least 2 s; it then moves towards
// the signal with a 30 s time constant, slow enough not to follow a weight
// that is being placed. While loaded C0 is frozen, and tare() re-baselines
// at once (to a 0.5 s running mean of the signal).
//
// The C0 in use steps to the tracked one whenever they differ by more than
// kStep_sigmas·σ, rather than moving every sample: the readings differ from
// a continuous C0 by at most that, and a recording can store each step
// (baselineChanges() counts every change of C0), so a review derives the
// same ΔC, force and deflection from the stored samples (readingAt()).
#pragma once

#include "core/calibration/CapacitiveCalibration.h"
#include "core/sensors/CapacitiveBeam.h"

#include <cstdint>
#include <optional>

namespace tactiscope::core::capacitive {

struct CapacitiveSensitivity {
    double c0_f = 0.0;
    double perNewton_f = 0.0;  // ΔC per newton at the tip
    double perMetre_f = 0.0;   // ΔC per metre of tip deflection

    static CapacitiveSensitivity fromModel(const sensors::CapacitiveBeam& beam);
    // Uses the calibration's fits; a missing one (only forces, or only
    // displacements, were calibrated) comes from the model through k_s.
    static CapacitiveSensitivity fromCalibration(const calibration::CapacitiveCalibrationResult& calibration,
                                                 const sensors::CapacitiveBeam& beam);
};

struct DriftSettings {
    double noiseSigma_f = 0.0;  // baseline noise σ; 0 disables drift tracking
    double quietBand_sigmas = 3.0;
    double quietFor_s = 2.0;
    double timeConstant_s = 30.0;
};

struct CapacitiveReading {
    double t_s = 0.0;
    double capacitance_f = 0.0;
    double c0_f = 0.0;
    double deltaC_f = 0.0;
    double relativeChange = 0.0;  // ΔC/C0
    double force_n = 0.0;
    double displacement_m = 0.0;
    bool unloaded = false;  // the drift rule sees a quiet, unloaded beam
};

class CapacitiveReadout {
public:
    static constexpr double kStep_sigmas = 0.05;

    // One sample read on a given C0: the per-sample formulas, shared with the
    // stored session's derived channels (core/derived).
    static CapacitiveReading readingAt(double t_s, double capacitance_f, double c0_f,
                                       const CapacitiveSensitivity& sensitivity);

    // Throws std::invalid_argument for non-positive sensitivities or C0.
    CapacitiveReadout(const CapacitiveSensitivity& sensitivity, const DriftSettings& drift);

    CapacitiveReading push(double t_s, double capacitance_f);
    void tare();
    void setBaseline(double c0_f);
    double c0_f() const { return m_c0_f; }
    const CapacitiveSensitivity& sensitivity() const { return m_sensitivity; }
    // How many times C0 changed (tare, setBaseline, a drift step) so far.
    std::uint64_t baselineChanges() const { return m_baselineChanges; }

private:
    CapacitiveSensitivity m_sensitivity;
    DriftSettings m_drift;
    double m_c0_f;
    double m_tracked_f;  // the drift rule's C0, which m_c0_f steps to
    std::uint64_t m_baselineChanges = 0;
    std::optional<double> m_last_s;
    double m_smoothed_f = 0.0;
    double m_quietSince_s = 0.0;
    bool m_quiet = false;
};

}  // namespace tactiscope::core::capacitive
