// Devices at different sample rates on one clock (issue 55): four
// `tactiscope-cli emulate` processes behind real ptys, load cells at 10,
// 100, 500 and 1,000 Hz (the slow one one sample per frame, 80 ppm slow;
// the 500 Hz one 100 ppm fast with its clock at 0.5 s), all marking one
// instant of the host's steady clock, recorded by one `record` into one
// session. Each mark is found in the exported samples alone (a line through
// its ramp), on the session's axis. Before TSP/1 said what a frame's time
// means, the emulator sent each frame a sample period after its last
// sample while the host took its arrival for that sample's: the marks lay
// apart by the difference of the periods (99 ms between 10 and 1,000 Hz)
// while stating ±0.016 ms. Now they must agree within 0.5 ms, and within
// twice their stated relative uncertainty, which holds a sample period of
// each device (where within its period a sample is taken, no arrival tells).
#include "devices/SteadyClock.h"
#include "support/CliRunner.h"
#include "support/ClockMarks.h"
#include "support/EmulatorProcess.h"

#include "core/storage/SessionStore.h"
#include "core/timing/ClockMappingJson.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <vector>

using tactiscope::testing::markTime_s;
using tactiscope::testing::roughMark_s;
using tactiscope::testing::runCli;
using tactiscope::testing::sessionIdIn;
using tactiscope::testing::startEmulator;
using tactiscope::testing::stopEmulator;

namespace {

struct Device {
    const char* name;
    double rate_hz;
    QStringList extra;
};

std::vector<double> numbers(const QJsonArray& array)
{
    std::vector<double> values;
    values.reserve(static_cast<std::size_t>(array.size()));
    for (const auto& v : array) values.push_back(v.toDouble());
    return values;
}

}  // namespace

TEST(ClocksAcrossRatesCli, DevicesAtTenToAThousandHertzMarkOneInstantWithinHalfAMillisecondAndTheirStatedUncertainty)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("s.tactiscope");
    const double launched = tactiscope::devices::steadySeconds();
    const QString mark = QString::number(launched + 26.0, 'f', 6);
    const std::array<Device, 4> devices{
        Device{"slow", 10.0, {"--samples-per-frame", "1", "--drift-ppm", "80"}},
        Device{"mid", 100.0, {}},
        Device{"fast", 500.0, {"--drift-ppm", "-100", "--clock-offset", "0.5"}},
        Device{"fastest", 1000.0, {}},
    };
    std::array<std::unique_ptr<QProcess>, 4> emulators;
    QStringList record{"record"};
    for (std::size_t i = 0; i < devices.size(); ++i) {
        emulators[i] = std::make_unique<QProcess>();
        const QString link = dir.filePath(QString::fromLatin1(devices[i].name));
        ASSERT_TRUE(startEmulator(*emulators[i], link,
                                  QStringList{"--scenario", "load-cell", "--seed", QString::number(i + 1), "--rate",
                                              QString::number(devices[i].rate_hz), "--mark-at", mark} +
                                      devices[i].extra));
        record << "--port" << QString::fromLatin1(devices[i].name) + "=" + link;
    }
    const auto recorded = runCli(record + QStringList{"--seconds", "45", "--db", db});
    for (auto& emulator : emulators) stopEmulator(*emulator);
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err.toStdString();
    const auto session = sessionIdIn(recorded.out);
    ASSERT_GT(session, 0) << recorded.out.toStdString();

    // Each part's clock states its sample period and a ±.
    std::array<tactiscope::core::timing::ClockMapping, 4> clocks;
    {
        tactiscope::core::storage::SessionStore store(db.toStdString(),
                                                      tactiscope::core::storage::Database::Access::ReadOnly);
        const auto parts = store.parts(session);
        ASSERT_EQ(parts.size(), devices.size());
        for (std::size_t i = 0; i < devices.size(); ++i) {
            ASSERT_EQ(parts[i].deviceName, devices[i].name);
            const auto clock = tactiscope::core::timing::clockMappingFromJson(parts[i].clockJson);
            ASSERT_TRUE(clock && clock->uncertainty_s(0.0)) << parts[i].clockJson;
            EXPECT_NEAR(clock->samplePeriod_s, 1.0 / devices[i].rate_hz, 1e-9) << devices[i].name;
            clocks[i] = *clock;
        }
    }

    const QString exported = dir.filePath("x.json");
    ASSERT_EQ(
        runCli({"sessions", "--db", db, "export", QString::number(session), "--format", "json", "--output", exported})
            .exitCode,
        0);
    QFile file(exported);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const auto samples = QJsonDocument::fromJson(file.readAll()).object().value(QStringLiteral("samples")).toObject();
    // Where the mark lies roughly, from the fastest device's samples.
    std::array<double, 4> marks{};
    const auto rough = roughMark_s(numbers(samples.value("fastest").toObject().value("t").toArray()),
                                   numbers(samples.value("fastest").toObject().value("force").toArray()));
    ASSERT_TRUE(rough) << "the mark was not recorded";
    for (std::size_t i = 0; i < devices.size(); ++i) {
        const auto device = samples.value(QString::fromLatin1(devices[i].name)).toObject();
        const double halfWidth_s = tactiscope::devices::simulator::markHalfWidth_s(devices[i].rate_hz);
        const auto found = markTime_s(numbers(device.value("t").toArray()), numbers(device.value("force").toArray()),
                                      *rough, halfWidth_s);
        ASSERT_TRUE(found) << devices[i].name;
        marks[i] = found->t_s;
        std::printf("%s (%g Hz): mark at %.6f s, ± %.3f ms\n", devices[i].name, devices[i].rate_hz, marks[i],
                    *clocks[i].uncertainty_s(0.0) * 1e3);
    }
    for (std::size_t i = 0; i < devices.size(); ++i)
        for (std::size_t j = i + 1; j < devices.size(); ++j) {
            const double apart = marks[i] - marks[j];
            const auto u = tactiscope::core::timing::relativeUncertainty_s(clocks[i], clocks[j], 0.0, 45.0);
            ASSERT_TRUE(u);
            EXPECT_LE(std::abs(apart), 0.5e-3) << devices[i].name << " and " << devices[j].name;
            EXPECT_LE(std::abs(apart), 2.0 * *u) << devices[i].name << " and " << devices[j].name;
            std::printf("%s − %s: %+.1f µs (relative ± %.3f ms)\n", devices[i].name, devices[j].name, apart * 1e6,
                        *u * 1e3);
        }
}
