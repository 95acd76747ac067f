// A fourth mode added by this file alone, as a sensor type would add
// itself (docs/conventions.md, "A new mode"): one definition registered —
// its word, title, roles, no zero, and its review lanes and export columns.
// Nothing else is edited, and the generic code serves it: the mode's word
// parses and is offered, a device whose channels play its roles feeds it
// and one that does not is refused with the roles' sentence, and a stored
// session read as this mode shows its derived lane, computed from the
// stored samples. (Recording it into a store would also need its word in
// the store's CHECK list, by a migration: the store keeps only words it
// knows.)
#include "core/ModeCapability.h"
#include "core/SampleBlock.h"
#include "core/derived/ModeLanes.h"
#include "core/derived/SessionLanes.h"
#include "core/modes/ChannelRoles.h"
#include "core/modes/ModeDefinition.h"
#include "core/storage/SessionStore.h"

#include "support/TempDirectory.h"

#include <gtest/gtest.h>

#include <array>

using namespace tactiscope::core;

namespace {

using ModeRegistryTest = tactiscope::testing::TempDirectoryTest;

constexpr auto kDifferenceMode = static_cast<Mode>(40);
constexpr std::array kRoles{ChannelRole::CantileverA, ChannelRole::CantileverB};

// A − B of the two cantilevers, as the mode's one derived column.
class Difference final : public storage::ComputedColumns {
public:
    Difference(storage::SessionSource& store, std::int64_t session)
        : m_store(store),
          m_session(session)
    {
        std::vector<ChannelDescriptor> channels;
        for (const auto& stored : store.channels(session)) channels.push_back(stored.descriptor);
        const auto picked = modeChannels(kDifferenceMode, channels);
        if (!picked) throw std::invalid_argument(*modeRefusal(kDifferenceMode, channels));
        m_a = (*picked)[0];
        m_b = (*picked)[1];
    }
    std::vector<ChannelDescriptor> channels() const override { return {{"a − b", "", ChannelKind::Strain}}; }
    std::string basis() const override { return "the difference of the cantilevers"; }
    std::vector<std::vector<double>> read(std::uint64_t first, std::uint64_t count) override
    {
        auto a = m_store.readChannel(m_session, m_a, first, count);
        const auto b = m_store.readChannel(m_session, m_b, first, count);
        for (std::size_t i = 0; i < a.size(); ++i) a[i] -= b[i];
        return {a};
    }

private:
    storage::SessionSource& m_store;
    std::int64_t m_session;
    std::size_t m_a = 0, m_b = 0;
};

class DifferenceLane final : public storage::LaneSource {
public:
    DifferenceLane(storage::SessionSource& store, std::int64_t session)
        : m_columns(store, session)
    {
    }
    ChannelDescriptor descriptor() const override { return m_columns.channels().front(); }
    std::vector<double> exact(std::uint64_t first, std::uint64_t count) override
    {
        return m_columns.read(first, count).front();
    }
    std::vector<storage::OverviewPoint> overview(std::uint64_t, std::uint64_t, std::size_t) override { return {}; }

private:
    Difference m_columns;
};

const ModeDefinition& differenceMode()
{
    static const ModeDefinition definition{
        .mode = kDifferenceMode,
        .name = "strain-difference",
        .title = "Strain difference",
        .needs = "two strain cantilevers",
        .roles = kRoles,
        .noZero = "the difference needs no zero",
        .lanes =
            [](storage::SessionSource& store, const storage::SessionSummary& session, const derived::LaneOptions&) {
                derived::ModeLanes lanes;
                lanes.after.push_back(std::make_unique<DifferenceLane>(store, session.id));
                lanes.basis = "the difference of the cantilevers";
                return lanes;
            },
        .computedColumns = [](storage::SessionSource& store, std::int64_t session)
            -> std::unique_ptr<storage::ComputedColumns> { return std::make_unique<Difference>(store, session); },
    };
    return definition;
}

// The mode for one test: the registry is the process's.
class Registered {
public:
    Registered() { registerMode(differenceMode()); }
    ~Registered() { unregisterMode(kDifferenceMode); }
    Registered(const Registered&) = delete;
    Registered& operator=(const Registered&) = delete;
};

}  // namespace

