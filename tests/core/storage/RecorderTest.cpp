// The recorder on a real store: what is consumed is what is stored, memory
// stays bounded while the disk is held up (the overflow becomes a gap), and
// a write error ends the recording with everything before it kept.
#include "core/storage/Recorder.h"
#include "core/storage/RecorderLock.h"
#include "core/storage/RecordingTap.h"

#include "core/SampleBlock.h"

#include "support/DamagedStore.h"
#include "support/Eventually.h"
#include "support/FileBytes.h"
#include "support/ReadOnlyAfterVfs.h"
#include "support/TempPath.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using namespace tactiscope::core;
using namespace tactiscope::core::storage;
using tactiscope::testing::eventually;

namespace {

class RecorderTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        m_path = tactiscope::testing::uniqueTempPath(
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".tactiscope");
        std::filesystem::remove(m_path);
    }
    void TearDown() override
    {
        for (const char* suffix : {"", "-wal", "-shm", "-recorder.lock"}) std::filesystem::remove(m_path + suffix);
    }

    std::string m_path;
};

const std::vector<ChannelDescriptor> kChannels{{"x", "m", ChannelKind::Position}, {"f", "N", ChannelKind::Force}};

SessionMetadata palpation()
{
    SessionMetadata metadata;
    metadata.mode = tactiscope::core::Mode::Palpation;
    return metadata;
}

// Channel c, device sample i → i + c / 2 (exact in binary32 below 2^22).
SampleBlock deviceBlock(std::uint64_t first, std::size_t count)
{
    SampleBlock block(2, count, 7.5 + static_cast<double>(first) / 1000.0, 1.0 / 1000.0, first);
    for (std::size_t c = 0; c < 2; ++c)
        for (std::size_t s = 0; s < count; ++s)
            block.channel(c)[s] = static_cast<double>(first + s) + static_cast<double>(c) / 2.0;
    return block;
}

}  // namespace

