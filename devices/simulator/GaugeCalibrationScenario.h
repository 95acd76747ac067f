// Simulated gauge-factor calibration rig: one beam of the simulated
// compliance probe (SimulatedProbe.h: the stiff one, or the soft one)
// clamped at its root, with masses hung on its tip through a LoadRig. One
// channel, the bridge ADC in counts, named as the probe names that beam's.
//
// The gauge on the beam is not the datasheet's: its true gauge factor
// (bonding, lead resistance, the gauge's own tolerance) differs from the
// nominal one the chain is configured with, which is exactly what the
// wizard must find. Physics: a tip force F strains the root by
// ε = F·6L/(E·w·t²); the bridge turns GF_true·ε into volts; the beam swings
// to rest with a first-order lag after a load changes. Electrical noise at
// the ADC input and quantisation come last, over an unbalanced bridge's
// zero offset.
#pragma once

#include "core/sensors/CantileverBeam.h"
#include "core/straingauge/StrainGaugeChain.h"
#include "devices/simulator/GaussianNoise.h"
#include "devices/simulator/SimulatedProbe.h"
#include "devices/simulator/SimulatedScenario.h"

#include <cstdint>

namespace tactiscope::devices::simulator {

struct GaugeCalibrationParameters {
    double sampleRate_hz = 500.0;
    bool softBeam = false;  // which of the probe's beams is clamped
    core::sensors::CantileverGeometry beam = kProbeStiffBeam;
    core::straingauge::AdcSettings adc;              // as the device is configured
    core::straingauge::BridgeSettings bridge;        // its gaugeFactor is the nominal one
    double trueGaugeFactor = kProbeTrueGaugeFactor;  // 7 % above the nominal 2.0
    double zeroOffset_counts = 120.0;
    double settleTime_s = 0.15;
    double electricalNoise_v = 1e-3;  // at the ADC input
    std::uint64_t seed = 1;
};

class GaugeCalibrationScenario final : public SimulatedScenario {
public:
    // Throws std::invalid_argument for non-physical parameters.
    explicit GaugeCalibrationScenario(const GaugeCalibrationParameters& parameters = {});

    std::string name() const override
    {
        return m_p.softBeam ? "gauge-factor calibration rig (soft beam)" : "gauge-factor calibration rig";
    }
    std::optional<core::Mode> mode() const override { return std::nullopt; }
    const std::vector<core::ChannelDescriptor>& channels() const override { return m_channels; }
    double sampleRate_hz() const override { return m_p.sampleRate_hz; }
    void generate(core::SampleBlock& block) override;
    std::shared_ptr<LoadRig> loadRig() const override { return m_rig; }

    const GaugeCalibrationParameters& parameters() const { return m_p; }

private:
    GaugeCalibrationParameters m_p;
    std::vector<core::ChannelDescriptor> m_channels;
    core::sensors::CantileverBeam m_beam;
    core::straingauge::StrainGaugeChain m_trueChain;  // the chain with the gauge's real factor
    std::shared_ptr<LoadRig> m_rig = std::make_shared<LoadRig>();
    GaussianNoise m_noise;
    double m_settled_n = 0.0;  // the load the beam has swung to so far
};

}  // namespace tactiscope::devices::simulator
