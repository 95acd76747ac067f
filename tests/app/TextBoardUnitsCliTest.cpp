// A text board's numbers have the unit they were given, or none (issue
// 53): plain numbers are recorded as plain numbers, a mode that reads a
// strain or a force refuses them and says how to give their unit (the
// board's label, --units, a profile's scale), and a palpation board that
// prints raw ADC counts is read through its profile's scale, its clipped
// presses judged from the declared full scale and no calibration said to
// be used that was not applied. Real pseudo-terminals, real boards'
// timing (support/TextBoard.h).
#include "support/BridgeArithmetic.h"
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"
#include "support/TextBoard.h"
#include "support/TextFiles.h"

#include "core/SampleBlock.h"
#include "core/calibration/CalibrationRecord.h"
#include "core/derived/CapacitiveChannels.h"
#include "core/sensors/BuiltInProfiles.h"
#include "core/sensors/SensorProfile.h"
#include "core/storage/SessionStore.h"
#include "devices/simulator/PalpationScenario.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace tactiscope;
using tactiscope::testing::CliResult;
using tactiscope::testing::runCli;
using tactiscope::testing::sessionIdIn;
using tactiscope::testing::TextBoard;
using tactiscope::testing::TextBoardOptions;

namespace {

std::string plainLine(std::uint64_t n)
{
    return "a:" + std::to_string(n) + " b:" + std::to_string(2 * n) + "\n";
}

QStringList recordBoard(const QString& link, const QString& db, double seconds)
{
    return {"record", "--port", link, "--protocol", "text", "--rate", "50", "--seconds", QString::number(seconds),
            "--db",   db};
}

}  // namespace

TEST(TextBoardUnitsCli, PlainNumbersAreNoStrainAScanRefusesThemAndSaysHowToGiveTheirUnit)
{
    QTemporaryDir dir;
    const QString link = dir.filePath(QStringLiteral("board"));
    TextBoard board(link.toStdString(), TextBoardOptions{50.0, plainLine, 1, 1e-3, false});
    ASSERT_TRUE(board.ok());
    const QString db = dir.filePath(QStringLiteral("bench.tactiscope"));

    // Roles alone do not make a plain number a strain.
    const CliResult refused = runCli(recordBoard(link, db, 1.0) +
                                     QStringList{"--mode", "panel-scan", "--roles", "a=cantilever-a,b=cantilever-b"});
    EXPECT_EQ(refused.exitCode, 2) << refused.out.toStdString();
    EXPECT_TRUE(refused.err.contains(QStringLiteral("a plays cantilever-a but is a plain number (no unit)")))
        << refused.err.toStdString();
    EXPECT_TRUE(refused.err.contains(QStringLiteral("--units a=UNIT"))) << refused.err.toStdString();

    // The general mode records them as they are: no unit, no kind.
    const CliResult general = runCli(recordBoard(link, db, 1.0));
    ASSERT_EQ(general.exitCode, 0) << general.err.toStdString();
    {
        core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
        const auto id = sessionIdIn(general.out);
        const auto channels = store.channels(id);
        ASSERT_EQ(channels.size(), 2u);
        EXPECT_EQ(channels[0].descriptor.unit, "");
        EXPECT_EQ(channels[0].descriptor.kind, core::ChannelKind::Other);
        EXPECT_EQ(store.session(id)->metadata.mode, core::Mode::General);
    }

    // Given in µε, they are strains, stored as such (×1e-6), and the scan runs.
    const CliResult scan =
        runCli(recordBoard(link, db, 1.0) +
               QStringList{"--mode", "panel-scan", "--roles", "a=cantilever-a,b=cantilever-b", "--units", "a=µε,b=µε"});
    ASSERT_EQ(scan.exitCode, 0) << scan.err.toStdString();
    core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto id = sessionIdIn(scan.out);
    const auto channels = store.channels(id);
    ASSERT_EQ(channels.size(), 2u);
    for (const auto& channel : channels) {
        EXPECT_EQ(channel.descriptor.kind, core::ChannelKind::Strain) << channel.descriptor.name;
        EXPECT_EQ(channel.descriptor.unit, "") << channel.descriptor.name;
    }
    const auto count = store.sampleCount(id);
    ASSERT_GT(count, 20u);
    const auto a = store.readChannel(id, 0, 0, count), b = store.readChannel(id, 1, 0, count);
    const double n0 = std::round(a[0] * 1e6);
    for (std::size_t i = 0; i < count; ++i) {
        const double n = n0 + static_cast<double>(i);
        ASSERT_EQ(a[i], static_cast<double>(static_cast<float>(n * 1e-6))) << i;
        ASSERT_EQ(b[i], static_cast<double>(static_cast<float>(2.0 * n * 1e-6))) << i;
    }

    // A unit for a channel the board does not print is refused.
    const CliResult unknown = runCli(recordBoard(link, db, 1.0) + QStringList{"--units", "c=mN"});
    EXPECT_NE(unknown.exitCode, 0);
    EXPECT_TRUE(unknown.err.contains(QStringLiteral("a unit is given for 'c', which the board does not print")))
        << unknown.err.toStdString();
}

