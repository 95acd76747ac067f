// A simulator scenario re-announced as a device that says nothing of its
// channels (a maker's board printing numbers): the same samples, other
// names, kind `other`, no mode, and an identity of the test's choosing.
#pragma once

#include "devices/BlockSource.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/simulator/SimulatorSource.h"

#include <memory>
#include <string>
#include <vector>

namespace tactiscope::testing {

class RelabelledSource final : public devices::BlockSource {
public:
    // `names`, one per channel of the scenario; sped up `speed` times.
    RelabelledSource(const std::string& scenario, const std::vector<std::string>& names, double speed = 10.0,
                     devices::DeviceIdentity identity = {"maker board", {}, {}})
        : m_identity(std::move(identity))
    {
        devices::simulator::SimulatorOptions options;
        options.speed = speed;
        m_inner =
            std::make_unique<devices::simulator::SimulatorSource>(devices::simulator::makeScenario(scenario), options);
        for (const auto& name : names) m_channels.push_back({name, "", core::ChannelKind::Other});
    }
    std::string name() const override { return m_identity.model; }
    devices::DeviceIdentity identity() const override { return m_identity; }
    const std::vector<core::ChannelDescriptor>& channels() const override { return m_channels; }
    double nominalSampleRate_hz() const override { return m_inner->nominalSampleRate_hz(); }
    devices::ReadStatus readBlock(core::SampleBlock& out, std::chrono::milliseconds timeout) override
    {
        return m_inner->readBlock(out, timeout);
    }

private:
    std::unique_ptr<devices::BlockSource> m_inner;
    std::vector<core::ChannelDescriptor> m_channels;
    devices::DeviceIdentity m_identity;
};

}  // namespace tactiscope::testing
