// What the live views show is the live session's lists, on one clock, and
// they agree with the record: each of the faults an operator met is
// reproduced on the simulator (sped up) and checked against the store —
// the defect list after a stop, a panel line's sites placed by its
// encoder, the press times while recording, the grid map's site at the
// record press, a profile chosen while pressing, a stream met in a press
// held still; and a device that declares nothing records in the general
// mode, or, given roles, as a panel scan.
#include "core/ModeCapability.h"
#include "core/compliance/LivePalpation.h"
#include "core/sensors/BuiltInProfiles.h"
#include "core/storage/DefectRecords.h"
#include "core/storage/SessionStore.h"
#include "core/storage/StoredSites.h"
#include "devices/session/LiveSession.h"
#include "devices/session/modes/PalpationUnit.h"
#include "devices/session/modes/PanelScanUnit.h"
#include "devices/simulator/PalpationScenario.h"
#include "devices/simulator/PanelScanScenario.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/simulator/SimulatorSource.h"

#include "support/BridgeArithmetic.h"
#include "support/LiveUnit.h"
#include "support/RelabelledSource.h"
#include "support/TempDirectory.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <thread>

using namespace tactiscope;
using devices::session::LiveClock;
using devices::session::LiveSession;
using tactiscope::devices::session::PalpationUnit;
using tactiscope::devices::session::PanelScanUnit;
using tactiscope::testing::liveUnit;
using tactiscope::testing::RelabelledSource;

