// SessionLanes: derived lanes where the mode has them, stored ones after.
#include "core/derived/SessionLanes.h"

#include "core/derived/CapacitiveChannels.h"
#include "core/derived/PalpationChannels.h"
#include "core/derived/PanelScanChannels.h"

#include <algorithm>
#include <stdexcept>

namespace tactiscope::core::derived {
namespace {

// One derived channel of a session; the lanes share the computation.
template <typename Channels>
class DerivedLane final : public storage::LaneSource {
public:
    DerivedLane(std::shared_ptr<Channels> channels, std::size_t index, std::optional<double> threshold = {})
        : m_channels(std::move(channels)),
          m_index(index),
          m_threshold(threshold)
    {
    }
    ChannelDescriptor descriptor() const override { return m_channels->channels()[m_index]; }
    std::vector<double> exact(std::uint64_t first, std::uint64_t count) override
    {
        return std::move(m_channels->read(first, count)[m_index]);
    }
    std::vector<storage::OverviewPoint> overview(std::uint64_t first, std::uint64_t count, std::size_t points) override
    {
        return m_channels->overview(m_index, first, count, points);
    }
    std::optional<double> threshold() const override { return m_threshold; }

private:
    std::shared_ptr<Channels> m_channels;
    std::size_t m_index;
    std::optional<double> m_threshold;
};

}  // namespace

SessionLanes sessionLanes(storage::SessionSource& store, const storage::SessionSummary& session,
                          const LaneOptions& options)
{
    const bool raw = options.raw;
    SessionLanes result;
    const auto channels = store.channels(session.id);
    std::vector<std::size_t> stored(channels.size());
    for (std::size_t c = 0; c < channels.size(); ++c) stored[c] = c;
    if (!raw && session.metadata.mode == Mode::Palpation) {
        try {
            auto palpation = std::make_shared<PalpationChannels>(store, session.id);
            for (std::size_t d = 0; d < palpation->channels().size(); ++d)
                result.lanes.push_back(std::make_unique<DerivedLane<PalpationChannels>>(palpation, d));
            std::erase_if(stored,
                          [&](std::size_t c) { return c == palpation->highChannel() || c == palpation->lowChannel(); });
            result.basis = palpation->basis();
            result.derived = true;
        } catch (const std::invalid_argument& e) {
            result.problem = e.what();
        }
    }
    if (!raw && session.metadata.mode == Mode::Capacitive) {
        try {
            auto capacitive = std::make_shared<CapacitiveChannels>(store, session.id, options.capacitiveCalibration);
            // The capacitance as stored, then ΔC, the force and the deflection.
            const std::size_t c = capacitive->capacitanceChannel();
            result.lanes.push_back(std::make_unique<storage::StoredLane>(store, session.id, c, channels[c].descriptor));
            for (const std::size_t d : {std::size_t{0}, std::size_t{2}, std::size_t{3}})
                result.lanes.push_back(std::make_unique<DerivedLane<CapacitiveChannels>>(capacitive, d));
            std::erase(stored, c);
            result.basis = capacitive->basis();
            result.derived = true;
        } catch (const std::invalid_argument& e) {
            result.problem = e.what();
        }
    }
    for (const std::size_t c : stored)
        result.lanes.push_back(std::make_unique<storage::StoredLane>(store, session.id, c, channels[c].descriptor));
    if (!raw && session.metadata.mode == Mode::PanelScan) {
        // The strains as stored (shown in µε), then what the detector made of them.
        try {
            auto detector = std::make_shared<PanelScanChannels>(store, session.id);
            result.lanes.push_back(
                std::make_unique<DerivedLane<PanelScanChannels>>(detector, 0, detector->parameters().threshold));
            result.lanes.push_back(std::make_unique<DerivedLane<PanelScanChannels>>(detector, 1));
            result.basis = detector->basis();
            result.derived = true;
        } catch (const std::invalid_argument& e) {
            result.problem = e.what();
        }
    }
    return result;
}

std::unique_ptr<storage::ComputedColumns> computedColumns(storage::SessionSource& store,
                                                          const storage::SessionSummary& session)
{
    switch (session.metadata.mode) {
    case Mode::Palpation:
        return std::make_unique<PalpationChannels>(store, session.id);
    case Mode::Capacitive:
        return std::make_unique<CapacitiveChannels>(store, session.id);
    case Mode::PanelScan:
        return std::make_unique<PanelScanChannels>(store, session.id);
    case Mode::General:
        break;
    }
    throw std::invalid_argument("session " + std::to_string(session.id) + " is a " +
                                std::string(toString(session.metadata.mode)) +
                                " recording: its channels are stored as they came, with no derived quantities");
}

}  // namespace tactiscope::core::derived
