// ScenarioCatalog: the table of simulator scenarios.
#include "devices/simulator/ScenarioCatalog.h"

#include "devices/simulator/CapacitiveWeightsScenario.h"
#include "devices/simulator/GaugeCalibrationScenario.h"
#include "devices/simulator/LoadCellScenario.h"
#include "devices/simulator/PalpationScenario.h"
#include "devices/simulator/PanelScanScenario.h"

namespace tactiscope::devices::simulator {

std::vector<std::string> scenarioIds()
{
    return {kPanelScanScenario,          kPanelLineScenario,  kPanelRestScenario,       kPalpationScenario,
            "capacitive-weights",        "gauge-calibration", "gauge-calibration-soft", "capacitive-calibration",
            kCapacitiveOverloadScenario, kLoadCellScenario};
}

std::unique_ptr<SimulatedScenario> makeScenario(std::string_view id, std::uint64_t seed, std::optional<double> rate_hz)
{
    if (id == kPanelScanScenario || id == kPanelLineScenario || id == kPanelRestScenario) {
        PanelScanParameters parameters;
        parameters.seed = seed;
        if (id == kPanelLineScenario) {
            parameters.restBetweenPanels_s = kPanelLineRest_s;
            parameters.positionChannel = true;  // a line's encoder
        }
        if (id == kPanelRestScenario) parameters.strokeAmplitude_m = 0.0;
        if (rate_hz) parameters.sampleRate_hz = *rate_hz;
        return std::make_unique<PanelScanScenario>(parameters);
    }
    if (id == kPalpationScenario) {
        PalpationParameters parameters;
        parameters.seed = seed;
        if (rate_hz) parameters.sampleRate_hz = *rate_hz;
        return std::make_unique<PalpationScenario>(parameters);
    }
    if (id == "capacitive-weights" || id == "capacitive-calibration" || id == kCapacitiveOverloadScenario) {
        CapacitiveWeightsParameters parameters;
        parameters.seed = seed;
        if (id == kCapacitiveOverloadScenario) {
            parameters.baseline_s = 2.0;
            parameters.dwell_s = 0.5;
            parameters.name = "overloaded capacitive beam";
        }
        if (rate_hz) parameters.sampleRate_hz = *rate_hz;
        if (id == "capacitive-calibration") parameters.protocol = WeightProtocol::Manual;
        return std::make_unique<CapacitiveWeightsScenario>(parameters);
    }
    if (id == "gauge-calibration" || id == "gauge-calibration-soft") {
        GaugeCalibrationParameters parameters;
        parameters.seed = seed;
        parameters.softBeam = id == "gauge-calibration-soft";
        if (rate_hz) parameters.sampleRate_hz = *rate_hz;
        return std::make_unique<GaugeCalibrationScenario>(parameters);
    }
    if (id == kLoadCellScenario) {
        LoadCellParameters parameters;
        parameters.seed = seed;
        if (rate_hz) parameters.sampleRate_hz = *rate_hz;
        return std::make_unique<LoadCellScenario>(parameters);
    }
    return nullptr;
}

}  // namespace tactiscope::devices::simulator
