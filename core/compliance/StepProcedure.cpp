// StepProcedure: samples to steps, each step through a StepReader.
#include "core/compliance/StepProcedure.h"

#include <cmath>
#include <map>
#include <stdexcept>

namespace tactiscope::core::compliance {

StepProcedureReading readSteps(const sensors::CompliancePair& pair, std::span<const double> displacement,
                               std::span<const double> forceHigh, std::span<const double> forceLow,
                               const StepSettings& settings)
{
    if (displacement.size() != forceHigh.size() || forceHigh.size() != forceLow.size())
        throw std::invalid_argument("the step procedure needs equal series of displacement and forces");
    if (!(settings.step_m > 0.0)) throw std::invalid_argument("the step must be a positive displacement");
    // Each step's samples, in time order.
    std::map<long long, std::vector<std::size_t>> byStep;
    for (std::size_t i = 0; i < displacement.size(); ++i) {
        if (!(forceHigh[i] > settings.contactThreshold_n && forceLow[i] > settings.contactThreshold_n)) continue;
        const long long step = std::llround(displacement[i] / settings.step_m);
        if (step >= 1) byStep[step].push_back(i);  // the first step is one step into the object
    }
    StepProcedureReading result;
    std::vector<double> inRange;
    for (const auto& [step, samples] : byStep) {
        ProcedureStep procedureStep;
        procedureStep.displacement_m = static_cast<double>(step) * settings.step_m;
        procedureStep.available = samples.size();
        if (samples.size() >= settings.readings) {
            StepReader reader(pair, settings.readings);
            for (std::size_t k = 0; k < settings.readings && !procedureStep.reading; ++k)
                procedureStep.reading = reader.push(forceHigh[samples[k]], forceLow[samples[k]]);
            if (procedureStep.reading->stiffness.range == sensors::ComplianceRange::InRange)
                inRange.push_back(procedureStep.reading->stiffness.objectStiffness_n_per_m);
        }
        result.steps.push_back(procedureStep);
    }
    result.stepsInRange = inRange.size();
    if (inRange.empty()) return result;
    double sum = 0.0;
    for (const double k : inRange) sum += k;
    const auto n = static_cast<double>(inRange.size());
    result.stiffness_n_per_m = sum / n;
    if (inRange.size() >= 2) {
        double squares = 0.0;
        for (const double k : inRange) squares += (k - sum / n) * (k - sum / n);
        result.standardError_n_per_m = std::sqrt(squares / (n - 1.0) / n);
    }
    return result;
}

}  // namespace tactiscope::core::compliance
