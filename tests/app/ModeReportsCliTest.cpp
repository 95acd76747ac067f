// `tactiscope-cli report` speaks each mode's language: a palpation recorded
// from the emulator lists its presses with site, k_o ± u and depth (from
// the stored readings), sums the site up and draws the site map and the
// tissue scale; a capacitive one recorded through a stored calibration
// heads with its peak force and deflection instead of "No verdict
// recorded", and states its baseline C0 and the calibration's fit
// (sensitivity ± SE, R², detection limit in µN and mgf). The first page of
// each is rendered to PNG for a look.
#include "core/calibration/CalibrationRecord.h"
#include "core/capacitive/CapacitiveReadout.h"
#include "core/sensors/BuiltInProfiles.h"
#include "core/storage/SessionStore.h"
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"
#include "support/PdfText.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>
#include <QRegularExpression>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace tactiscope;
using tactiscope::testing::pdfText;
using tactiscope::testing::runCli;

namespace {

QString reportText(const QString& db, const QString& pdf)
{
    const auto result = runCli({"report", "--db", db, "--session", "last", "--output", pdf});
    EXPECT_EQ(result.exitCode, 0) << result.err.toStdString();
    return pdfText(pdf);
}

}  // namespace

TEST(ModeReportsCli, APalpationReportListsItsPressesBySiteWithTheMapAndTheScale)
{
    if (*tactiscope::testing::pdfTextMissing()) GTEST_SKIP() << tactiscope::testing::pdfTextMissing();
    QTemporaryDir dir;
    const QString db = dir.filePath("clinic.tactiscope");
    const auto recorded =
        tactiscope::testing::recordEmulated(dir.path(), db, "palpation", 8, {"--site", "B2", "--subject", "phantom-1"});
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err.toStdString();
    const QString pdf = dir.filePath("palpation.pdf");
    const QString text = reportText(db, pdf);
    ASSERT_FALSE(text.isEmpty());

    core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
    const auto readings = store.readings(1);
    ASSERT_GE(readings.size(), 2u);
    const QLocale locale;
    EXPECT_TRUE(text.contains(QStringLiteral("Presses (%1)").arg(readings.size()))) << text.toStdString();
    for (const auto& r : readings) {
        ASSERT_TRUE(r.standardError);
        // The uncertainty to two significant digits (at most six decimals), the value to its place.
        const int decimals = std::clamp(1 - static_cast<int>(std::floor(std::log10(*r.standardError))), 0, 6);
        const QString value =
            locale.toString(r.value, 'f', decimals) + " ± " + locale.toString(*r.standardError, 'f', decimals);
        EXPECT_TRUE(text.contains(value)) << value.toStdString();
        const QJsonObject details = QJsonDocument::fromJson(QByteArray::fromStdString(r.detailsJson)).object();
        const QString depth = locale.toString(details["displacement_min_m"].toDouble() * 1e3, 'f', 2) + " – " +
                              locale.toString(details["displacement_max_m"].toDouble() * 1e3, 'f', 2);
        EXPECT_TRUE(text.contains(depth)) << depth.toStdString();
    }
    for (const char* expected : {"By site", "Site map and tissue scale", "Computed from", "gauge factor"})
        EXPECT_TRUE(text.contains(QString::fromUtf8(expected))) << expected << "\n" << text.toStdString();
    EXPECT_FALSE(text.contains("Defect")) << "a palpation has no defects to speak of";
    EXPECT_TRUE(tactiscope::testing::savePdfFirstPage(pdf, QStringLiteral("report-palpation-page1")));
}

