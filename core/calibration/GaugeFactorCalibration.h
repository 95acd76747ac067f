// Gauge-factor calibration of a strain-gauge cantilever: with the beam's
// geometry known, a known tip load F (or a known tip deflection Δ, i.e.
// F = k·Δ) puts a known strain ε = F·(6L/(E·w·t²)) on the root. Each
// calibration step's mean reading gives the relative resistance change
// x = GF·ε through the bridge equation, so the slope of x against ε is the
// effective gauge factor of the whole channel (gauge, bonding, wiring). The
// slope of counts against force is fitted too, for channels read directly
// in newtons.
#pragma once

#include "core/calibration/CalibrationRecord.h"
#include "core/calibration/StabilityMonitor.h"
#include "core/sensors/CantileverBeam.h"
#include "core/straingauge/StrainGaugeChain.h"

#include <string>
#include <vector>

namespace tactiscope::core::calibration {

struct CalibrationLoad {
    // Exactly one of the two is given (the other left at 0): a tip force, or
    // a tip deflection that the beam's stiffness turns into a force.
    double force_n = 0.0;
    double tipDeflection_m = 0.0;
    double meanCounts = 0.0;                // mean reading of the stable window at this load
    double meanStandardError_counts = 0.0;  // its standard uncertainty; 0: not known
};

// The unloaded reading: the mean of its stable window and that mean's
// standard uncertainty (0: not known).
struct ZeroReading {
    double meanCounts = 0.0;
    double meanStandardError_counts = 0.0;
};

// Force from a reading through a fitted counts-per-newton slope: the direct
// route, which needs neither the beam model nor the gauge factor.
struct ForceCalibration {
    double zeroCounts = 0.0;
    double countsPerNewton = 1.0;

    double force_n(double counts) const { return (counts - zeroCounts) / countsPerNewton; }
};

struct GaugeFactorResult {
    double gaugeFactor = 0.0;  // effective, from the fit
    // Its standard uncertainty (k = 1): propagated from each point's
    // standard error (the readings' noise, correlated samples included) and
    // scaled up by the fit's Birge ratio when the points scatter more than
    // that (settling, a swinging weight, a wrong mass). From the scatter
    // about the line alone when the points' errors are not known. The
    // beam's dimensions and modulus and the masses are taken as exact.
    double gaugeFactorUncertainty = 0.0;
    double nominalGaugeFactor = 0.0;
    double deviationFromNominal = 0.0;  // (effective − nominal) / nominal
    double countsPerNewton = 0.0;
    double zeroCounts = 0.0;
    // The fitted points, the zero first and then the loads in their order:
    // root strain and the bridge's relative change x = ΔR/R.
    std::vector<double> strain, relativeChange;
    LinearFit strainFit;  // x = GF·ε: slope is the gauge factor (weighted when the errors are known)
    LinearFit forceFit;   // counts − zero against force (likewise)
    CalibrationRecord record;

    ForceCalibration forceCalibration() const { return {zeroCounts, countsPerNewton}; }
};

// The points are weighted by their standard errors only when the zero's
// and every load's are known. Throws std::invalid_argument for fewer than
// two loads, a load with both or neither of force and deflection, or loads
// that are all equal.
GaugeFactorResult calibrateGaugeFactor(const sensors::CantileverBeam& beam, const straingauge::StrainGaugeChain& chain,
                                       const ZeroReading& zero, const std::vector<CalibrationLoad>& loads,
                                       const std::string& sensorName, const std::string& operatorName);

// What "stable" means for a bridge reading, scaled to the ADC: over 1 s a
// drift of at most 0.02 % of full scale per second and a σ of at most
// 0.1 % of full scale, far above a bridge amplifier's noise and far below a
// swinging beam, whatever the resolution.
StabilitySettings gaugeStabilityDefaults(const straingauge::StrainGaugeChain& chain);

// Whether a mean reading lies within 5 % of the ADC's limit: there the ADC,
// not the beam, may have set it (a clipped peak pulls the mean), so it is
// no calibration point.
bool nearAdcLimit(double meanCounts, const straingauge::StrainGaugeChain& chain);

// Standard gravity, for loads given as masses (1 gf = 9.80665 mN).
inline constexpr double kStandardGravity_m_per_s2 = 9.80665;

}  // namespace tactiscope::core::calibration