namespace {

// A palpation board: the simulator's probe printing its two beams' raw
// ADC counts and its displacement in mm as plain numbers, 200 lines a
// second.
struct PalpationBoard {
    devices::simulator::PalpationParameters parameters;
    std::vector<std::string> lines;
};

PalpationBoard palpationBoard()
{
    PalpationBoard board;
    auto& p = board.parameters;
    p.sampleRate_hz = 200.0;
    p.objectStiffness_n_per_m = 3000.0;        // the issue's phantom
    p.pressDepths_m = {0.003, 0.006, 0.0095};  // the deepest drives the stiff beam to its limit
    p.seed = 5;
    devices::simulator::PalpationScenario scenario(p);
    const std::size_t count = 60 * 200;
    core::SampleBlock samples(3, count, 0.0, 1.0 / p.sampleRate_hz, 0);
    scenario.generate(samples);
    for (std::size_t i = 0; i < count; ++i) {
        char line[96];
        std::snprintf(line, sizeof line, "stiff:%.0f soft:%.0f d:%.4f\n", samples.channel(0)[i], samples.channel(1)[i],
                      1e3 * samples.channel(2)[i]);
        board.lines.emplace_back(line);
    }
    return board;
}

std::string geometryJson(const core::sensors::CantileverGeometry& g)
{
    char text[200];
    std::snprintf(text, sizeof text,
                  R"({"length_m": %.17g, "width_m": %.17g, "thickness_m": %.17g, "youngs_modulus_pa": %.17g})",
                  g.length_m, g.width_m, g.thickness_m, g.youngsModulus_pa);
    return text;
}

std::string profileJson(const devices::simulator::PalpationParameters& p, bool withScales)
{
    std::string json = R"({"kind": "compliance_pair", "name": "maker probe", "high": )" + geometryJson(p.high) +
                       R"(, "low": )" + geometryJson(p.low) +
                       R"(, "roles": {"stiff": "stiff-beam", "soft": "soft-beam"})";
    if (withScales) {
        char scales[300];
        std::snprintf(scales, sizeof scales,
                      R"(, "channels": {"stiff": {"unit": "N", "counts_per_unit": %.17g, "full_scale": 32768},)"
                      R"( "soft": {"unit": "N", "counts_per_unit": %.17g, "full_scale": 32768},)"
                      R"( "d": {"unit": "mm"}})",
                      tactiscope::testing::countsPerNewton(p.high, p), tactiscope::testing::countsPerNewton(p.low, p));
        json += scales;
    }
    return json + "}";
}

}  // namespace

