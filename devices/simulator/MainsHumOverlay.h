// Mains hum added to a simulated probe's measuring channels, as a strain
// bridge on a press line picks it up: a common part, the same on every
// gauge (the cable's pick-up), and a differential part of opposite sign on
// alternate channels (each bridge's own loop), each at the mains frequency
// with its 3rd harmonic. The hum of a channel c at time t is
// (common + s_c·differential)·(sin φ + h₃·sin 3φ), φ = 2π·f·t + φ₀,
// s_c = +1, −1, +1, …, in each channel's stored unit (strain for gauges).
// Positions and a probe's decisions carry none.
#pragma once

#include "devices/simulator/SimulatedScenario.h"

#include <cstdint>
#include <memory>

namespace tactiscope::devices::simulator {

struct MainsHumSettings {
    double mains_hz = 50.0;
    double common = 0.0;
    double differential = 0.0;
    double thirdHarmonic = 0.3;  // of the fundamental's amplitude
    double phase_rad = 0.4;

    bool any() const { return common != 0.0 || differential != 0.0; }
};

// `inner` with the hum added; its name, mode, channels and rate unchanged.
class HummedScenario final : public SimulatedScenario {
public:
    HummedScenario(std::unique_ptr<SimulatedScenario> inner, const MainsHumSettings& hum);

    std::string name() const override { return m_inner->name(); }
    std::optional<core::Mode> mode() const override { return m_inner->mode(); }
    const std::vector<core::ChannelDescriptor>& channels() const override { return m_inner->channels(); }
    double sampleRate_hz() const override { return m_inner->sampleRate_hz(); }
    void generate(core::SampleBlock& block) override;
    std::shared_ptr<LoadRig> loadRig() const override { return m_inner->loadRig(); }
    std::optional<double> appliedLoad_n(double t_s) const override { return m_inner->appliedLoad_n(t_s); }

private:
    std::unique_ptr<SimulatedScenario> m_inner;
    MainsHumSettings m_hum;
    std::uint64_t m_produced = 0;
};

}  // namespace tactiscope::devices::simulator
