// A simulated scenario is the physics behind the built-in simulator: it
// produces consecutive samples of a fixed set of channels at a fixed rate.
// Scenarios are deterministic for a given seed, so tests and demos repeat.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/Vocabulary.h"
#include "devices/simulator/LoadRig.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tactiscope::core {
class SampleBlock;
}

namespace tactiscope::devices::simulator {

class SimulatedScenario {
public:
    virtual ~SimulatedScenario() = default;

    virtual std::string name() const = 0;
    // The mode whose probe this scenario simulates; none for a calibration
    // rig that only a wizard reads.
    virtual std::optional<core::Mode> mode() const = 0;
    virtual const std::vector<core::ChannelDescriptor>& channels() const = 0;
    virtual double sampleRate_hz() const = 0;

    // Fills every sample of `block` with the next samples of the scenario;
    // the block's shape (channels, samples) is set by the caller.
    virtual void generate(core::SampleBlock& block) = 0;

    // The rig a calibration wizard places loads with; null for scenarios that
    // follow their own script.
    virtual std::shared_ptr<LoadRig> loadRig() const { return nullptr; }

    // The load the script applies at t_s, in N, for a scenario that places
    // loads (a calibration's weights): what a researcher logs beside the
    // recording. None for the others.
    virtual std::optional<double> appliedLoad_n(double /*t_s*/) const { return std::nullopt; }
};

}  // namespace tactiscope::devices::simulator