TEST(TextBoardUnitsCli, APalpationBoardsCountsAreReadThroughItsProfilesScaleAndItsClippedPressesFlagged)
{
    const PalpationBoard printed = palpationBoard();
    const auto& p = printed.parameters;
    QTemporaryDir dir;
    const QString link = dir.filePath(QStringLiteral("board"));
    TextBoard board(link.toStdString(),
                    TextBoardOptions{p.sampleRate_hz,
                                     [&](std::uint64_t n) { return printed.lines[n % printed.lines.size()]; }, 4, 2e-3,
                                     true});
    ASSERT_TRUE(board.ok());
    const QString db = dir.filePath(QStringLiteral("clinic.tactiscope"));
    // A gauge-factor calibration of the probe's beams waits in the store:
    // counts read through the profile's scale never go through it.
    core::calibration::CalibrationRecord waiting;
    waiting.kind = core::calibration::kGaugeFactorKind;
    waiting.sensorName = core::calibration::beamSensorName("maker probe", true);
    waiting.operatorName = "tester";
    waiting.timestampUtc = "2026-11-20T08:00:00Z";
    waiting.values = {{"gauge_factor", 2.2}};
    core::storage::SessionStore(db.toStdString()).addCalibration(waiting);
    const auto record = [&](bool withScales, const QString& seconds) {
        const QString profile = dir.filePath(withScales ? QStringLiteral("scaled.json") : QStringLiteral("bare.json"));
        tactiscope::testing::writeText(profile, QString::fromStdString(profileJson(p, withScales)));
        return runCli({"record", "--port", link, "--protocol", "text", "--rate", "200", "--mode", "palpation",
                       "--profile", profile, "--seconds", seconds, "--db", db});
    };

    // Without a scale, counts are no force: refused, naming the beam.
    const CliResult bare = record(false, QStringLiteral("1"));
    EXPECT_EQ(bare.exitCode, 2);
    EXPECT_TRUE(bare.err.contains(QStringLiteral("stiff plays stiff-beam but is a plain number (no unit)")))
        << bare.err.toStdString();
    EXPECT_TRUE(bare.err.contains(QStringLiteral("sensor profile's \"channels\""))) << bare.err.toStdString();

    // A unit given for a beam the profile scales replaces the scale: said.
    const QString scaledProfile = dir.filePath(QStringLiteral("scaled.json"));
    tactiscope::testing::writeText(scaledProfile, QString::fromStdString(profileJson(p, true)));
    const CliResult overridden = runCli({"record", "--port", link, "--protocol", "text", "--rate", "200", "--mode",
                                         "palpation", "--profile", scaledProfile, "--units", "stiff=mN", "--seconds",
                                         "1", "--db", dir.filePath(QStringLiteral("other.tactiscope"))});
    EXPECT_TRUE(overridden.err.contains(QStringLiteral("--units stiff=mN: the profile scales stiff's counts")))
        << overridden.err.toStdString();

    const CliResult run = record(true, QStringLiteral("24"));
    ASSERT_EQ(run.exitCode, 0) << run.err.toStdString();
    core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto id = sessionIdIn(run.out);
    ASSERT_GT(id, 0) << run.out.toStdString();
    EXPECT_EQ(store.channels(id)[0].descriptor.unit, "counts");  // the board's raw readings, kept as sent
    EXPECT_EQ(store.channels(id)[2].descriptor.unit, "counts");  // millimetres as printed, read through the profile
    // Listed with the scale they are read through, not as bare counts.
    const CliResult shown = runCli({"sessions", "show", QString::number(id), "--db", db});
    EXPECT_TRUE(shown.out.contains(QStringLiteral("d [counts, read as mm]"))) << shown.out.toStdString();
    EXPECT_TRUE(shown.out.contains(QStringLiteral("stiff [counts, ") +
                                   QString::number(tactiscope::testing::countsPerNewton(p.high, p), 'g', 6) +
                                   QStringLiteral(" a N] as stiff-beam")))
        << shown.out.toStdString();

    // The presses the board printed in the recording, from its samples (the
    // millimetres as printed): a run of displacement beyond 0.5 mm; clipped
    // where the stiff beam came within 1 % of the declared full scale.
    const auto count = store.sampleCount(id);
    const auto stiff = store.readChannel(id, 0, 0, count), depth = store.readChannel(id, 2, 0, count);
    int presses = 0, clipped = 0;
    bool pressing = false, atLimit = false;
    for (std::size_t i = 0; i < count; ++i) {
        const bool in = depth[i] > 0.5;
        if (in) atLimit = atLimit || std::abs(stiff[i]) >= 0.99 * 32768.0;
        if (pressing && !in && i > 0) {
            ++presses;
            clipped += atLimit ? 1 : 0;
        }
        if (!in) atLimit = false;
        pressing = in;
    }
    ASSERT_GE(clipped, 1);
    ASSERT_GE(presses - clipped, 3);
    const auto readings = store.readings(id);
    // Each reading is listed by `sessions show` with its value and unit.
    for (const auto& reading : readings)
        EXPECT_TRUE(shown.out.contains(QStringLiteral("stiffness %1 ± ").arg(reading.value, 0, 'g', 6)))
            << reading.value << "\n"
            << shown.out.toStdString();
    // Every press that ended in the recording and did not clip is read (the
    // first may have begun before it); none that clipped is.
    EXPECT_GE(static_cast<int>(readings.size()), presses - clipped - 1);
    EXPECT_LE(static_cast<int>(readings.size()), presses - clipped);
    // Each clipped press is said in the record, and at the end, as one that
    // gave no reading: not to be taken for a press never made.
    const auto events = store.events(id);
    const auto clippedNotes = std::ranges::count_if(events, [](const core::storage::SessionEvent& event) {
        return event.note.find("reached a beam's converter limit: no reading") != std::string::npos;
    });
    EXPECT_GE(clippedNotes, clipped - 1);
    EXPECT_LE(clippedNotes, clipped);
    EXPECT_TRUE(run.out.contains(QStringLiteral("gave none (clipped or out of the probe's range")))
        << run.out.toStdString();
    // Read through the scale as a probe's chain reads: true within their
    // uncertainty. The presses share one zero, so a recording is one draw
    // of its error (here all six lie 0.2–2.2 u above); the coverage of ±u
    // over many recordings is ComplianceRangeCli's. A wrong scale would be
    // off by far more.
    for (const auto& reading : readings) {
        ASSERT_TRUE(reading.standardError.has_value());
        // The displacement read through the profile's "mm": the press's
        // deepest point in metres, within the depths the board pressed to.
        const double deepest_m = QJsonDocument::fromJson(QByteArray::fromStdString(reading.detailsJson))
                                     .object()[QStringLiteral("displacement_max_m")]
                                     .toDouble();
        EXPECT_GT(deepest_m, 2e-3) << reading.detailsJson;
        EXPECT_LT(deepest_m, 1e-2) << reading.detailsJson;
        EXPECT_LE(std::abs(reading.value - p.objectStiffness_n_per_m), 3.0 * *reading.standardError)
            << reading.value << " ± " << *reading.standardError;
    }

    // The calibration waiting in the store was not applied, so it is not
    // recorded as used.
    EXPECT_TRUE(store.calibrationsOfSession(id).empty());
    EXPECT_TRUE(core::calibration::recordsFromJsonArray(store.session(id)->metadata.calibrationsJson).empty());
}

