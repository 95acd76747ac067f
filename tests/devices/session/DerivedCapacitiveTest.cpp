// The review's capacitive force and deflection are the live ones: a
// capacitive session recorded through the live session from the simulator
// (an operator's tare, drift steps of C0 while the beam rests, then
// weights placed and lifted), then
// derived from the store by core/derived/CapacitiveChannels, gives the F
// and w the live view showed for the same samples, to the rounding of the
// stored binary32 capacitance, on the same baselines C0.
#include "core/LiveBuffer.h"
#include "core/capacitive/LiveCapacitive.h"
#include "core/derived/CapacitiveChannels.h"
#include "core/sensors/BuiltInProfiles.h"
#include "core/storage/SessionStore.h"
#include "devices/session/LiveSession.h"
#include "devices/session/modes/CapacitiveUnit.h"
#include "devices/simulator/CapacitiveWeightsScenario.h"
#include "devices/simulator/SimulatorSource.h"
#include "support/LiveUnit.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <thread>
#include <unistd.h>

using namespace tactiscope;
using tactiscope::devices::session::CapacitiveUnit;
using tactiscope::testing::liveUnit;

TEST(DerivedCapacitive, TheReviewsForceAndDeflectionAreTheLiveOnesForTheSameSamples)
{
    const auto store =
        std::filesystem::temp_directory_path() / ("tactiscope-derived-c-" + std::to_string(::getpid()) + ".tactiscope");
    std::filesystem::remove(store);
    {
        // A calibration with the baseline noise turns on drift tracking, so
        // C0 also steps while the beam rests.
        const auto profile =
            std::get<core::sensors::CapacitiveBeamProfile>(*core::sensors::builtInProfile(core::Mode::Capacitive));
        const auto model =
            core::capacitive::CapacitiveSensitivity::fromModel(core::sensors::CapacitiveBeam(profile.geometry));
        core::calibration::CalibrationRecord record;
        record.kind = core::calibration::kCapacitiveKind;
        record.sensorName = profile.name;
        record.timestampUtc = "2026-11-20T10:00:00Z";
        record.values = {{"c0_pf", model.c0_f * 1e12},
                         {"sensitivity_pf_per_mn", model.perNewton_f * 1e9},
                         {"baseline_sigma_pf", 0.004}};
        core::storage::SessionStore(store.string()).addCalibration(record);
    }
    devices::session::LiveSessionOptions options;
    options.storePath = store.string();
    devices::simulator::SimulatorOptions pace;
    pace.speed = 20.0;  // 10 Hz: 200 samples a second
    // 20 s at rest, a 50 mgf weight for 5 s, 20 s at rest.
    devices::simulator::CapacitiveWeightsParameters scenario;
    scenario.weights_mgf = {50};
    scenario.baseline_s = 20.0;
    devices::session::LiveSession live(
        std::make_unique<devices::simulator::SimulatorSource>(
            std::make_unique<devices::simulator::CapacitiveWeightsScenario>(scenario), pace),
        options);
    ASSERT_EQ(live.mode(), core::Mode::Capacitive);
    live.start();
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // 4 s: past the start tare
    ASSERT_FALSE(live.startRecording({}));
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    bool tared = false;
    for (int attempt = 0; attempt < 50 && !tared; ++attempt) {
        live.poll();
        tared = !live.tare();
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ASSERT_TRUE(tared);
    std::this_thread::sleep_for(std::chrono::milliseconds(1900));  // to 44 s: the weight, then the rest
    live.poll();
    const auto summary = live.stopRecording();
    ASSERT_TRUE(summary);

    core::LiveCursor outputCursor;
    core::LiveChunk output;
    liveUnit<CapacitiveUnit>(live).capacitive()->output()->readNew(outputCursor, output);

    core::storage::SessionStore sessions(store.string(), core::storage::Database::Access::ReadOnly);
    for (const auto& z : sessions.zeros(summary->session))
        std::cerr << "ZERO " << z.firstIndex << " " << z.valuesJson << "\n";
    std::cerr << "CAL " << sessions.session(summary->session)->metadata.calibrationsJson << "\n";
    // The C0 at the start, the tare, and drift steps while the beam rested.
    EXPECT_GE(sessions.zeros(summary->session).size(), 3u);
    core::derived::CapacitiveChannels derived(sessions, summary->session);
    const std::uint64_t n = sessions.sampleCount(summary->session);
    ASSERT_GT(n, 250u);
    const auto values = derived.read(0, n);
    const double stiffness_n_per_m =
        core::sensors::CapacitiveBeam(
            std::get<core::sensors::CapacitiveBeamProfile>(*core::sensors::builtInProfile(core::Mode::Capacitive))
                .geometry)
            .stiffness_n_per_m();
    // Where the session's sample 0 was in the stream: where the live force
    // runs as the derived one does for 30 samples (the noise, 2 µN, makes
    // every stretch its own; binary32 rounding moves the force by ~2 nN).
    std::optional<std::uint64_t> start;
    for (std::size_t k = 0; k + 30 <= output.sampleCount() && !start; ++k) {
        bool same = true;
        for (std::size_t s = 0; s < 30 && same; ++s) same = std::abs(output.values[0][k + s] - values[2][s]) < 1e-8;
        if (same) start = output.firstIndex + k;
    }
    ASSERT_TRUE(start);
    std::size_t compared = 0, loaded = 0;
    for (std::uint64_t i = 0; i < n; ++i) {
        const std::uint64_t stream = *start + i;
        if (stream < output.firstIndex || stream - output.firstIndex >= output.sampleCount()) continue;
        const std::size_t k = stream - output.firstIndex;
        // C rounded to binary32 moves by 2^-24·51 pF = 3e-18 F: ~2 nN of
        // force, and that force over the beam's stiffness of deflection.
        ASSERT_NEAR(values[2][i], output.values[0][k], 1e-8) << "force, sample " << i;
        ASSERT_NEAR(values[3][i], output.values[1][k], 1e-8 / stiffness_n_per_m) << "deflection, sample " << i;
        loaded += std::abs(output.values[0][k]) > 1e-4;  // a weight on the beam
        ++compared;
    }
    EXPECT_GT(compared, n - 10);
    EXPECT_GT(loaded, 30u);
    std::filesystem::remove(store);
}