TEST_F(RecorderTest, StoresEveryConsumedSampleFromSampleZero)
{
    std::int64_t id = 0;
    {
        Recorder recorder(m_path, palpation(), kChannels, 1000.0, 100'000);
        id = recorder.sessionId();
        // The device's count starts at 5000: the session still starts at 0.
        for (std::uint64_t first = 5000; first < 8000; first += 30) recorder.consume(deviceBlock(first, 30));
        const auto stats = recorder.finish(tactiscope::core::SessionStatus::Complete);
        EXPECT_EQ(stats.samplesWritten, 3000u);
        EXPECT_EQ(stats.samplesDropped, 0u);
        EXPECT_TRUE(stats.error.empty());
    }
    SessionStore store(m_path, Database::Access::ReadOnly);
    EXPECT_EQ(store.session(id)->status, tactiscope::core::SessionStatus::Complete);
    EXPECT_EQ(store.sampleCount(id), 3000u);
    EXPECT_TRUE(store.gaps(id).empty());
    const auto force = store.readChannel(id, 1, 0, 3000);
    for (std::uint64_t i = 0; i < 3000; ++i) ASSERT_EQ(force[i], static_cast<double>(5000 + i) + 0.5) << i;
    // Times are rebased with the indices: each chunk starts at index / rate.
    auto chunks = store.database().prepare("SELECT first_index, first_time_s FROM chunks WHERE session_id = ?");
    chunks.bind(1, id);
    int count = 0;
    for (; chunks.step(); ++count) EXPECT_NEAR(chunks.real(1), static_cast<double>(chunks.int64(0)) / 1000.0, 1e-12);
    EXPECT_GT(count, 0);
}

TEST_F(RecorderTest, MemoryStaysBoundedWhileTheDiskIsHeldUpAndTheOverflowIsAGap)
{
    Recorder recorder(m_path, palpation(), kChannels, 1000.0, 200);
    const auto id = recorder.sessionId();
    std::uint64_t sent = 0;
    {
        // Another connection holds the write lock, as a slow disk would.
        Database other(m_path, Database::Access::ReadWrite);
        other.exec("BEGIN IMMEDIATE");
        for (; sent < 20'000; sent += 50) recorder.consume(deviceBlock(sent, 50));
        other.exec("COMMIT");
    }
    // Once the queue has drained, a block fits again and closes the gap.
    ASSERT_TRUE(eventually([&] {
        const auto s = recorder.stats();
        return s.samplesWritten + s.samplesDropped == sent;
    }));
    recorder.consume(deviceBlock(sent, 50));
    sent += 50;
    const auto stats = recorder.finish(tactiscope::core::SessionStatus::Complete);
    EXPECT_GE(stats.samplesDropped, 20'000u - 2 * 200u);  // at most the queue and one batch in flight
    EXPECT_EQ(stats.samplesWritten + stats.samplesDropped, sent);

    SessionStore store(m_path, Database::Access::ReadOnly);
    std::uint64_t gapSamples = 0;
    for (const auto& gap : store.gaps(id)) gapSamples += gap.count;
    EXPECT_EQ(gapSamples, stats.samplesDropped);
    EXPECT_EQ(store.sampleCount(id), sent);
    const auto last = store.readChannel(id, 0, sent - 50, 50);
    for (std::uint64_t i = 0; i < 50; ++i) ASSERT_EQ(last[i], static_cast<double>(sent - 50 + i));
}

// A device lost before the stop: the samples from its last to the stop
// are a gap to the session's end, stored as it finishes.
TEST_F(RecorderTest, SamplesLostAtTheEndAreMarkedLost)
{
    Recorder recorder(m_path, palpation(), kChannels, 1000.0, 100'000);
    const auto id = recorder.sessionId();
    for (std::uint64_t first = 0; first < 600; first += 50) recorder.consume(deviceBlock(first, 50));
    recorder.markLostUntil(0.9995);  // silent from sample 600 to the stop, 1 s in
    const auto stats = recorder.finish(tactiscope::core::SessionStatus::Complete);
    EXPECT_EQ(stats.samplesWritten, 600u);
    EXPECT_TRUE(stats.error.empty()) << stats.error;
    SessionStore store(m_path, Database::Access::ReadOnly);
    EXPECT_EQ(store.sampleCount(id), 1000u);
    ASSERT_EQ(store.gaps(id).size(), 1u);
    EXPECT_EQ(store.gaps(id).back().firstIndex, 600u);
    EXPECT_EQ(store.gaps(id).back().count, 400u);
    EXPECT_TRUE(std::isnan(store.readChannel(id, 1, 999, 1).at(0)));
    EXPECT_EQ(store.readChannel(id, 1, 599, 1).at(0), 599.5);  // channel 1 is index + 0.5
}

TEST_F(RecorderTest, AWriteErrorStopsRecordingAndKeepsWhatWasCommitted)
{
    Recorder recorder(m_path, palpation(), kChannels, 1000.0, 100'000);
    const auto id = recorder.sessionId();
    recorder.consume(deviceBlock(0, 100));
    ASSERT_TRUE(eventually([&] { return recorder.stats().commits >= 1; }));
    recorder.consume(deviceBlock(100, 100));
    recorder.consume(deviceBlock(50, 100));  // out of order: the store refuses the batch
    ASSERT_TRUE(eventually([&] { return !recorder.stats().error.empty(); }));
    recorder.consume(deviceBlock(200, 100));  // dropped: recording has stopped
    const auto stats = recorder.finish(tactiscope::core::SessionStatus::Complete);
    EXPECT_NE(stats.error.find("out of order"), std::string::npos) << stats.error;
    EXPECT_NE(stats.error.find("everything recorded before was kept"), std::string::npos);
    EXPECT_EQ(stats.samplesWritten, 100u);
    EXPECT_EQ(stats.samplesDropped, 300u);

    SessionStore store(m_path, Database::Access::ReadOnly);
    EXPECT_EQ(store.session(id)->status, tactiscope::core::SessionStatus::Interrupted);
    // The samples after the failure are a gap to the end, not missing.
    EXPECT_EQ(store.sampleCount(id), 300u);
    ASSERT_EQ(store.gaps(id).size(), 1u);
    EXPECT_EQ(store.gaps(id)[0].firstIndex, 100u);
    EXPECT_EQ(store.gaps(id)[0].count, 200u);
}

TEST_F(RecorderTest, OneRecorderPerStoreAtATime)
{
    auto first = std::make_unique<Recorder>(m_path, palpation(), kChannels, 1000.0, 1000);
    try {
        Recorder second(m_path, palpation(), kChannels, 1000.0, 1000);
        FAIL() << "two recorders share a store";
    } catch (const StorageError& e) {
        EXPECT_NE(std::string(e.what()).find("another Tactiscope is recording into"), std::string::npos) << e.what();
    }
    first.reset();  // finished: the store is free again
    Recorder third(m_path, palpation(), kChannels, 1000.0, 1000);
    EXPECT_EQ(third.sessionId(), 2);
}

TEST_F(RecorderTest, OpeningTheStoreLeavesALiveRecordingAloneAndMarksACrashedOneInterrupted)
{
    std::int64_t crashed = 0;
    {
        // A session begun without a recorder and never ended: what a killed
        // process leaves behind.
        SessionStore store(m_path);
        crashed = store.beginSession(palpation(), kChannels, 1000.0);
        store.appendBlocks(crashed, std::vector{deviceBlock(0, 100)});
    }
    Recorder live(m_path, palpation(), kChannels, 1000.0, 1000);  // recovers the crashed one
    {
        SessionStore reviewer(m_path);  // e.g. `sessions list` while recording
        EXPECT_EQ(reviewer.session(crashed)->status, tactiscope::core::SessionStatus::Interrupted);
        EXPECT_EQ(reviewer.sampleCount(crashed), 100u);
        EXPECT_EQ(reviewer.session(live.sessionId())->status, tactiscope::core::SessionStatus::Recording);
    }
    live.finish(tactiscope::core::SessionStatus::Complete);
    SessionStore after(m_path);
    EXPECT_EQ(after.session(live.sessionId())->status, tactiscope::core::SessionStatus::Complete);
}

TEST_F(RecorderTest, AReaderSeesACrashedRecordingAsInterruptedAndALiveOneAsRecording)
{
    // Before, a reader (list, show, export, report: all read-only opens)
    // said "recording" until something opened the store read-write.
    std::int64_t crashed = 0;
    {
        SessionStore store(m_path);
        crashed = store.beginSession(palpation(), kChannels, 1000.0);  // never ended: killed
    }
    {
        SessionStore reader(m_path, Database::Access::ReadOnly);
        EXPECT_EQ(reader.session(crashed)->status, tactiscope::core::SessionStatus::Interrupted);
        EXPECT_EQ(reader.sessions().at(0).status, tactiscope::core::SessionStatus::Interrupted);
    }
    {
        const auto recorder = RecorderLock::acquire(m_path);  // a live recorder holds the store
        SessionStore reader(m_path, Database::Access::ReadOnly);
        EXPECT_EQ(reader.session(crashed)->status, tactiscope::core::SessionStatus::Recording);
    }
    // The reader changed nothing in the file.
    Database db(m_path, Database::Access::ReadOnly);
    auto status = db.prepare("SELECT status FROM sessions WHERE id = ?");
    status.bind(1, crashed);
    ASSERT_TRUE(status.step());
    EXPECT_EQ(status.text(0), "recording");
}

TEST_F(RecorderTest, AFullDiskStopsRecordingAndKeepsEveryCommittedSampleAndMarksTheRestLost)
{
    // In a child process, so the file-size limit (a full disk, as far as
    // SQLite can tell) and its signal stay there. The child tells how many
    // samples it dropped through a pipe.
    int pipe[2];
    ASSERT_EQ(::pipe(pipe), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        std::signal(SIGXFSZ, SIG_IGN);  // a write past the limit fails instead of killing
        int code = 3;
        try {
            Recorder recorder(m_path, palpation(), kChannels, 1000.0, 1'000'000);
            const rlimit limit{512 * 1024, 512 * 1024};
            ::setrlimit(RLIMIT_FSIZE, &limit);
            std::uint64_t first = 0;
            for (; first < 2'000'000 && recorder.stats().error.empty(); first += 500) {
                recorder.consume(deviceBlock(first, 500));
                std::this_thread::sleep_for(std::chrono::milliseconds(5));  // ~100 k samples/s: several commits
            }
            recorder.consume(deviceBlock(first, 500));  // after the failure: dropped, and part of the gap
            const auto stats = recorder.finish(tactiscope::core::SessionStatus::Complete);
            code = stats.error.empty()                                  ? 1
                   : stats.samplesWritten == 0                          ? 2
                   : stats.error.find("disk full") == std::string::npos ? 5
                                                                        : 0;
            if (code != 0) std::fprintf(stderr, "recorder: %s\n", stats.error.c_str());  // for the failure
            const bool marked = stats.error.find("could not be marked") == std::string::npos;
            const std::uint64_t report[2] = {stats.samplesDropped, marked ? 1u : 0u};
            if (::write(pipe[1], report, sizeof report) != sizeof report) code = 6;
        } catch (const std::exception&) {
            code = 4;
        }
        std::_Exit(code);
    }
    ::close(pipe[1]);
    std::uint64_t report[2] = {0, 0};
    const auto got = ::read(pipe[0], report, sizeof report);
    ::close(pipe[0]);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    ASSERT_EQ(WEXITSTATUS(status), 0) << "1: never full, 2: nothing written, 3/4: could not start, 5: unclear message";
    ASSERT_EQ(got, static_cast<ssize_t>(sizeof report));
    const auto [dropped, marked] = report;

    SessionStore store(m_path);
    ASSERT_EQ(store.sessions().size(), 1u);
    const auto session = store.sessions().front();
    EXPECT_EQ(session.status, tactiscope::core::SessionStatus::Interrupted);
    EXPECT_EQ(store.checkIntegrity(), "ok");
    const std::uint64_t n = store.sampleCount(session.id);
    ASSERT_GT(n, 0u);
    // The samples the summary calls lost are the store's gap to the end (or,
    // were the disk too full even for that row, the summary says so).
    const auto gaps = store.gaps(session.id);
    ASSERT_EQ(gaps.size(), marked ? 1u : 0u);
    const std::uint64_t stored = marked ? gaps[0].firstIndex : n;
    if (marked) {
        EXPECT_EQ(gaps[0].count, dropped);
        EXPECT_EQ(gaps[0].firstIndex + gaps[0].count, n);
    }
    const auto force = store.readChannel(session.id, 1, 0, stored);
    for (std::uint64_t i = 0; i < stored; ++i) ASSERT_EQ(force[i], static_cast<double>(i) + 0.5) << i;
}

TEST_F(RecorderTest, AReaderDuringRecordingSeesAGrowingConsistentPrefix)
{
    Recorder recorder(m_path, palpation(), kChannels, 1000.0, 1'000'000);
    const auto id = recorder.sessionId();
    std::atomic<bool> done = false;
    std::thread writer([&] {
        // About 20 k samples a second for 1.5 s: several commits.
        for (std::uint64_t first = 0; first < 30'000; first += 20) {
            recorder.consume(deviceBlock(first, 20));
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        done = true;
    });
    // Another connection, read-only, as the review window opens the store.
    SessionStore reader(m_path, Database::Access::ReadOnly);
    EXPECT_EQ(reader.session(id)->status, tactiscope::core::SessionStatus::Recording);
    std::size_t previous = 0, reads = 0, grew = 0;
    while (!done) {
        const auto x = reader.readChannel(id, 0, 0, 1'000'000);
        ASSERT_GE(x.size(), previous);
        if (x.size() > previous) ++grew;
        previous = x.size();
        ++reads;
        // A prefix: every sample from 0 on, none missing, none torn.
        for (std::size_t i = 0; i < x.size(); ++i) ASSERT_EQ(x[i], static_cast<double>(i)) << i << " of " << x.size();
        // The pyramid belongs to the same commit as the samples it sums up.
        const auto overview = reader.overview(id, 1, 0, 1'000'000, 50);
        if (!overview.empty()) {
            const auto& last = overview.back();
            EXPECT_EQ(last.max, static_cast<double>(last.firstIndex + last.count - 1) + 0.5);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    writer.join();
    recorder.finish(tactiscope::core::SessionStatus::Complete);
    EXPECT_GT(reads, 10u);
    EXPECT_GT(grew, 2u);  // the reader saw several commits land
    EXPECT_EQ(reader.readChannel(id, 0, 0, 1'000'000).size(), 30'000u);
    EXPECT_EQ(reader.session(id)->status, tactiscope::core::SessionStatus::Complete);
}

TEST_F(RecorderTest, AStoreWhoseDiskTurnsReadOnlyStopsRecordingAndKeepsWhatWasCommitted)
{
    tactiscope::testing::ReadOnlyAfterVfs disk;
    std::int64_t id = 0;
    std::uint64_t committed = 0;
    {
        Recorder recorder(m_path, palpation(), kChannels, 1000.0, 100'000);
        id = recorder.sessionId();
        recorder.consume(deviceBlock(0, 300));
        ASSERT_TRUE(eventually([&] { return recorder.stats().commits >= 1; }));
        disk.failWrites();
        recorder.consume(deviceBlock(300, 300));
        ASSERT_TRUE(eventually([&] { return !recorder.stats().error.empty(); }));
        const auto stats = recorder.finish(tactiscope::core::SessionStatus::Complete);
        committed = stats.samplesWritten;
        EXPECT_EQ(committed, 300u);
        EXPECT_NE(stats.error.find("disk I/O error"), std::string::npos) << stats.error;
        EXPECT_NE(stats.error.find("everything recorded before was kept"), std::string::npos) << stats.error;
    }
    // The disk comes back (remounted read-write): the next open finds the
    // session that could not be ended and keeps every committed sample.
    tactiscope::testing::ReadOnlyAfterVfs writable;
    SessionStore store(m_path);
    EXPECT_EQ(store.checkIntegrity(), "ok");
    EXPECT_EQ(store.session(id)->status, tactiscope::core::SessionStatus::Interrupted);
    const auto force = store.readChannel(id, 1, 0, 1000);
    ASSERT_EQ(force.size(), committed);
    for (std::uint64_t i = 0; i < committed; ++i) ASSERT_EQ(force[i], static_cast<double>(i) + 0.5) << i;
}

TEST_F(RecorderTest, ADamagedStoreIsReportedAndNeverWritten)
{
    std::int64_t id = 0;
    {
        Recorder recorder(m_path, palpation(), kChannels, 1000.0, 1'000'000);
        id = recorder.sessionId();
        for (std::uint64_t first = 0; first < 200'000; first += 1000) recorder.consume(deviceBlock(first, 1000));
        recorder.finish(tactiscope::core::SessionStatus::Complete);
    }
    {
        SessionStore checkpoint(m_path);  // the last connection folds the WAL into the file
    }
    const auto size = std::filesystem::file_size(m_path);
    ASSERT_TRUE(tactiscope::testing::scribbleOverTheMiddle(m_path));
    const std::string damaged = tactiscope::testing::fileBytes(m_path);
    ASSERT_EQ(damaged.size(), size);
    {
        SessionStore store(m_path);
        EXPECT_NE(store.checkIntegrity(), "ok");
        // Reading the damaged part fails with a message naming the file.
        try {
            for (std::size_t c = 0; c < 2; ++c) store.readChannel(id, c, 0, 200'000);
            ADD_FAILURE() << "read a damaged store without noticing";
        } catch (const StorageError& e) {
            EXPECT_NE(std::string(e.what()).find(m_path), std::string::npos) << e.what();
        }
    }
    // Recording into it is refused before anything is written (before, it
    // went ahead silently).
    try {
        Recorder recorder(m_path, palpation(), kChannels, 1000.0, 1'000'000);
        ADD_FAILURE() << "recorded into a damaged store";
    } catch (const StorageError& e) {
        EXPECT_NE(std::string(e.what()).find(m_path + " is damaged ("), std::string::npos) << e.what();
    }
    // Nothing was written to repair or reset it.
    EXPECT_TRUE(tactiscope::testing::fileBytes(m_path) == damaged);
}

// A start the source's clock cannot place yet (a board's catch-up still
// arriving): the tap holds the blocks, then records from where it is
// placed; stopped before, it records from the answer it must then give.
TEST_F(RecorderTest, ATapHoldsTheBlocksUntilTheStartIsPlacedAndRecordsFromIt)
{
    RecordingTap tap;
    auto recorder = std::make_shared<Recorder>(m_path, palpation(), kChannels, 1000.0, 100'000);
    std::vector<std::pair<double, bool>> asked;
    tap.attach(recorder, [&asked](double newestEnd_s, bool mustAnswer) {
        asked.emplace_back(newestEnd_s, mustAnswer);
        // Placed once the stream is past 7.8 s (block time), at 7.65 s.
        return newestEnd_s >= 7.8 ? RecordingStart::at(7.65) : RecordingStart::notYet();
    });
    for (std::uint64_t first = 0; first < 400; first += 100) tap.consume(deviceBlock(first, 100));
    ASSERT_EQ(asked.size(), 3u);  // the third block ends at 7.8 s: placed
    EXPECT_FALSE(asked.back().second);
    EXPECT_EQ(tap.detach(), recorder);
    recorder->finish(tactiscope::core::SessionStatus::Complete);
    SessionStore store(m_path, Database::Access::ReadOnly);
    EXPECT_EQ(store.sampleCount(recorder->sessionId()), 250u);  // 7.65 s (sample 150) to 7.9 s
    EXPECT_EQ(store.readChannel(recorder->sessionId(), 0, 0, 1)[0], 150.0);
}

TEST_F(RecorderTest, ATapStoppedOrHoldingAllItMayBeforeTheStartIsPlacedRecordsFromItsAnswer)
{
    {
        RecordingTap tap;
        auto recorder = std::make_shared<Recorder>(m_path, palpation(), kChannels, 1000.0, 100'000);
        tap.attach(recorder, [](double, bool mustAnswer) {
            return mustAnswer ? RecordingStart::at(7.55) : RecordingStart::notYet();
        });
        for (std::uint64_t first = 0; first < 200; first += 100) tap.consume(deviceBlock(first, 100));
        EXPECT_EQ(tap.detach(), recorder);
        recorder->finish(tactiscope::core::SessionStatus::Complete);
        SessionStore store(m_path, Database::Access::ReadOnly);
        EXPECT_EQ(store.sampleCount(recorder->sessionId()), 150u);
    }
    {
        // At most 30 blocks of 100 samples: a catch-up's minute of lines in
        // a second is held as long as the tap may (the finder's clock says
        // how long to wait, not the blocks' time).
        const std::uint64_t blocks = 30;
        RecordingTap tap(blocks * 100 * kChannels.size());
        auto recorder = std::make_shared<Recorder>(m_path, palpation(), kChannels, 1000.0, 100'000);
        std::vector<bool> asked;
        tap.attach(recorder, [&asked](double, bool mustAnswer) {
            asked.push_back(mustAnswer);
            return mustAnswer ? RecordingStart::fromFirstBlock() : RecordingStart::notYet();
        });
        for (std::uint64_t k = 0; k < blocks + 5; ++k) tap.consume(deviceBlock(100 * k, 100));
        // Asked on every block until the one that filled the tap, which had to be answered.
        ASSERT_EQ(asked.size(), blocks);
        EXPECT_EQ(std::ranges::count(asked, true), 1);
        EXPECT_TRUE(asked.back());
        EXPECT_EQ(tap.detach(), recorder);
        recorder->finish(tactiscope::core::SessionStatus::Complete);
        SessionStore store(m_path, Database::Access::ReadOnly);
        EXPECT_EQ(store.sampleCount(recorder->sessionId()), 100 * (blocks + 5));
    }
}

// A recording of a set length holds its whole periods from its start, on
// the stream's clock, however late the stop comes: 2 s of a 100 Hz stream
// are 200 samples whether its rate was measured a little high or low
// (before, the stop's moment decided: 201 for 2 s, 1000 for 10 s), from the
// placed start, across a gap (lost samples are time in it too).
TEST_F(RecorderTest, ATapOfASetLengthRecordsExactlyItsPeriodsAndIsThenComplete)
{
    const auto stream = [](double rate_hz, std::uint64_t first, std::size_t count) {
        SampleBlock block(2, count, static_cast<double>(first) / rate_hz, 1.0 / rate_hz, first);
        for (std::size_t s = 0; s < count; ++s) block.channel(0)[s] = static_cast<double>(first + s);
        return block;
    };
    // The first sample at or after the start: at 100.0005 Hz sample 50 lies 25 ns before it.
    for (const auto& [rate_hz, first] : {std::pair{99.9995, 50.0}, {100.0, 50.0}, {100.0005, 51.0}}) {
        RecordingTap tap;
        auto recorder = std::make_shared<Recorder>(m_path, palpation(), kChannels, rate_hz, 100'000);
        tap.attach(
            recorder, [](double, bool) { return RecordingStart::at(0.5); }, 2.0);
        std::uint64_t next = 0;
        for (; !tap.complete() && next < 1000; next += 7) tap.consume(stream(rate_hz, next, 7));
        EXPECT_EQ(next, 252u) << rate_hz;       // complete with the block that holds the last sample
        tap.consume(stream(rate_hz, next, 7));  // a late block: past the length
        EXPECT_EQ(tap.detach(), recorder);
        recorder->finish(tactiscope::core::SessionStatus::Complete);
        SessionStore store(m_path, Database::Access::ReadOnly);
        ASSERT_EQ(store.sampleCount(recorder->sessionId()), 200u) << rate_hz;
        EXPECT_EQ(store.readChannel(recorder->sessionId(), 0, 0, 1)[0], first) << rate_hz;
        EXPECT_EQ(store.readChannel(recorder->sessionId(), 0, 199, 1)[0], first + 199.0) << rate_hz;
    }
    // A gap of 30 samples within it: 2 s are 200 periods, 170 of them with samples.
    RecordingTap tap;
    auto recorder = std::make_shared<Recorder>(m_path, palpation(), kChannels, 100.0, 100'000);
    tap.attach(recorder, {}, 2.0);
    tap.consume(stream(100.0, 0, 100));
    EXPECT_FALSE(tap.complete());
    tap.consume(stream(100.0, 130, 100));
    EXPECT_TRUE(tap.complete());
    EXPECT_EQ(tap.detach(), recorder);
    const auto stats = recorder->finish(tactiscope::core::SessionStatus::Complete);
    EXPECT_EQ(stats.samplesWritten, 170u);
    SessionStore store(m_path, Database::Access::ReadOnly);
    EXPECT_EQ(store.sampleCount(recorder->sessionId()), 200u);
}

TEST_F(RecorderTest, ATapRecordsOnlyWhileARecorderIsAttachedAndMarkersLandInTheSession)
{
    RecordingTap tap;
    tap.consume(deviceBlock(0, 100));  // nothing attached: not recorded
    auto recorder = std::make_shared<Recorder>(m_path, palpation(), kChannels, 1000.0, 100'000);
    tap.attach(recorder);
    tap.consume(deviceBlock(100, 250));
    EXPECT_DOUBLE_EQ(recorder->sessionTime_s(), 0.249);  // the newest sample, session-relative
    recorder->addEvents(
        {{0, kLiveAnalysis, tactiscope::core::EventKind::Marker, 0.2, 0.2, 0, {}, {}, {}, "weld seam"}});
    EXPECT_EQ(tap.detach(), recorder);
    tap.consume(deviceBlock(350, 100));  // detached: not recorded
    const auto stats = recorder->finish(tactiscope::core::SessionStatus::Complete);
    EXPECT_EQ(stats.samplesWritten, 250u);
    EXPECT_EQ(stats.eventsWritten, 1u);

    SessionStore store(m_path, Database::Access::ReadOnly);
    EXPECT_EQ(store.sampleCount(recorder->sessionId()), 250u);
    EXPECT_EQ(store.readChannel(recorder->sessionId(), 0, 0, 1)[0], 100.0);
    const auto markers = store.events(recorder->sessionId());
    ASSERT_EQ(markers.size(), 1u);
    EXPECT_EQ(markers[0].kind, tactiscope::core::EventKind::Marker);
    EXPECT_EQ(markers[0].start_s, 0.2);
    EXPECT_EQ(markers[0].note, "weld seam");
}