namespace {

// A force board printing mN: a ramp 0…4.9 mN repeating each second.
std::string forceLine(std::uint64_t n)
{
    return "force:" + std::to_string(0.1 * static_cast<double>(n % 50)) + "\n";
}

}  // namespace

// The seams: units given per device in a session of several, and a
// trigger and limits on a board's channel in the unit it was given (mN),
// read in SI (N) as a probe's are.
TEST(TextBoardUnitsCli, EachDeviceOfASessionTakesItsOwnUnitsAndATriggerAndLimitsReadThemInSi)
{
    QTemporaryDir dir;
    const QString left = dir.filePath(QStringLiteral("left")), right = dir.filePath(QStringLiteral("right"));
    TextBoard leftBoard(left.toStdString(), TextBoardOptions{50.0, forceLine, 1, 1e-3, false});
    TextBoard rightBoard(right.toStdString(), TextBoardOptions{50.0, plainLine, 1, 1e-3, false});
    ASSERT_TRUE(leftBoard.ok() && rightBoard.ok());
    const QString db = dir.filePath(QStringLiteral("bench.tactiscope"));

    const CliResult unnamed = runCli({"record", "--port", "l=" + left, "--port", "r=" + right, "--protocol", "text",
                                      "--rate", "50", "--seconds", "1", "--db", db, "--units", "force=mN"});
    EXPECT_EQ(unnamed.exitCode, 2);
    EXPECT_TRUE(unnamed.err.contains(QStringLiteral("--units: with several devices, name each channel as "
                                                    "DEVICE/CHANNEL")))
        << unnamed.err.toStdString();
    const CliResult noSuchDevice = runCli({"record", "--port", "l=" + left, "--port", "r=" + right, "--protocol",
                                           "text", "--rate", "50", "--seconds", "1", "--db", db, "--units", "c/a=mN"});
    EXPECT_EQ(noSuchDevice.exitCode, 2);
    EXPECT_TRUE(noSuchDevice.err.contains(QStringLiteral("--units: no port is named 'c'")))
        << noSuchDevice.err.toStdString();

    const CliResult both = runCli({"record", "--port", "l=" + left, "--port", "r=" + right, "--protocol", "text",
                                   "--rate", "50", "--seconds", "1.5", "--db", db, "--units", "l/force=mN,r/a=µε"});
    ASSERT_EQ(both.exitCode, 0) << both.err.toStdString();
    {
        core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
        const auto parts = store.parts(sessionIdIn(both.out));
        ASSERT_EQ(parts.size(), 2u);
        for (const auto& part : parts) {
            const auto channels = store.channels(part.id);
            if (part.deviceName == "l") {
                EXPECT_EQ(channels[0].descriptor, (core::ChannelDescriptor{"force", "N", core::ChannelKind::Force}));
            } else {
                EXPECT_EQ(channels[0].descriptor, (core::ChannelDescriptor{"a", "", core::ChannelKind::Strain}));
                EXPECT_EQ(channels[1].descriptor, (core::ChannelDescriptor{"b", "", core::ChannelKind::Other}));
            }
        }
    }

    // A trigger at 3 mN and a critical limit at 4 mN, both written in N.
    const QString triggered = dir.filePath(QStringLiteral("triggered.tactiscope"));
    const CliResult watched = runCli({"record",
                                      "--port",
                                      left,
                                      "--protocol",
                                      "text",
                                      "--rate",
                                      "50",
                                      "--seconds",
                                      "4",
                                      "--db",
                                      triggered,
                                      "--units",
                                      "force=mN",
                                      "--trigger",
                                      "force>0.003",
                                      "--pre",
                                      "0.1",
                                      "--post",
                                      "0.1",
                                      "--sessions",
                                      "1",
                                      "--limit",
                                      "force>warning:0.0035,critical:0.004"});
    ASSERT_EQ(watched.exitCode, 0) << watched.err.toStdString();
    core::storage::SessionStore store(triggered.toStdString(), core::storage::Database::Access::ReadOnly);
    ASSERT_EQ(store.sessions().size(), 1u);
    const auto id = store.sessions().front().id;
    const auto force = store.readChannel(id, 0, 0, store.sampleCount(id));
    ASSERT_FALSE(force.empty());
    EXPECT_GT(*std::ranges::max_element(force), 0.003);  // the trigger's crossing is in it, in N
    EXPECT_LT(*std::ranges::max_element(force), 0.005);
    std::size_t critical = 0;
    for (const auto& event : store.events(id))
        if (event.kind == core::EventKind::Alarm && event.note.find("critical") != std::string::npos) ++critical;
    EXPECT_GE(critical, 1u);
}

