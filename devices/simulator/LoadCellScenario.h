// A reference load cell (issue 40): one force channel in newtons, read from
// the rig's load (LoadRig) with a zero offset of its own and white noise,
// as a µN-class cell in series with a capacitive beam reads the force a
// calibration rig applies. Stiff beside the beam: it follows the load at
// once. Its zero offset is what a calibration must take off itself.
#pragma once

#include "devices/simulator/GaussianNoise.h"
#include "devices/simulator/SimulatedScenario.h"

#include <cstdint>

namespace tactiscope::devices::simulator {

inline const std::string kLoadCellScenario{"load-cell"};

struct LoadCellParameters {
    double sampleRate_hz = 1000.0;
    double zero_n = 20e-6;    // its reading with nothing on it
    double noise_n = 0.3e-6;  // σ per sample
    std::uint64_t seed = 1;
};

class LoadCellScenario final : public SimulatedScenario {
public:
    // Throws std::invalid_argument for a non-positive rate or a negative noise.
    explicit LoadCellScenario(const LoadCellParameters& parameters = {});

    std::string name() const override { return "reference load cell"; }
    std::optional<core::Mode> mode() const override { return std::nullopt; }
    const std::vector<core::ChannelDescriptor>& channels() const override { return m_channels; }
    double sampleRate_hz() const override { return m_p.sampleRate_hz; }
    void generate(core::SampleBlock& block) override;
    std::shared_ptr<LoadRig> loadRig() const override { return m_rig; }

private:
    LoadCellParameters m_p;
    std::vector<core::ChannelDescriptor> m_channels;
    std::shared_ptr<LoadRig> m_rig = std::make_shared<LoadRig>();
    GaussianNoise m_noise;
};

}  // namespace tactiscope::devices::simulator
