// Simulated palpation (seed 001): a hand presses the two-beam compliance
// probe onto a specimen of stiffness k_o, again and again, to a sequence of
// depths. Channels: the raw ADC counts of the high- and low-stiffness beams'
// half bridges, and the probe's displacement into the specimen (the paper's
// displacement gauge), so the whole chain from counts to k_o is exercised.
//
// Physics: both beams see the same displacement X into the specimen; each
// side is its beam in series with the object, F = X·k·k_o/(k + k_o), and the
// root strain is F·6L/(E·w·t²). The hand is not a machine: each press has
// its own in, hold and out durations, the speed varies within a ramp, and a
// physiological tremor (8–12 Hz, tens of µm) rides on top. Electrical noise,
// bridge offsets and ADC quantisation come last.
#pragma once

#include "core/sensors/CantileverBeam.h"
#include "core/straingauge/StrainGaugeChain.h"
#include "devices/simulator/GaussianNoise.h"
#include "devices/simulator/SimulatedProbe.h"
#include "devices/simulator/SimulatedScenario.h"

#include <cstdint>
#include <random>
#include <vector>

namespace tactiscope::devices::simulator {

struct PalpationParameters {
    double sampleRate_hz = 1000.0;
    // The paper's probe: Perspex, 10 mm wide, 50 mm long, 3 mm and 1 mm
    // thick, the one the gauge rig calibrates (SimulatedProbe.h).
    core::sensors::CantileverGeometry high = kProbeStiffBeam;
    core::sensors::CantileverGeometry low = kProbeSoftBeam;
    double objectStiffness_n_per_m = 117.0;
    std::vector<double> pressDepths_m{0.002, 0.004, 0.006, 0.008};  // cycled
    double pause_s = 1.0;                                           // probe lifted between presses
    double tremorAmplitude_m = 30e-6;
    double displacementNoise_m = 5e-6;  // displacement gauge
    double electricalNoise_v = 1e-3;    // at the ADC input
    core::straingauge::AdcSettings adc;
    core::straingauge::BridgeSettings bridge;        // as the device is configured: the nominal gauge factor
    double trueGaugeFactor = kProbeTrueGaugeFactor;  // of both beams' gauges
    double zeroOffsetHigh_counts = 120.0;            // unbalanced bridges
    double zeroOffsetLow_counts = -85.0;
    std::uint64_t seed = 1;
};

class PalpationScenario final : public SimulatedScenario {
public:
    // Throws std::invalid_argument for non-physical parameters.
    explicit PalpationScenario(const PalpationParameters& parameters = {});

    std::string name() const override { return "palpation"; }
    std::optional<core::Mode> mode() const override { return core::Mode::Palpation; }
    const std::vector<core::ChannelDescriptor>& channels() const override { return m_channels; }
    double sampleRate_hz() const override { return m_p.sampleRate_hz; }
    void generate(core::SampleBlock& block) override;

    const PalpationParameters& parameters() const { return m_p; }
    // The chain as the device is configured (nominal gauge factor, without
    // tare): what an uncalibrated reader converts the counts with.
    core::straingauge::StrainGaugeChain chain() const { return {m_p.adc, m_p.bridge}; }

private:
    struct Press {
        double start_s, in_s, hold_s, out_s, depth_m, tremorFrequency_hz, tremorPhase;
    };
    void planNextPress();
    double displacement_m(double t_s);
    double toCounts(double strain, double zeroOffset, GaussianNoise& noise) const;

    PalpationParameters m_p;
    std::vector<core::ChannelDescriptor> m_channels;
    core::sensors::CantileverBeam m_high;
    core::sensors::CantileverBeam m_low;
    core::straingauge::StrainGaugeChain m_chain;
    std::mt19937_64 m_random;
    GaussianNoise m_noiseHigh;
    GaussianNoise m_noiseLow;
    GaussianNoise m_noiseDisplacement;
    Press m_press{};
    std::size_t m_pressCount = 0;
    std::uint64_t m_nextSample = 0;
};

}  // namespace tactiscope::devices::simulator