// A capacitive board that prints its converter's counts, 100,000 a
// picofarad and 1,000,000 at none: with its profile's scale the capacitive
// mode takes it, the counts are stored as sent, and the review reads them
// as the capacitance they are (a load of 1 pF is 1 pF of ΔC; the baseline
// the tare took is a capacitance the board printed). Without the scale the
// mode refuses, naming the channel.
TEST(TextBoardUnitsCli, ACapacitiveBoardsCountsAreReadThroughItsProfilesScale)
{
    // 51.44 pF at rest and 52.44 pF loaded, by turns of half a second.
    const auto picofarads = [](std::uint64_t n) { return 51.44 + ((n / 25) % 2 == 1 ? 1.0 : 0.0); };
    QTemporaryDir dir;
    const QString link = dir.filePath(QStringLiteral("beam"));
    TextBoard board(link.toStdString(), TextBoardOptions{50.0,
                                                         [&](std::uint64_t n) {
                                                             const auto counts =
                                                                 std::llround(1e6 + 1e5 * picofarads(n));
                                                             return "c:" + std::to_string(counts) + "\r\n";
                                                         },
                                                         1, 1e-3, false});
    ASSERT_TRUE(board.ok());
    std::string profile = core::sensors::toJson(*core::sensors::builtInProfile(core::Mode::Capacitive));
    const QString bare = dir.filePath(QStringLiteral("bare.json")),
                  scaled = dir.filePath(QStringLiteral("scaled.json"));
    tactiscope::testing::writeText(bare, QString::fromStdString(profile));
    profile.insert(profile.rfind('}'), R"(, "channels": {"c": {"unit": "pF", "counts_per_unit": 1e5, "offset": 1e6}})");
    tactiscope::testing::writeText(scaled, QString::fromStdString(profile));
    const QString db = dir.filePath(QStringLiteral("beam.tactiscope"));
    const auto record = [&](const QString& withProfile) {
        return runCli({"record", "--port", link, "--protocol", "text", "--rate", "50", "--mode", "capacitive",
                       "--profile", withProfile, "--seconds", "3", "--db", db});
    };

    const CliResult refused = record(bare);
    EXPECT_EQ(refused.exitCode, 2);
    EXPECT_TRUE(refused.err.contains(QStringLiteral("no channel plays capacitance"))) << refused.err.toStdString();

    const CliResult recorded = record(scaled);
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err.toStdString();
    core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto id = sessionIdIn(recorded.out);
    const auto channels = store.channels(id);
    ASSERT_EQ(channels.size(), 1u);
    EXPECT_EQ(channels[0].descriptor.unit, "counts");
    const std::uint64_t count = store.sampleCount(id);
    // --seconds 3 at 50 Hz: 150 samples, counted from the recording's start
    // (the capacitive profile's setup after the connection, tenths of a
    // second, was recorded and counted on top: 8.37 s for --seconds 8).
    EXPECT_NEAR(static_cast<double>(count), 150.0, 3.0);
    const auto sent = store.readChannel(id, 0, 0, count);
    core::derived::CapacitiveChannels review(store, id, std::nullopt);
    const auto derived = review.read(0, count);
    for (const auto& [first, c0_f] : review.baselines()) {
        EXPECT_GE(c0_f, 51.44e-12 - 1e-17);
        EXPECT_LE(c0_f, 52.44e-12 + 1e-17);
    }
    // Each sample's ΔC is its own capacitance over its baseline's: counts
    // the board sent through the scale, to the float's precision.
    const auto baselines = review.baselines();
    std::size_t loaded = 0, rest = 0;
    for (std::uint64_t s = 0; s < count; ++s) {
        const auto on = std::ranges::find_if(baselines.rbegin(), baselines.rend(),
                                             [s](const auto& baseline) { return baseline.first <= s; });
        ASSERT_NE(on, baselines.rend());
        const double capacitance_f = (sent[s] - 1e6) / 1e5 * 1e-12;
        ASSERT_NEAR(derived[0][s], capacitance_f - on->second, 1e-18) << s;
        (std::abs(capacitance_f - 52.44e-12) < 1e-16 ? loaded : rest) += 1;
    }
    EXPECT_GT(loaded, 40u);
    EXPECT_GT(rest, 40u);
}
