// The review's forces are the live ones: a palpation recorded through the
// live session from the simulator (with an operator's tare in the middle),
// then derived from the store by core/derived/PalpationChannels, gives the
// F_H, F_L and Q the live view showed for the same samples — to the
// rounding of the stored binary32 samples — and its overview of the forces,
// mapped from the store's pyramid, bounds exactly what the samples give.
#include "core/LiveBuffer.h"
#include "core/compliance/LivePalpation.h"
#include "core/derived/PalpationChannels.h"
#include "core/storage/SessionStore.h"
#include "devices/session/LiveSession.h"
#include "devices/session/modes/PalpationUnit.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/simulator/SimulatorSource.h"
#include "support/LiveUnit.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <thread>
#include <unistd.h>

using namespace tactiscope;
using tactiscope::devices::session::PalpationUnit;
using tactiscope::testing::liveUnit;

namespace {

// Where the session's sample 0 was in the live stream: the session's last
// samples are still in the live raw buffer (2 s long), which holds the
// stream's values that the store rounded to binary32.
std::optional<std::uint64_t> sessionStart(const core::LiveChunk& raw, const std::vector<double>& storedTail,
                                          std::uint64_t tailFirst)
{
    for (std::size_t k = 0; k + storedTail.size() <= raw.sampleCount(); ++k) {
        bool same = true;
        for (std::size_t s = 0; s < storedTail.size() && same; ++s)
            same = static_cast<float>(raw.values[0][k + s]) == static_cast<float>(storedTail[s]);
        if (same) return raw.firstIndex + k - tailFirst;
    }
    return std::nullopt;
}

}  // namespace

TEST(DerivedPalpation, TheReviewsForcesAreTheLiveOnesForTheSameSamples)
{
    const auto store =
        std::filesystem::temp_directory_path() / ("tactiscope-derived-" + std::to_string(::getpid()) + ".tactiscope");
    std::filesystem::remove(store);
    devices::session::LiveSessionOptions options;
    options.storePath = store.string();
    devices::simulator::SimulatorOptions pace;
    pace.speed = 3.0;
    devices::session::LiveSession live(
        std::make_unique<devices::simulator::SimulatorSource>(devices::simulator::makeScenario("palpation"), pace),
        options);
    ASSERT_EQ(live.mode(), core::Mode::Palpation);
    live.start();
    std::this_thread::sleep_for(std::chrono::milliseconds(400));  // 1.2 s: the first zero is taken
    ASSERT_FALSE(live.startRecording({}));
    // An operator's tare between presses: refused while pressing, so tried until taken.
    bool tared = false;
    for (int attempt = 0; attempt < 100 && !tared; ++attempt) {
        std::this_thread::sleep_for(std::chrono::milliseconds(40));
        live.poll();
        tared = !live.tare();
    }
    ASSERT_TRUE(tared);
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    live.poll();
    const auto summary = live.stopRecording();
    ASSERT_TRUE(summary);

    core::LiveCursor cursor;
    core::LiveChunk raw, forces;
    live.buffer()->readNew(cursor, raw);
    core::LiveCursor forceCursor;
    liveUnit<PalpationUnit>(live).palpation()->output()->readNew(forceCursor, forces);

    core::storage::SessionStore sessions(store.string(), core::storage::Database::Access::ReadOnly);
    EXPECT_EQ(sessions.zeros(summary->session).size(), 2u);  // the one in use at the start, and the tare
    core::derived::PalpationChannels derived(sessions, summary->session);
    const std::uint64_t n = sessions.sampleCount(summary->session);
    ASSERT_GT(n, 1000u);
    const auto offset = sessionStart(raw, sessions.readChannel(summary->session, 0, n - 50, 50), n - 50);
    ASSERT_TRUE(offset);
    const auto values = derived.read(0, n);
    std::size_t compared = 0, contact = 0;
    for (std::uint64_t i = 0; i < n; ++i) {
        const std::uint64_t stream = *offset + i;
        if (stream < forces.firstIndex || stream - forces.firstIndex >= forces.sampleCount()) continue;
        const std::size_t k = stream - forces.firstIndex;
        for (std::size_t c = 0; c < 2; ++c) {
            const double want = forces.values[c][k], got = values[c][i];
            // A count rounded to binary32 moves by at most 2^-24 of itself:
            // the force by that many counts' worth (~2e-8 N here).
            ASSERT_NEAR(got, want, 1e-6 * std::abs(want) + 1e-7) << "sample " << i << ", channel " << c;
        }
        const double q = forces.values[2][k];
        ASSERT_EQ(std::isnan(values[2][i]), std::isnan(q)) << "sample " << i;
        if (!std::isnan(q)) {
            ASSERT_NEAR(values[2][i], q, 1e-5 * q) << "sample " << i;
            ++contact;
        }
        ++compared;
    }
    EXPECT_GT(compared, n - 10);
    EXPECT_GT(contact, 100u);  // presses were compared, not just the probe in the air

    // The overview of the forces from the pyramid bounds the exact samples
    // of each stretch, and reaches them.
    const auto overview = derived.overview(0, 0, n, 40);
    ASSERT_FALSE(overview.empty());
    for (const auto& point : overview) {
        double lo = INFINITY, hi = -INFINITY;
        for (std::uint64_t s = point.firstIndex; s < point.firstIndex + point.count; ++s) {
            if (std::isnan(values[0][s])) continue;
            lo = std::min(lo, values[0][s]);
            hi = std::max(hi, values[0][s]);
        }
        if (std::isinf(lo)) continue;
        EXPECT_DOUBLE_EQ(point.min, lo) << point.firstIndex;
        EXPECT_DOUBLE_EQ(point.max, hi) << point.firstIndex;
    }
    std::filesystem::remove(store);
}
