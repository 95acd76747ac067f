// Simulated C0 and sensitivity calibration of the capacitive beam (seed 002):
// one capacitance channel (10 Hz, like the paper's PCap01 kit) while weights
// are placed on and taken off the free end.
//
// The response to a weight settles with a first-order lag (the soft beam
// swinging to rest) and creeps slightly further (viscoelastic silicone),
// which also leaves a little hysteresis between loading and unloading. The
// baseline drifts linearly and wanders (random walk), and every sample has
// white noise. Protocols: cumulative (weights stacked up in steps, then
// taken off again, the paper's procedure), individual (each weight placed
// and removed on its own, so the baseline reappears between weights) or
// manual (a calibration wizard places and removes weights through the
// scenario's LoadRig, when it wants, for as long as it wants).
#pragma once

#include "core/sensors/CapacitiveBeam.h"
#include "devices/simulator/GaussianNoise.h"
#include "devices/simulator/SimulatedScenario.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tactiscope::devices::simulator {

enum class WeightProtocol { Cumulative, Individual, Manual };

struct CapacitiveWeightsParameters {
    double sampleRate_hz = 10.0;
    core::sensors::CapacitiveBeamGeometry geometry = paperSensorNo1();
    WeightProtocol protocol = WeightProtocol::Cumulative;
    std::string name;  // what the link says it is; empty: by its protocol
    std::vector<double> weights_mgf{10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120, 130, 140, 150};
    double baseline_s = 10.0;  // unloaded at the start and the end
    double dwell_s = 8.0;      // per step: time for the wizard's rule (a stable window, then a fresh one)
    double settleTime_s = 0.4;
    double creepFraction = 0.01;
    double creepTime_s = 4.0;
    double drift_f_per_s = 0.5e-15;  // 0.0005 pF/s
    double wander_f_per_sqrt_s = 0.2e-15;
    double noise_f = 4e-15;  // 0.004 pF
    std::uint64_t seed = 1;

    // The paper's sensor No. 1 with a 15 µm Eco-flex dielectric.
    static core::sensors::CapacitiveBeamGeometry paperSensorNo1();
};

// One step of the protocol, as a calibration wizard would follow it.
struct WeightStep {
    double start_s = 0.0;
    double end_s = 0.0;
    double force_n = 0.0;  // total load during the step
    bool loading = true;   // placing (or holding) rather than removing weight
};

class CapacitiveWeightsScenario final : public SimulatedScenario {
public:
    // Throws std::invalid_argument for non-physical parameters.
    explicit CapacitiveWeightsScenario(const CapacitiveWeightsParameters& parameters = {});

    // The rig a wizard drives is named as the source list names it.
    std::string name() const override
    {
        if (!m_p.name.empty()) return m_p.name;
        return m_p.protocol == WeightProtocol::Manual ? "capacitive calibration rig" : "capacitive weights";
    }
    std::optional<core::Mode> mode() const override { return core::Mode::Capacitive; }
    const std::vector<core::ChannelDescriptor>& channels() const override { return m_channels; }
    double sampleRate_hz() const override { return m_p.sampleRate_hz; }
    void generate(core::SampleBlock& block) override;

    const CapacitiveWeightsParameters& parameters() const { return m_p; }
    const core::sensors::CapacitiveBeam& beam() const { return m_beam; }
    // The loaded steps after the first baseline, and the whole length.
    // Empty for the manual protocol, which has no script.
    const std::vector<WeightStep>& schedule() const { return m_schedule; }
    double duration_s() const { return m_duration_s; }
    double loadAt_n(double t_s) const;
    std::shared_ptr<LoadRig> loadRig() const override { return m_rig; }
    std::optional<double> appliedLoad_n(double t_s) const override { return loadAt_n(t_s); }

private:
    CapacitiveWeightsParameters m_p;
    std::vector<core::ChannelDescriptor> m_channels;
    core::sensors::CapacitiveBeam m_beam;
    std::vector<WeightStep> m_schedule;
    std::shared_ptr<LoadRig> m_rig;  // manual protocol only
    double m_duration_s = 0.0;
    GaussianNoise m_noise;
    GaussianNoise m_wanderSteps;
    std::uint64_t m_nextSample = 0;
    double m_settled_n = 0.0;  // load the beam has settled to
    double m_creep_n = 0.0;    // extra, viscoelastic part
    double m_wander_f = 0.0;
};

}  // namespace tactiscope::devices::simulator
