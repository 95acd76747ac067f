// A palpation recorded from the emulator, its presses read again by
// core/derived/PalpationReanalysis: with the session's own profile and
// calibrations they are the recorded readings (the same code on the same
// counts, which binary32 stores exactly); with the stiff beam's gauge
// factor 5 % higher each k_o follows eq. 2 at Q / 1.05 (F ∝ 1/GF, so
// Q = F_H/F_L scales by GF_L/GF_H), with the beams' stiffnesses computed
// here from the profile (k = E·w·t³ / (4·L³)); saved under a name, the
// readings are an analysis of their own that an export and import carry
// and `report --analysis` reports.
#include "core/derived/PalpationReanalysis.h"
#include "core/calibration/CalibrationRecord.h"
#include "core/sensors/SensorProfile.h"
#include "core/storage/SessionStore.h"
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"
#include "support/PdfText.h"

#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <cmath>

using namespace tactiscope;
using tactiscope::testing::runCli;

namespace {

double beamStiffness(const core::sensors::CantileverGeometry& g)
{
    return g.youngsModulus_pa * g.width_m * std::pow(g.thickness_m, 3) / (4.0 * std::pow(g.length_m, 3));
}

}  // namespace

TEST(PalpationReanalysis, TheSessionsOwnBasisGivesTheRecordedReadingsAndAnotherGaugeFactorMovesQ)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("clinic.tactiscope");
    const auto recorded =
        tactiscope::testing::recordEmulated(dir.path(), db, "palpation", 8, {"--site", "C4", "--subject", "phantom"});
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err.toStdString();
    core::storage::SessionStore store(db.toStdString());
    const auto summary = *store.session(1);
    const auto probe = std::get<core::sensors::CompliancePairProfile>(
        core::sensors::parseSensorProfile(summary.metadata.profileJson, "the session's"));
    const auto calibrations = core::calibration::recordsFromJsonArray(summary.metadata.calibrationsJson);
    const auto live = store.readings(1);
    ASSERT_GE(live.size(), 2u);

    const auto same = core::derived::reanalysePalpation(store, 1, probe, calibrations);
    ASSERT_EQ(same.readings.size(), live.size());
    for (std::size_t i = 0; i < live.size(); ++i) {
        EXPECT_NEAR(same.readings[i].start_s, live[i].start_s, 1e-9) << i;
        EXPECT_NEAR(same.readings[i].end_s, live[i].end_s, 1e-9) << i;
        EXPECT_NEAR(same.readings[i].value, live[i].value, 1e-9 * live[i].value) << i;
        EXPECT_NEAR(*same.readings[i].standardError, *live[i].standardError, 1e-6 * *live[i].standardError) << i;
        EXPECT_EQ(same.readings[i].site, "C4");
    }

    // The stiff beam's gauge factor 5 % above the nominal one the session used.
    ASSERT_TRUE(calibrations.empty()) << "the emulated session reads through the nominal gauge factors";
    core::calibration::CalibrationRecord stiff;
    stiff.kind = core::calibration::kGaugeFactorKind;
    stiff.sensorName = core::calibration::beamSensorName(probe.name, true);
    stiff.timestampUtc = "2026-11-23T09:00:00Z";
    stiff.values = {{"gauge_factor", 2.0 * 1.05}};  // nominal: 2
    const auto moved = core::derived::reanalysePalpation(store, 1, probe, {stiff});
    EXPECT_NE(moved.basis.find("stiff beam gauge factor 2.1 (calibrated)"), std::string::npos) << moved.basis;
    ASSERT_EQ(moved.readings.size(), live.size());
    const double kh = beamStiffness(probe.high), kl = beamStiffness(probe.low);
    for (std::size_t i = 0; i < live.size(); ++i) {
        // Q from the recorded k_o (eq. 2 inverted), scaled, and k_o again.
        const double k = live[i].value;
        const double q = (k * kh + kh * kl) / (kh * kl + k * kl);
        const double q2 = q / 1.05;
        const double expected = kh * kl * (q2 - 1.0) / (kh - q2 * kl);
        EXPECT_NEAR(moved.readings[i].value, expected, 0.01 * expected) << i;
        EXPECT_LT(moved.readings[i].value, k) << i;
    }

    // Saved, it is an analysis of its own; the recorded readings stay.
    auto saved = moved.readings;
    for (auto& r : saved) r.analysis = "GF 2.1 high";
    store.addReadings(1, saved);
    EXPECT_EQ(store.readings(1).size(), live.size());
    EXPECT_EQ(store.readings(1, "GF 2.1 high").size(), live.size());
    const auto analyses = store.analyses(1);
    EXPECT_NE(std::ranges::find(analyses, "GF 2.1 high"), analyses.end());

    // An export and import carry it.
    const QString csv = dir.filePath("s.csv");
    ASSERT_EQ(runCli({"sessions", "--db", db, "export", "1", "--format", "csv", "--output", csv}).exitCode, 0);
    const QString copy = dir.filePath("copy.tactiscope");
    const auto imported = runCli({"import", csv, "--db", copy});
    ASSERT_EQ(imported.exitCode, 0) << imported.err.toStdString();
    core::storage::SessionStore copied(copy.toStdString(), core::storage::Database::Access::ReadOnly);
    EXPECT_EQ(copied.readings(1).size(), live.size());
    ASSERT_EQ(copied.readings(1, "GF 2.1 high").size(), live.size());
    EXPECT_EQ(copied.readings(1, "GF 2.1 high")[0].value, saved[0].value);

    if (*tactiscope::testing::pdfTextMissing()) GTEST_SKIP() << tactiscope::testing::pdfTextMissing();
    const QString pdf = dir.filePath("r.pdf");
    const auto report = runCli({"report", "--db", db, "--session", "1", "--analysis", "GF 2.1 high", "--output", pdf});
    ASSERT_EQ(report.exitCode, 0) << report.err.toStdString();
    const QString text = tactiscope::testing::pdfText(pdf);
    EXPECT_TRUE(text.contains("From the saved re-analysis \"GF 2.1 high\"")) << text.toStdString();
}