TEST_F(ModeRegistryTest, AModeRegisteredAloneIsParsedOfferedAndRunsOnTheChannelsThatPlayItsRoles)
{
    const Registered registered;
    EXPECT_EQ(modeFromString("strain-difference"), kDifferenceMode);
    EXPECT_EQ(toString(kDifferenceMode), "strain-difference");
    EXPECT_EQ(modeChoices(), "panel-scan, palpation, capacitive, general or strain-difference");
    EXPECT_EQ(modeDefinitions().back().title, "Strain difference");

    const std::vector<ChannelDescriptor> scanProbe{{"a", "", ChannelKind::Strain}, {"b", "", ChannelKind::Strain}};
    EXPECT_EQ(runnableModes(scanProbe), (std::vector{Mode::PanelScan, Mode::General, kDifferenceMode}));
    const std::vector<ChannelDescriptor> board{{"x", "", ChannelKind::Other}, {"y", "", ChannelKind::Other}};
    EXPECT_EQ(runnableModes(board), std::vector{Mode::General});
    EXPECT_EQ(*modeRefusal(kDifferenceMode, board),
              "strain-difference needs two strain cantilevers: no channel plays cantilever-a, cantilever-b; this "
              "device has x (other), y (other).");
    // Given roles, plain numbers are still no strains; strains are.
    EXPECT_FALSE(
        modeChannels(kDifferenceMode, applyRoles(board, parseRoleAssignment("y=cantilever-a,x=cantilever-b"))));
    const std::vector<ChannelDescriptor> strains{{"x", "", ChannelKind::Strain}, {"y", "", ChannelKind::Strain}};
    EXPECT_EQ(modeChannels(kDifferenceMode, applyRoles(strains, parseRoleAssignment("y=cantilever-a,x=cantilever-b"))),
              (std::vector<std::size_t>{1, 0}));
    // A word or value taken is refused.
    EXPECT_THROW(registerMode(differenceMode()), std::invalid_argument);
    ModeDefinition sameWord = differenceMode();
    sameWord.mode = static_cast<Mode>(41);
    sameWord.name = "palpation";
    EXPECT_THROW(registerMode(sameWord), std::invalid_argument);
}

TEST_F(ModeRegistryTest, TheReviewAndTheExportAskTheDefinitionForTheModesQuantities)
{
    const Registered registered;
    storage::SessionStore store(file("d.tactiscope"));
    storage::SessionMetadata metadata;
    metadata.mode = Mode::General;
    const std::vector<ChannelDescriptor> channels{{"a", "", ChannelKind::Strain}, {"b", "", ChannelKind::Strain}};
    const auto id = store.beginSession(metadata, channels, 100.0);
    SampleBlock block(2, 50, 0.0, 0.01, 0);
    for (std::size_t s = 0; s < 50; ++s) {
        block.channel(0)[s] = 1e-6 * static_cast<double>(s);
        block.channel(1)[s] = 0.25e-6 * static_cast<double>(s * s % 7);
    }
    store.appendBlocks(id, std::vector{block});
    store.endSession(id, SessionStatus::Complete);

    // The stored session read as the new mode: its lane after the strains.
    auto session = *store.session(id);
    session.metadata.mode = kDifferenceMode;
    auto lanes = derived::sessionLanes(store, session);
    EXPECT_TRUE(lanes.derived);
    EXPECT_EQ(lanes.basis, "the difference of the cantilevers");
    ASSERT_EQ(lanes.lanes.size(), 3u);
    EXPECT_EQ(lanes.lanes[2]->descriptor().name, "a − b");
    const auto a = store.readChannel(id, 0, 0, 50), b = store.readChannel(id, 1, 0, 50);
    const auto difference = lanes.lanes[2]->exact(0, 50);
    ASSERT_EQ(difference.size(), 50u);
    for (std::size_t s = 0; s < 50; ++s) EXPECT_EQ(difference[s], a[s] - b[s]) << s;
    EXPECT_EQ(derived::computedColumns(store, session)->channels().front().name, "a − b");
    // Read as the general mode, the same session has no derived quantities.
    session.metadata.mode = Mode::General;
    EXPECT_FALSE(derived::sessionLanes(store, session).derived);
    EXPECT_THROW(derived::computedColumns(store, session), std::invalid_argument);
}