TEST(ModeReportsCli, ACapacitiveReportStatesItsBaselineAndTheCalibrationsFit)
{
    if (*tactiscope::testing::pdfTextMissing()) GTEST_SKIP() << tactiscope::testing::pdfTextMissing();
    QTemporaryDir dir;
    const QString db = dir.filePath("lab.tactiscope");
    const auto profile =
        std::get<core::sensors::CapacitiveBeamProfile>(*core::sensors::builtInProfile(core::Mode::Capacitive));
    core::calibration::CalibrationRecord record;
    record.kind = core::calibration::kCapacitiveKind;
    record.sensorName = profile.name;
    record.operatorName = "Grace";
    record.timestampUtc = "2026-11-20T10:00:00Z";
    // The beam's own C0 (the model's), so the readings before the first tare are the beam's.
    const auto model =
        core::capacitive::CapacitiveSensitivity::fromModel(core::sensors::CapacitiveBeam(profile.geometry));
    record.values = {{"c0_pf", model.c0_f * 1e12},      {"baseline_sigma_pf", 0.0038}, {"drift_pf_per_s", 0.00012},
                     {"sensitivity_pf_per_mn", 0.5678}, {"r_squared", 0.99931},        {"detection_limit_mn", 0.02008}};
    record.fit.slope = 0.5678e-9;
    record.fit.rSquared = 0.99931;
    record.fit.slopeStandardError = 0.0042e-9;
    record.fit.points = 6;
    core::storage::SessionStore(db.toStdString()).addCalibration(record);
    // At 100 Hz (the beam's converter at its fastest), so six seconds give
    // a noise floor's spectrum too.
    const auto recorded = tactiscope::testing::recordEmulated(dir.path(), db, "capacitive-weights", 6,
                                                              {"--subject", "beam-1"}, {"--rate", "100"});
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err.toStdString();
    const QString pdf = dir.filePath("capacitive.pdf");
    const QString text = reportText(db, pdf);
    ASSERT_FALSE(text.isEmpty());

    const QLocale locale;
    EXPECT_FALSE(text.contains("No verdict recorded")) << text.toStdString();
    for (const QString& expected :
         {QStringLiteral("Peak tip force"), QStringLiteral("Capacitive beam"), QStringLiteral("pF at the start"),
          QStringLiteral("2026-11-20T10:00:00Z by Grace"),
          locale.toString(0.5678, 'f', 4) + " ± " + locale.toString(0.0042, 'f', 4) + " pF/mN",
          QStringLiteral("R² = ") + locale.toString(0.99931, 'f', 5) + ", 6 points",
          // 0.02008 mN is 20.08 µN, and 20.08 µN / 9.80665 µN per mgf is 2.05 mgf: three digits
          // each, as the wizard says it.
          locale.toString(20.1, 'f', 1) + " µN (" + locale.toString(2.05, 'f', 2) + " mgf)"})
        EXPECT_TRUE(text.contains(expected)) << expected.toStdString() << "\n" << text.toStdString();
    // The calibration record in words (issue 37): before, "baseline_sigma_pf = 0.0038, c0_pf = …".
    for (const char* label :
         {"Baseline noise σ 0.0038 pF", "Baseline drift 0.00012 pF/s", "Detection limit (3σ) 20.1 µN"})
        EXPECT_TRUE(text.contains(QString::fromUtf8(label))) << label << "\n" << text.toStdString();
    for (const char* key : {"c0_pf", "baseline_sigma_pf", "drift_pf_per_s", "detection_limit_mn", "r_squared"})
        EXPECT_FALSE(text.contains(QString::fromLatin1(key))) << key;
    // Signal quality (issue 57): the beam's detection limit from this
    // recording's noise floor beside the calibration's. The emulated beam's
    // noise is white, σ = 4 fF, so its floor over the sampled band gives
    // 3σ/S = 3 × 4 fF / 0.5678 pF/mN = 21.1 µN (the median's bias and the
    // steps' edges within a few per cent).
    EXPECT_TRUE(text.contains("Signal quality")) << text.toStdString();
    const QRegularExpression limits(QStringLiteral("Detection limit \\(3σ/S\\)\\s+([0-9.,]+) µN from this "
                                                   "recording's noise"));
    const auto found = limits.match(QString(text).replace(QLatin1Char('\n'), QLatin1Char(' ')));
    ASSERT_TRUE(found.hasMatch()) << text.toStdString();
    EXPECT_NEAR(locale.toDouble(found.captured(1)), 3.0 * 4e-15 / 0.5678e-9 * 1e6, 2.5)
        << found.captured(0).toStdString();
    // Six seconds of the unloaded start hold no load step: its creep is
    // said to be none told from the noise, not a number.
    EXPECT_TRUE(text.contains("Creep after a load step (capacitance)")) << text.toStdString();
    EXPECT_TRUE(text.contains("none told from the noise")) << text.toStdString();
    EXPECT_TRUE(tactiscope::testing::savePdfFirstPage(pdf, QStringLiteral("report-capacitive-page1")));
}
