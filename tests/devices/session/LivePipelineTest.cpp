// The one live pipeline (issue 52) with simulated devices sped up tenfold
// into a real store: one device and several record through the same
// calls; a session of several ends with each part and its parts' verdict
// (the panel probe found its dents; the load cell judges nothing), stored
// on the session as the store lists it; what a session keeps (its
// devices, one trigger for one device) is refused with the reason; and a
// poll's news carries every part's end.
#include "devices/session/LivePipeline.h"
#include "core/storage/SessionStore.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/simulator/SimulatorSource.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>
#include <unistd.h>

using namespace tactiscope;
using devices::session::LivePipeline;

namespace {

// A folder of its own under the system's temporary one, removed at the end.
struct TemporaryFolder {
    std::filesystem::path path = std::filesystem::temp_directory_path() /
                                 ("tactiscope-pipeline-" + std::to_string(::getpid()) + "-" +
                                  std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
    TemporaryFolder() { std::filesystem::create_directories(path); }
    ~TemporaryFolder() { std::filesystem::remove_all(path); }
    std::string filePath(const std::string& name) const { return (path / name).string(); }
};

std::unique_ptr<devices::BlockSource> spedUp(const char* scenario)
{
    devices::simulator::SimulatorOptions options;
    options.speed = 10.0;
    return std::make_unique<devices::simulator::SimulatorSource>(devices::simulator::makeScenario(scenario), options);
}

// Polls for `seconds` of the host's clock, gathering every news.
std::vector<devices::session::PipelineNews> run(LivePipeline& pipeline, double seconds)
{
    std::vector<devices::session::PipelineNews> news;
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        news.push_back(pipeline.poll());
    }
    return news;
}

}  // namespace

TEST(LivePipeline, OneDeviceAndTwoRecordThroughTheSameCallsAndTheSessionTakesItsPartsVerdict)
{
    TemporaryFolder dir;
    const std::string store = dir.filePath("s.tactiscope");
    LivePipeline pipeline(store);
    ASSERT_FALSE(pipeline.add(spedUp("panel-scan"), {}));
    EXPECT_EQ(pipeline.name(0), "tactiscope-simulator");
    pipeline.start();
    core::storage::SessionMetadata metadata;
    metadata.subject = "door-1";

    // One device: a session of one.
    ASSERT_FALSE(pipeline.startRecording(metadata));
    run(pipeline, 2.0);  // 20 s of the panel
    const auto one = pipeline.stopRecording();
    ASSERT_TRUE(one);
    ASSERT_EQ(one->parts.size(), 1u);
    EXPECT_EQ(one->parts[0].device, "");
    EXPECT_EQ(one->verdict, core::Verdict::DefectsFound);

    // A second device: a session of two, each its part.
    ASSERT_FALSE(pipeline.add(spedUp("load-cell"), {}));
    EXPECT_EQ(pipeline.names(),
              (std::vector<std::string>{"tactiscope-simulator", "tactiscope-simulator-reference-load-cell"}));
    pipeline.start();
    ASSERT_FALSE(pipeline.startRecording(metadata));
    EXPECT_TRUE(pipeline.isRecording());
    // What a session keeps is refused while it records.
    EXPECT_TRUE(pipeline.add(spedUp("panel-scan"), {}));
    EXPECT_TRUE(pipeline.remove(1));
    const std::int64_t session = pipeline.sessionId();
    run(pipeline, 2.0);
    const auto two = pipeline.stopRecording();
    ASSERT_TRUE(two);
    EXPECT_EQ(two->session, session);
    ASSERT_EQ(two->parts.size(), 2u);
    EXPECT_EQ(two->parts[0].device, "tactiscope-simulator");
    EXPECT_EQ(two->parts[0].what.verdict, core::Verdict::DefectsFound);
    EXPECT_FALSE(two->parts[1].what.verdict);  // a load cell judges nothing
    EXPECT_EQ(two->verdict, core::Verdict::DefectsFound);
    EXPECT_FALSE(pipeline.isRecording());

    // A trigger records one device.
    core::trigger::TriggerSettings trigger;
    trigger.condition = *core::trigger::parseTrigger("a>20e-6").condition;
    EXPECT_TRUE(pipeline.armTrigger(trigger, metadata));

    core::storage::SessionStore sessions(store, core::storage::Database::Access::ReadOnly);
    const auto listed = sessions.sessions();
    ASSERT_EQ(listed.size(), 2u);
    const auto whole = sessions.session(session);
    EXPECT_EQ(whole->devices, 2u);
    EXPECT_EQ(whole->verdict, core::Verdict::DefectsFound);
    EXPECT_EQ(whole->metadata.mode, core::Mode::PanelScan);  // its first device's
    std::uint64_t partEvents = 0;
    for (const auto& part : sessions.parts(session)) partEvents += sessions.session(part.id)->eventCount;
    EXPECT_EQ(whole->eventCount, partEvents);
    EXPECT_GT(partEvents, 0u);
}

TEST(LivePipeline, AStoreThatRefusesASessionOfSeveralRecordsNothingAndSaysWhy)
{
    TemporaryFolder dir;
    const std::string store = dir.filePath("missing/folder/that/is/a/file");
    {
        std::FILE* blocker = std::fopen(dir.filePath("missing").c_str(), "w");
        ASSERT_NE(blocker, nullptr);
        std::fclose(blocker);
    }
    LivePipeline pipeline(store);
    ASSERT_FALSE(pipeline.add(spedUp("panel-scan"), {}));
    ASSERT_FALSE(pipeline.add(spedUp("load-cell"), {}));
    pipeline.start();
    const auto refused = pipeline.startRecording({});
    ASSERT_TRUE(refused);
    EXPECT_FALSE(refused->empty());
    EXPECT_FALSE(pipeline.isRecording());
    EXPECT_TRUE(pipeline.poll().ended.empty());
}
