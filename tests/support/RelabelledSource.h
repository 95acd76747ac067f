// A simulator scenario re-announced as a maker's board printing numbers:
// the same samples, other names, no mode, and an identity of the test's
// choosing. A name may carry the unit the board labels it with ("d[m]",
// "a[strain]": the values are the scenario's, in SI); without one the
// channel is a plain number, as a board that says nothing of it.
#pragma once

#include "core/UnitScale.h"
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
        for (const auto& name : names) {
            const auto bracket = name.find('[');
            core::ChannelDescriptor channel{name.substr(0, bracket), "", core::ChannelKind::Other};
            if (bracket != std::string::npos)
                core::giveUnit(channel, name.substr(bracket + 1, name.size() - bracket - 2));
            m_channels.push_back(std::move(channel));
        }
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
