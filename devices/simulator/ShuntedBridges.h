// The strain-gauge bridges behind a simulated probe's strain channels, each
// with a shunt resistor it can switch across its first active gauge (TSP/1
// command 6; the emulator and the built-in simulator alike). The step a
// shunt makes is the bridge's own response: the Wheatstone bridge solved
// from its four resistances,
//   V_out/V_ex = R₁/(R₁ + R₂) − R₄/(R₃ + R₄),  R₁ = R_g·R_s/(R_g + R_s) when shunted,
// read back to strain the way a probe's firmware does for its bridge type
// with the gauge factor it is set to:
//   quarter  ε = 4·V_r / (GF·(1 − 2·V_r))
//   half     ε = 2·V_r / GF          (bending: two arms, ±ε)
//   full     ε = V_r / GF            (bending: four arms)
// (core/straingauge/ShuntCalibration.h says what a check expects of it.)
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/SampleBlock.h"
#include "core/straingauge/StrainGaugeChain.h"

#include <optional>
#include <string>
#include <vector>

namespace tactiscope::devices::simulator {

// A simulated probe's bridges: the paper prototypes' 350 Ω gauges in
// quarter bridges, a 100 kΩ shunt, the probe set to GF 2.
struct ProbeBridge {
    core::straingauge::BridgeType type = core::straingauge::BridgeType::Quarter;
    double gauge_ohm = 350.0;
    double shunt_ohm = 100e3;
    double gaugeFactor = 2.0;  // what the probe's firmware converts with
};

// The strain a channel of `bridge` reads with its shunt on, from the bridge
// solved from its resistances.
double shuntedReading(const ProbeBridge& bridge);

class ShuntedBridges {
public:
    explicit ShuntedBridges(std::vector<core::ChannelDescriptor> channels, ProbeBridge bridge = {});

    // Switches channel `channel`'s shunt; none when done, else why not
    // (no such channel, or it is no strain channel: no bridge behind it).
    std::optional<std::string> set(std::size_t channel, bool on);
    // Adds each shunted channel's step to the block's samples.
    void apply(core::SampleBlock& block) const;

private:
    std::vector<core::ChannelDescriptor> m_channels;
    std::vector<bool> m_on;
    double m_step;
};

}  // namespace tactiscope::devices::simulator
