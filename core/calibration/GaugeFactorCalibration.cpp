// Gauge-factor and counts-per-newton fits from calibration loads.
#include "core/calibration/GaugeFactorCalibration.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace tactiscope::core::calibration {

GaugeFactorResult calibrateGaugeFactor(const sensors::CantileverBeam& beam, const straingauge::StrainGaugeChain& chain,
                                       const ZeroReading& zero, const std::vector<CalibrationLoad>& loads,
                                       const std::string& sensorName, const std::string& operatorName)
{
    if (loads.size() < 2) throw std::invalid_argument("gauge-factor calibration needs at least two loads");
    const double zeroCounts = zero.meanCounts;
    straingauge::StrainGaugeChain tared = chain;
    tared.tare(zeroCounts);
    const auto relativeChange = [&](double counts) { return tared.relativeChange(tared.bridgeRatio(counts)); };
    // A reading's standard error carried through the (nearly linear) bridge equation.
    const auto changeError = [&](double counts, double error) {
        return std::abs(relativeChange(counts + error) - relativeChange(counts));
    };

    // The zero step is a point too: no load, no strain. Its error is its
    // own; taring by it shifts every load point alike, which the fit's
    // intercept takes up, so the points stay independent.
    std::vector<double> strain{0.0}, change{0.0}, force{0.0}, counts{0.0};
    std::vector<double> changeErrors{changeError(zeroCounts, zero.meanStandardError_counts)};
    std::vector<double> countErrors{zero.meanStandardError_counts};
    for (const CalibrationLoad& load : loads) {
        const bool byForce = load.force_n != 0.0;
        const bool byDeflection = load.tipDeflection_m != 0.0;
        if (byForce == byDeflection)
            throw std::invalid_argument("each calibration load needs either a force or a tip deflection");
        const double f = byForce ? load.force_n : load.tipDeflection_m * beam.stiffness_n_per_m();
        strain.push_back(f * beam.rootStrainPerNewton());
        change.push_back(relativeChange(load.meanCounts));
        force.push_back(f);
        counts.push_back(load.meanCounts - zeroCounts);
        changeErrors.push_back(changeError(load.meanCounts, load.meanStandardError_counts));
        countErrors.push_back(load.meanStandardError_counts);
    }
    const bool errorsKnown = std::all_of(changeErrors.begin(), changeErrors.end(), [](double u) { return u > 0.0; });

    GaugeFactorResult result;
    result.strainFit = errorsKnown ? fitLineWithUncertainties(strain, change, changeErrors) : fitLine(strain, change);
    result.forceFit = errorsKnown ? fitLineWithUncertainties(force, counts, countErrors) : fitLine(force, counts);
    result.gaugeFactor = result.strainFit.slope;
    result.gaugeFactorUncertainty = result.strainFit.slopeStandardError;
    result.nominalGaugeFactor = chain.bridge().gaugeFactor;
    result.deviationFromNominal = (result.gaugeFactor - result.nominalGaugeFactor) / result.nominalGaugeFactor;
    result.countsPerNewton = result.forceFit.slope;
    result.strain = std::move(strain);
    result.relativeChange = std::move(change);
    result.zeroCounts = zeroCounts;

    CalibrationRecord& r = result.record;
    r.kind = kGaugeFactorKind;
    r.sensorName = sensorName;
    r.operatorName = operatorName;
    r.timestampUtc = utcTimestampNow();
    r.values = {{"gauge_factor", result.gaugeFactor},
                {"gauge_factor_standard_error", result.gaugeFactorUncertainty},
                {"nominal_gauge_factor", result.nominalGaugeFactor},
                {"counts_per_newton", result.countsPerNewton},
                {"zero_counts", zeroCounts},
                {"counts_per_newton_standard_error", result.forceFit.slopeStandardError}};
    if (errorsKnown) r.values.emplace_back("birge_ratio", result.strainFit.birgeRatio);
    r.fit = result.strainFit;
    return result;
}

StabilitySettings gaugeStabilityDefaults(const straingauge::StrainGaugeChain& chain)
{
    const double fullScale = chain.fullScaleCounts();
    return {1.0, 2e-4 * fullScale, 1e-3 * fullScale};
}

bool nearAdcLimit(double meanCounts, const straingauge::StrainGaugeChain& chain)
{
    return std::abs(meanCounts) > 0.95 * chain.fullScaleCounts();
}

}  // namespace tactiscope::core::calibration
