// Gauge-factor and counts-per-newton fits from calibration loads.
#include "core/calibration/GaugeFactorCalibration.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace tactiscope::core::calibration {

GaugeFactorResult calibrateGaugeFactor(const sensors::CantileverBeam& beam, const straingauge::StrainGaugeChain& chain,
                                       double zeroCounts, const std::vector<CalibrationLoad>& loads,
                                       const std::string& sensorName, const std::string& operatorName)
{
    if (loads.size() < 2) throw std::invalid_argument("gauge-factor calibration needs at least two loads");
    straingauge::StrainGaugeChain tared = chain;
    tared.tare(zeroCounts);

    // The zero step is a point too: no load, no strain.
    std::vector<double> strain{0.0}, change{0.0}, force{0.0}, counts{0.0};
    for (const CalibrationLoad& load : loads) {
        const bool byForce = load.force_n != 0.0;
        const bool byDeflection = load.tipDeflection_m != 0.0;
        if (byForce == byDeflection)
            throw std::invalid_argument("each calibration load needs either a force or a tip deflection");
        const double f = byForce ? load.force_n : load.tipDeflection_m * beam.stiffness_n_per_m();
        strain.push_back(f * beam.rootStrainPerNewton());
        change.push_back(tared.relativeChange(tared.bridgeRatio(load.meanCounts)));
        force.push_back(f);
        counts.push_back(load.meanCounts - zeroCounts);
    }

    GaugeFactorResult result;
    result.strainFit = fitLine(strain, change);
    result.forceFit = fitLine(force, counts);
    result.gaugeFactor = result.strainFit.slope;
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
                {"nominal_gauge_factor", result.nominalGaugeFactor},
                {"counts_per_newton", result.countsPerNewton},
                {"zero_counts", zeroCounts},
                {"counts_per_newton_standard_error", result.forceFit.slopeStandardError}};
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
