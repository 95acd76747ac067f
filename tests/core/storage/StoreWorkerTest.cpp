// The store worker on real files: jobs run in the order posted, on one
// connection that is not the caller's thread; a file that is not a store
// fails each job with the store's own message; a job posted just before the
// worker goes is still done.
#include "core/storage/StoreWorker.h"

#include "core/storage/SessionStore.h"
#include "support/TempPath.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <future>
#include <thread>

using namespace tactiscope::core;
using storage::SessionSource;
using storage::SessionStore;
using storage::StoreWorker;

namespace {

const std::vector<ChannelDescriptor> kChannels{{"a", "", ChannelKind::Strain}};

storage::SessionMetadata subject(const std::string& name)
{
    storage::SessionMetadata metadata;
    metadata.mode = Mode::PanelScan;
    metadata.subject = name;
    return metadata;
}

}  // namespace

TEST(StoreWorker, RunsJobsInOrderOnOneConnectionOffTheCallersThread)
{
    const std::string path = tactiscope::testing::uniqueTempPath("worker.tactiscope");
    std::vector<std::thread::id> threads;
    std::vector<std::string> order;
    {
        StoreWorker worker(path);
        SessionStore* first = nullptr;
        bool sameConnection = true;
        for (const std::string name : {"door-1", "door-2", "door-3"}) {
            worker.post(
                [&, name](SessionSource& source) {
                    auto& store = dynamic_cast<SessionStore&>(source);  // a file opens a station's store
                    if (!first) first = &store;
                    sameConnection = sameConnection && first == &store;
                    threads.push_back(std::this_thread::get_id());
                    const auto id = store.beginSession(subject(name), kChannels, 100.0);
                    store.endSession(id, SessionStatus::Complete);
                    order.push_back(name);
                },
                [](const std::string& error) { ADD_FAILURE() << error; });
        }
        std::promise<void> done;
        worker.post([&](SessionSource&) { done.set_value(); }, {});
        done.get_future().wait();
        EXPECT_TRUE(sameConnection);
    }
    EXPECT_EQ(order, (std::vector<std::string>{"door-1", "door-2", "door-3"}));
    ASSERT_EQ(threads.size(), 3u);
    EXPECT_NE(threads.front(), std::this_thread::get_id());
    EXPECT_EQ(threads.front(), threads.back());
    SessionStore store(path, storage::Database::Access::ReadOnly);
    const auto sessions = store.sessions();  // newest first
    ASSERT_EQ(sessions.size(), 3u);
    EXPECT_EQ(sessions.back().metadata.subject, "door-1");
    std::filesystem::remove(path);
}

TEST(StoreWorker, AFileThatIsNotAStoreFailsEachJobWithTheStoresMessage)
{
    const std::string path = tactiscope::testing::uniqueTempPath("notes.txt");
    std::ofstream(path) << "my notes, not a store\n";
    std::vector<std::string> errors;
    bool ran = false;
    {
        StoreWorker worker(path);
        for (int i = 0; i < 2; ++i)
            worker.post([&](SessionSource&) { ran = true; }, [&](const std::string& e) { errors.push_back(e); });
    }
    EXPECT_FALSE(ran);
    ASSERT_EQ(errors.size(), 2u);  // opened again for the second job, and refused again
    EXPECT_NE(errors.front().find("not a Tactiscope session store"), std::string::npos) << errors.front();
    std::ifstream in(path);
    std::string text;
    std::getline(in, text);
    EXPECT_EQ(text, "my notes, not a store");  // untouched
    std::filesystem::remove(path);
}

TEST(StoreWorker, AJobPostedJustBeforeTheWorkerGoesIsStillDone)
{
    const std::string path = tactiscope::testing::uniqueTempPath("late.tactiscope");
    std::int64_t session = 0;
    {
        SessionStore store(path);
        session = store.beginSession(subject("door-9"), kChannels, 100.0);
        store.endSession(session, SessionStatus::Complete);
    }
    {
        StoreWorker worker(path);
        worker.post(
            [session](SessionSource& store) {
                dynamic_cast<SessionStore&>(store).setVerdict(session, Verdict::DefectsFound);
            },
            {});
    }
    SessionStore store(path, storage::Database::Access::ReadOnly);
    EXPECT_EQ(store.session(session)->verdict, Verdict::DefectsFound);
    std::filesystem::remove(path);
}
