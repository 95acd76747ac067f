// The calibration history on a real store: three gauge-factor calibrations
// of one beam half a year apart (2.10, 2.12, 2.14: mean 2.12, SD 0.02,
// +1.90 % from the first, 0.04 per year, by hand) and one of a capacitive
// beam; a session linked to the middle one.
#include "ui/calibration/CalibrationHistory.h"

#include "core/storage/SessionStore.h"
#include "support/MainWindowHelpers.h"
#include "support/Screenshot.h"
#include "support/TempDirectory.h"

#include <QDateTime>
#include <QLabel>
#include <QListWidget>
#include <QTableWidget>

#include <gtest/gtest.h>

using namespace tactiscope;
using tactiscope::testing::child;

namespace {

const char* kBeam = "Perspex probe — stiff beam";

core::calibration::CalibrationRecord record(const char* kind, const char* sensor, const char* when,
                                            std::vector<std::pair<std::string, double>> values)
{
    core::calibration::CalibrationRecord r;
    r.kind = kind;
    r.sensorName = sensor;
    r.operatorName = "Ada";
    r.timestampUtc = when;
    r.values = std::move(values);
    r.fit.points = 5;
    r.fit.rSquared = 0.99999;
    return r;
}

class CalibrationHistoryTest : public tactiscope::testing::TempDirectoryTest {
protected:
    void SetUp() override
    {
        TempDirectoryTest::SetUp();
        core::storage::SessionStore store(file("s.tactiscope"));
        // Half a year is 182.625 days: 182 days and 15 hours.
        store.addCalibration(record("gauge_factor", kBeam, "2026-01-01T00:00:00Z",
                                    {{"gauge_factor", 2.10}, {"gauge_factor_standard_error", 0.002}}));
        m_middle = store.addCalibration(record("gauge_factor", kBeam, "2026-07-02T15:00:00Z",
                                               {{"gauge_factor", 2.12}, {"gauge_factor_standard_error", 0.003}}));
        store.addCalibration(record("gauge_factor", kBeam, "2027-01-01T06:00:00Z",
                                    {{"gauge_factor", 2.14}, {"gauge_factor_standard_error", 0.002}}));
        store.addCalibration(record("capacitive", "Beam No. 1", "2026-11-20T10:00:00Z",
                                    {{"sensitivity_pf_per_mn", 1.8}, {"c0_pf", 51.44}}));
        core::storage::SessionMetadata metadata;
        metadata.mode = tactiscope::core::Mode::Palpation;
        metadata.subject = "phantom-3";
        const std::vector<core::ChannelDescriptor> channels{{"high", "count", core::ChannelKind::Other}};
        const auto session = store.beginSession(metadata, channels, 100.0);
        store.endSession(session, tactiscope::core::SessionStatus::Complete);
        store.linkCalibration(session, m_middle);
    }

    std::int64_t m_middle = 0;
};

}  // namespace

TEST_F(CalibrationHistoryTest, ShowsEachSensorsRecordsDriftAndTheSessionsThatUsedThem)
{
    ui::CalibrationHistory history(QString::fromStdString(file("s.tactiscope")));
    history.show();
    auto* sensors = child<QListWidget>(history, "sensorList");
    ASSERT_EQ(sensors->count(), 2);
    EXPECT_EQ(sensors->item(0)->text(), QStringLiteral("Beam No. 1"));
    ASSERT_TRUE(history.selectSensor(QString::fromUtf8(kBeam)));
    EXPECT_FALSE(history.selectSensor(QStringLiteral("no such sensor")));

    auto* table = child<QTableWidget>(history, "recordTable");
    ASSERT_EQ(table->rowCount(), 3);
    EXPECT_EQ(table->item(0, 2)->text(), QStringLiteral("2.1000"));
    EXPECT_TRUE(table->item(2, 0)->text().contains(QStringLiteral("active")));
    EXPECT_FALSE(table->item(1, 0)->text().contains(QStringLiteral("active")));
    EXPECT_EQ(table->item(1, 6)->text(), QStringLiteral("1"));  // one session used it
    const QString drift = child<QLabel>(history, "driftText")->text();
    EXPECT_TRUE(drift.contains(QStringLiteral("mean 2.1200, SD 0.020"))) << drift.toStdString();
    EXPECT_TRUE(drift.contains(QStringLiteral("newest 1.90 %"))) << drift.toStdString();
    // Three records make a slope, not a trend (issue 52): the rule is said.
    EXPECT_TRUE(drift.contains(QStringLiteral("no trend from 3 records over 365 days (one needs 10 over 30 days)")))
        << drift.toStdString();

    const auto points = history.plottedPoints();
    ASSERT_EQ(points.size(), 3u);
    EXPECT_EQ(points[0].x(), QDateTime(QDate(2026, 1, 1), QTime(0, 0), Qt::UTC).toSecsSinceEpoch());
    EXPECT_EQ(points[2].y(), 2.14);

    history.selectRecord(1);
    auto* sessions = child<QListWidget>(history, "sessionList");
    ASSERT_EQ(sessions->count(), 1);
    EXPECT_TRUE(sessions->item(0)->text().contains(QStringLiteral("phantom-3")));
    tactiscope::testing::saveScreenshot(history, QStringLiteral("calibration-history"));
    history.selectRecord(0);
    EXPECT_EQ(sessions->item(0)->text(), QStringLiteral("none yet"));

    ASSERT_TRUE(history.selectSensor(QStringLiteral("Beam No. 1")));
    EXPECT_EQ(table->rowCount(), 1);
    EXPECT_EQ(table->item(0, 2)->text(), QStringLiteral("1.8000"));
}

TEST_F(CalibrationHistoryTest, AStoreWithoutCalibrationsSaysWhereToMakeOne)
{
    ui::CalibrationHistory history(QString::fromStdString(file("none.tactiscope")));
    EXPECT_EQ(child<QListWidget>(history, "sensorList")->count(), 0);
    EXPECT_TRUE(child<QLabel>(history, "problemText")->text().startsWith(QStringLiteral("No calibrations in")));
}