namespace {

using LiveListsTest = tactiscope::testing::TempDirectoryTest;

// Simulated seconds per wall-clock second: a minute of scanning in six.
constexpr double kSpeed = 10.0;

std::unique_ptr<devices::BlockSource> simulator(const char* scenario)
{
    devices::simulator::SimulatorOptions options;
    options.speed = kSpeed;
    return std::make_unique<devices::simulator::SimulatorSource>(devices::simulator::makeScenario(scenario), options);
}

// Polls the session until `done` or 20 wall-clock seconds.
bool pollUntil(LiveSession& session, const std::function<bool()>& done)
{
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (std::chrono::steady_clock::now() < deadline) {
        session.poll();
        if (done()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
}

devices::session::LiveSessionOptions optionsFor(const std::string& store)
{
    devices::session::LiveSessionOptions options;
    options.storePath = store;
    return options;
}

std::size_t storedCount(const std::vector<devices::session::PressRecord>& presses)
{
    std::size_t n = 0;
    for (const auto& press : presses) n += press.stored ? 1 : 0;
    return n;
}

}  // namespace

TEST_F(LiveListsTest, AfterTheStopTheDefectListIsExactlyWhatWasStoredThenANewListStarts)
{
    LiveSession session(simulator("panel-scan"), optionsFor(file("s.tactiscope")));
    session.start();
    // Defects before the record press: since connect, not recorded.
    ASSERT_TRUE(pollUntil(session, [&] { return liveUnit<PanelScanUnit>(session).defects().size() >= 2; }));
    EXPECT_EQ(session.lists().clock, LiveClock::SinceConnect);
    const auto unrecorded = session.lists().generation;

    ASSERT_FALSE(session.startRecording({}));
    EXPECT_NE(session.lists().generation, unrecorded);
    EXPECT_TRUE(liveUnit<PanelScanUnit>(session).defects().empty());  // the panel starts empty
    ASSERT_TRUE(pollUntil(session, [&] { return liveUnit<PanelScanUnit>(session).defects().size() >= 3; }));
    EXPECT_EQ(session.lists().clock, LiveClock::Recording);
    const auto summary = session.stopRecording();
    ASSERT_TRUE(summary);

    // The list holds the recording's defects, on its clock, as stored.
    EXPECT_EQ(session.lists().clock, LiveClock::Recorded);
    EXPECT_EQ(session.lists().session, summary->session);
    core::storage::SessionStore store(file("s.tactiscope"), core::storage::Database::Access::ReadOnly);
    auto stored = store.events(summary->session);
    std::erase_if(stored, [](const auto& e) { return e.kind != core::EventKind::Defect; });
    const auto shown = liveUnit<PanelScanUnit>(session).defects();
    ASSERT_EQ(shown.size(), stored.size());
    EXPECT_EQ(shown.size(), summary->defects);
    for (std::size_t i = 0; i < shown.size(); ++i) {
        EXPECT_DOUBLE_EQ(shown[i].start_s, stored[i].start_s) << i;
        EXPECT_DOUBLE_EQ(shown[i].end_s, stored[i].end_s) << i;
        EXPECT_LE(shown[i].end_s, summary->end_s) << i;
    }

    // The next defect starts a list of its own, since connect: nothing of
    // the recorded panel is counted with it, and its times are the stream's.
    const auto recorded = session.lists().generation;
    const double recordingOrigin_s = session.lists().origin_s;
    EXPECT_GT(recordingOrigin_s, 1.0);
    ASSERT_TRUE(pollUntil(session, [&] { return session.lists().generation != recorded; }));
    EXPECT_EQ(session.lists().clock, LiveClock::SinceConnect);
    EXPECT_EQ(session.lists().origin_s, 0.0);
    ASSERT_FALSE(liveUnit<PanelScanUnit>(session).defects().empty());
    for (const auto& e : liveUnit<PanelScanUnit>(session).defects())
        EXPECT_GT(e.end_s, recordingOrigin_s + summary->end_s - 0.5);
}

// The line's encoder places the live panel's sites as it places the stored
// session's (issue 55): the count under the list, the verdict's sites and
// `sessions show` agree, each site within a millimetre of the dent.
TEST_F(LiveListsTest, APanelLinesEncoderPlacesTheLiveSitesAsTheStoredOnes)
{
    LiveSession session(simulator(devices::simulator::kPanelLineScenario.c_str()), optionsFor(file("s.tactiscope")));
    session.start();
    ASSERT_FALSE(session.startRecording({}));
    ASSERT_TRUE(pollUntil(session, [&] { return liveUnit<PanelScanUnit>(session).defects().size() >= 6; }));
    const auto summary = session.stopRecording();
    ASSERT_TRUE(summary);

    const auto live = liveUnit<PanelScanUnit>(session).sites();
    EXPECT_EQ(live.method, "from the position channel");
    ASSERT_EQ(live.sites.size(), 1u);
    EXPECT_EQ(summary->sites, 1u);
    const double dent_m = devices::simulator::PanelScanParameters{}.defectPosition_m;
    ASSERT_EQ(live.sites[0].kind, core::detector::SiteKind::Site) << core::detector::siteText(live.sites[0]);
    EXPECT_NEAR(*live.sites[0].position_m, dent_m, 0.001) << core::detector::siteText(live.sites[0]);

    core::storage::SessionStore store(file("s.tactiscope"), core::storage::Database::Access::ReadOnly);
    const auto defects = core::storage::defectEventsOf(store.events(summary->session));
    const auto stored = core::storage::storedSites(store, summary->session, defects);
    EXPECT_EQ(stored.method, live.method);
    ASSERT_EQ(stored.sites.size(), 1u);
    // The store keeps samples in binary32: 0.1 µm on a 100 mm stroke.
    EXPECT_NEAR(*stored.sites[0].position_m, *live.sites[0].position_m, 1e-6);
    EXPECT_EQ(stored.sites[0].crossings.size(), live.sites[0].crossings.size());
}

TEST_F(LiveListsTest, WhileRecordingPressTimesAreTheRecordingsAsStored)
{
    LiveSession session(simulator("palpation"), optionsFor(file("p.tactiscope")));
    ASSERT_EQ(session.mode(), core::Mode::Palpation);
    session.start();
    // Some presses first, so the stream's clock is well ahead of the recording's.
    ASSERT_TRUE(pollUntil(session, [&] { return liveUnit<PalpationUnit>(session).presses().size() >= 2; }));
    const double streamBefore_s = liveUnit<PalpationUnit>(session).presses().back().press.end_s;
    ASSERT_FALSE(session.startRecording({}));
    ASSERT_TRUE(pollUntil(session, [&] { return storedCount(liveUnit<PalpationUnit>(session).presses()) >= 2; }));
    const auto summary = session.stopRecording();
    ASSERT_TRUE(summary);

    core::storage::SessionStore store(file("p.tactiscope"), core::storage::Database::Access::ReadOnly);
    const auto readings = store.readings(summary->session);
    std::vector<devices::session::PressRecord> shown;
    for (const auto& press : liveUnit<PalpationUnit>(session).presses())
        if (press.stored) shown.push_back(press);
    ASSERT_EQ(shown.size(), readings.size());
    for (std::size_t i = 0; i < shown.size(); ++i) {
        EXPECT_DOUBLE_EQ(shown[i].press.start_s, readings[i].start_s) << i;
        EXPECT_DOUBLE_EQ(shown[i].press.end_s, readings[i].end_s) << i;
        EXPECT_LT(shown[i].press.start_s, summary->end_s) << i;
    }
    // On the stream's clock they would all come after the presses before.
    EXPECT_LT(shown.front().press.start_s, streamBefore_s);
}

TEST_F(LiveListsTest, TheFirstRecordedPressIsTakenAtTheSiteSelectedBeforeRecordAndOnlyStoredPressesMoveOn)
{
    LiveSession session(simulator("palpation"), optionsFor(file("g.tactiscope")));
    liveUnit<PalpationUnit>(session).setSiteGrid(core::compliance::SiteGrid(3, 4));
    liveUnit<PalpationUnit>(session).selectSite({0, 0});
    session.start();
    // Presses while not recording read at A1, and leave the selection there.
    ASSERT_TRUE(pollUntil(session, [&] { return liveUnit<PalpationUnit>(session).presses().size() >= 2; }));
    EXPECT_EQ(liveUnit<PalpationUnit>(session).siteGrid()->currentName(), "A1");
    for (const auto& press : liveUnit<PalpationUnit>(session).presses()) EXPECT_FALSE(press.stored);

    ASSERT_FALSE(session.startRecording({}));
    EXPECT_TRUE(liveUnit<PalpationUnit>(session).presses().empty());
    ASSERT_TRUE(pollUntil(session, [&] { return storedCount(liveUnit<PalpationUnit>(session).presses()) >= 2; }));
    const auto summary = session.stopRecording();
    core::storage::SessionStore store(file("g.tactiscope"), core::storage::Database::Access::ReadOnly);
    const auto readings = store.readings(summary->session);
    ASSERT_GE(readings.size(), 2u);
    EXPECT_EQ(readings[0].site, "A1");
    EXPECT_EQ(readings[1].site, "A2");
    EXPECT_EQ(liveUnit<PalpationUnit>(session).siteGrid()->currentName(),
              core::compliance::SiteGrid::name({0, int(readings.size()) % 4}));
}

TEST_F(LiveListsTest, AProfileChosenWhilePressingTakesNoZeroUnderLoad)
{
    LiveSession session(simulator("palpation"), optionsFor(file("z.tactiscope")));
    session.start();
    ASSERT_TRUE(pollUntil(session, [&] { return !liveUnit<PalpationUnit>(session).presses().empty(); }));
    // The deepest presses load the beams most: wait for one in progress.
    ASSERT_TRUE(pollUntil(session, [&] { return liveUnit<PalpationUnit>(session).palpation()->state().pressing; }));
    const auto zero = liveUnit<PalpationUnit>(session).palpation()->currentZero();
    ASSERT_TRUE(zero);
    const auto previous = liveUnit<PalpationUnit>(session).palpation();
    ASSERT_FALSE(session.setProfile(core::Mode::Palpation, *core::sensors::builtInProfile(core::Mode::Palpation)));
    ASSERT_NE(liveUnit<PalpationUnit>(session).palpation(), previous);  // rebuilt
    ASSERT_TRUE(liveUnit<PalpationUnit>(session).palpation()->currentZero());
    EXPECT_EQ(liveUnit<PalpationUnit>(session).palpation()->currentZero()->firstIndex, zero->firstIndex);
    EXPECT_FALSE(liveUnit<PalpationUnit>(session).palpation()->state().taring);

    // The next presses read the specimen, not the load it was pressed with.
    const std::size_t before = liveUnit<PalpationUnit>(session).presses().size();
    ASSERT_TRUE(pollUntil(session, [&] { return liveUnit<PalpationUnit>(session).presses().size() >= before + 3; }));
    const double truth = devices::simulator::PalpationParameters{}.objectStiffness_n_per_m;
    for (std::size_t i = before + 1; i < liveUnit<PalpationUnit>(session).presses().size(); ++i) {
        const auto& press = liveUnit<PalpationUnit>(session).presses()[i].press;
        EXPECT_EQ(press.stiffness.range, core::sensors::ComplianceRange::InRange) << i;
        EXPECT_NEAR(press.stiffness.objectStiffness_n_per_m, truth, 0.05 * truth) << i;
    }
}

namespace {

// A hand that holds a press still (no tremor): its hold is a load a zero
// may be taken under.
devices::simulator::PalpationParameters steadyHand()
{
    devices::simulator::PalpationParameters p;
    p.tremorAmplitude_m = 0.0;
    return p;
}

// The simulator's palpation stream as a device met at sample `skip`: the
// samples before it are dropped, and the rest numbered and timed from 0.
class JoinedMidStreamSource final : public devices::BlockSource {
public:
    explicit JoinedMidStreamSource(std::uint64_t skip)
        : m_skip(skip)
    {
        devices::simulator::SimulatorOptions options;
        options.speed = kSpeed;
        m_inner = std::make_unique<devices::simulator::SimulatorSource>(
            std::make_unique<devices::simulator::PalpationScenario>(steadyHand()), options);
    }
    std::string name() const override { return m_inner->name(); }
    devices::DeviceIdentity identity() const override { return m_inner->identity(); }
    std::optional<core::Mode> declaredMode() const override { return m_inner->declaredMode(); }
    const std::vector<core::ChannelDescriptor>& channels() const override { return m_inner->channels(); }
    double nominalSampleRate_hz() const override { return m_inner->nominalSampleRate_hz(); }
    devices::ReadStatus readBlock(core::SampleBlock& out, std::chrono::milliseconds timeout) override
    {
        for (;;) {
            const auto status = m_inner->readBlock(out, timeout);
            if (status != devices::ReadStatus::Block) return status;
            if (out.firstSampleIndex() < m_skip) continue;
            out.rebase(-static_cast<double>(m_skip) * out.dt_s(), std::uint64_t{0} - m_skip);
            return status;
        }
    }

private:
    std::unique_ptr<devices::BlockSource> m_inner;
    std::uint64_t m_skip;
};

// Where the longest hold of the stream's first presses begins (as a
// multiple of its blocks), and how many samples it lasts: the run where
// the displacement stays within 1 % of its press's deepest point.
std::pair<std::uint64_t, std::size_t> longestHold()
{
    devices::simulator::PalpationScenario scenario(steadyHand());
    core::SampleBlock samples(3, static_cast<std::size_t>(30.0 * scenario.sampleRate_hz()), 0.0,
                              1.0 / scenario.sampleRate_hz());
    scenario.generate(samples);
    const auto d = samples.channel(2);
    const double lifted = d[0];
    std::pair<std::uint64_t, std::size_t> longest{0, 0};
    for (std::size_t in = 0; in < d.size();) {
        while (in < d.size() && d[in] <= lifted + 1e-3) ++in;
        std::size_t out = in;
        while (out < d.size() && d[out] > lifted + 1e-3) ++out;
        if (out == d.size()) break;
        const auto press = d.subspan(in, out - in);
        const double deepest = *std::ranges::max_element(press);
        std::size_t first = 0;
        while (press[first] < deepest - 0.01 * (deepest - lifted)) ++first;
        std::size_t last = press.size() - 1;
        while (press[last] < deepest - 0.01 * (deepest - lifted)) --last;
        const std::size_t start = (in + first + 9) / 10 * 10;
        if (in + last > start && in + last - start > longest.second) longest = {start, in + last - start};
        in = out;
    }
    return longest;
}

}  // namespace

// A stream met in a press held still takes its first zero under that load;
// when the probe lifts the zero is taken again, and the recording keeps a
// note there saying what came before read from the loaded zero, as the
// operator is told. Before, nothing in the record said so.
TEST_F(LiveListsTest, AZeroTakenAgainAfterAStartUnderLoadIsNotedInTheRecording)
{
    const auto [holdStart, holdLength] = longestHold();
    ASSERT_GE(static_cast<double>(holdLength), 0.6 * steadyHand().sampleRate_hz) << "no hold long enough to zero in";
    LiveSession session(std::make_unique<JoinedMidStreamSource>(holdStart), optionsFor(file("h.tactiscope")));
    ASSERT_EQ(session.mode(), core::Mode::Palpation);
    ASSERT_FALSE(session.startRecording({}));
    session.start();
    std::vector<devices::LinkNotice> told;
    ASSERT_TRUE(pollUntil(session, [&] {
        for (auto& notice : session.takeLinkNotices()) told.push_back(std::move(notice));
        return liveUnit<PalpationUnit>(session).presses().size() >= 2;
    }));
    // Stopped in a press: it gives no reading, and the record says so.
    ASSERT_TRUE(pollUntil(session, [&] { return liveUnit<PalpationUnit>(session).palpation()->state().pressing; }));
    const auto summary = session.stopRecording();
    ASSERT_TRUE(summary);
    const auto zeroedAgain = [](const std::string& text) {
        return text.starts_with("the forces held at F_H -") && text.ends_with("zeroed again here");
    };
    EXPECT_EQ(std::ranges::count_if(told, [&](const auto& notice) { return zeroedAgain(notice.text); }), 1);
    core::storage::SessionStore store(file("h.tactiscope"), core::storage::Database::Access::ReadOnly);
    const auto events = store.events(summary->session);
    const auto note = std::ranges::find_if(events, [&](const auto& e) { return zeroedAgain(e.note); });
    ASSERT_NE(note, events.end());
    // Where the probe had lifted: after the hold's rest, before the next press.
    EXPECT_GT(note->start_s, 0.5);
    const auto readings = store.readings(summary->session);
    ASSERT_FALSE(readings.empty());
    EXPECT_LT(note->start_s, readings.front().start_s);
    const double truth = devices::simulator::PalpationParameters{}.objectStiffness_n_per_m;
    for (const auto& reading : readings) EXPECT_NEAR(reading.value, truth, 0.05 * truth);
    const auto unended = std::ranges::find_if(events, [](const auto& e) {
        return e.note.ends_with("was still under way when the recording ended: no reading");
    });
    ASSERT_NE(unended, events.end());
    EXPECT_GT(unended->start_s, readings.back().end_s);
}

TEST_F(LiveListsTest, ADeviceThatDeclaresNothingRecordsInGeneralModeAndGivenRolesAsAPanelScan)
{
    {
        LiveSession general(std::make_unique<RelabelledSource>("panel-scan", std::vector<std::string>{"a", "b"}),
                            optionsFor(file("m.tactiscope")));
        EXPECT_EQ(general.mode(), core::Mode::General);
        const auto refusal = general.refusalOf(core::Mode::PanelScan);
        ASSERT_TRUE(refusal);
        EXPECT_NE(refusal->find("no channel plays cantilever-a, cantilever-b"), std::string::npos) << *refusal;
        EXPECT_EQ(general.tare().value_or(""),
                  "general recording has no zero to take: it stores the channels as they come");
        ASSERT_FALSE(general.startRecording({}));
        general.start();
        ASSERT_TRUE(pollUntil(general, [&] { return general.sessionTime_s() > 3.0; }));
        const auto summary = general.stopRecording();
        ASSERT_TRUE(summary);
        EXPECT_FALSE(summary->verdict);
        core::storage::SessionStore store(file("m.tactiscope"), core::storage::Database::Access::ReadOnly);
        const auto session = store.session(summary->session);
        EXPECT_EQ(session->metadata.mode, core::Mode::General);
        EXPECT_GT(session->sampleCount, 1000u);
        const auto channels = store.channels(summary->session);
        ASSERT_EQ(channels.size(), 2u);
        EXPECT_EQ(channels[0].descriptor.name, "a");
        EXPECT_FALSE(channels[0].descriptor.role);
    }
    auto options = optionsFor(file("m.tactiscope"));
    options.roles = core::parseRoleAssignment("a=cantilever-a,b=cantilever-b");
    {
        // Roles alone make no plain number a strain (issue 53).
        LiveSession plain(std::make_unique<RelabelledSource>("panel-scan", std::vector<std::string>{"a", "b"}),
                          options);
        EXPECT_EQ(plain.mode(), core::Mode::General);
        EXPECT_NE(plain.refusalOf(core::Mode::PanelScan)->find("a plays cantilever-a but is a plain number"),
                  std::string::npos);
    }
    // The board that labels its values as strains, given the roles.
    LiveSession scan(
        std::make_unique<RelabelledSource>("panel-scan", std::vector<std::string>{"a[strain]", "b[strain]"}), options);
    EXPECT_EQ(scan.mode(), core::Mode::PanelScan);
    ASSERT_TRUE(scan.unitAs<PanelScanUnit>());
    ASSERT_FALSE(scan.startRecording({}));
    scan.start();
    ASSERT_TRUE(pollUntil(scan, [&] { return liveUnit<PanelScanUnit>(scan).defects().size() >= 2; }));
    const auto summary = scan.stopRecording();
    ASSERT_TRUE(summary);
    EXPECT_EQ(summary->verdict, core::Verdict::DefectsFound);
    core::storage::SessionStore store(file("m.tactiscope"), core::storage::Database::Access::ReadOnly);
    EXPECT_EQ(store.session(summary->session)->metadata.mode, core::Mode::PanelScan);
    const auto channels = store.channels(summary->session);
    EXPECT_EQ(channels[0].descriptor.role, core::ChannelRole::CantileverA);
    EXPECT_EQ(channels[1].descriptor.role, core::ChannelRole::CantileverB);
    // The roles cannot change under a recording, and name only real channels.
    EXPECT_FALSE(scan.setRoles({}));                // not recording: taken
    EXPECT_EQ(scan.mode(), core::Mode::PanelScan);  // two strains: A and B by their kind
    EXPECT_FALSE(scan.channels()[0].role);
    EXPECT_TRUE(scan.setRoles({{"z", core::ChannelRole::CantileverA}}).has_value());
}

// A palpation profile that names its channels' roles makes an undeclared
// three-column board a palpation probe; the roles given by hand win.
TEST_F(LiveListsTest, AProfilesRolesMakeABoardAPalpationProbe)
{
    // Its beams print raw counts, its displacement gauge metres.
    const std::vector<std::string> board{"ch1", "ch2", "ch3[m]"};
    LiveSession plain(std::make_unique<RelabelledSource>("palpation", board), optionsFor(file("b.tactiscope")));
    EXPECT_EQ(plain.mode(), core::Mode::General);

    auto probe = std::get<core::sensors::CompliancePairProfile>(*core::sensors::builtInProfile(core::Mode::Palpation));
    probe.roles = core::parseRoleAssignment("ch1=stiff-beam,ch2=soft-beam,ch3=displacement,ch9=capacitance");
    // The counts' scale, as the maker writes it for the simulated probe.
    const devices::simulator::PalpationParameters simulated;
    const auto countsPerNewton = [&](const core::sensors::CantileverGeometry& beam) {
        return tactiscope::testing::countsPerNewton(beam, simulated);
    };
    probe.channels = {{"ch1", {"N", countsPerNewton(probe.high), 32768.0}},
                      {"ch2", {"N", countsPerNewton(probe.low), 32768.0}}};
    // Given to a running session: the channels are built again on its roles.
    ASSERT_FALSE(plain.setProfile(core::Mode::Palpation, probe));
    EXPECT_FALSE(plain.refusalOf(core::Mode::Palpation));
    ASSERT_TRUE(plain.unitAs<PalpationUnit>());
    EXPECT_EQ(plain.channels()[2].role, core::ChannelRole::Displacement);

    auto options = optionsFor(file("b.tactiscope"));
    options.profiles.emplace(core::Mode::Palpation, probe);
    LiveSession session(std::make_unique<RelabelledSource>("palpation", board), options);
    EXPECT_EQ(session.mode(), core::Mode::Palpation);  // ch9 is not on this board: left out
    session.start();
    ASSERT_TRUE(pollUntil(session, [&] { return liveUnit<PalpationUnit>(session).presses().size() >= 2; }));
    const double truth = devices::simulator::PalpationParameters{}.objectStiffness_n_per_m;
    EXPECT_NEAR(liveUnit<PalpationUnit>(session).presses().back().press.stiffness.objectStiffness_n_per_m, truth,
                0.05 * truth);
    // Roles by hand win over the profile's: the beams swapped, no palpation.
    EXPECT_FALSE(session.setRoles(core::parseRoleAssignment("ch1=soft-beam,ch2=stiff-beam")));
    EXPECT_EQ(session.channels()[0].role, core::ChannelRole::SoftBeam);
    EXPECT_EQ(session.channels()[1].role, core::ChannelRole::StiffBeam);
}
