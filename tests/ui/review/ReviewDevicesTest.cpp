// A session of several devices in the review window (issue 40): a
// capacitive beam at 100 Hz and a load cell at 1 kHz on another board,
// each on its own clock (the beam's 0.5 s ahead and 80 ppm slow), both
// stepping at one instant, 4.000 s on the session's clock. The window
// plots each device's channels by DEVICE/CHANNEL at their mapped times, so
// the two steps are seen together, and says how each clock was mapped.
#include "core/SampleBlock.h"
#include "core/derived/SessionLanes.h"
#include "core/storage/SessionStore.h"
#include "core/storage/TraceWindow.h"
#include "core/timing/ClockMappingJson.h"
#include "support/CliRunner.h"
#include "support/EmulatorProcess.h"
#include "support/Screenshot.h"
#include "ui/review/ReviewPlot.h"
#include "ui/review/ReviewWindow.h"

#include <QLabel>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTreeWidget>

#include <gtest/gtest.h>

#include <cmath>

using namespace tactiscope;

namespace {

// A part whose own time a maps to the session's as a + offset + drift·(a − 5),
// its one channel 0 before session time 4 s and 1 from then on.
void storePart(core::storage::SessionStore& store, core::storage::SessionMetadata metadata, double rate_hz,
               double offset_s, double drift)
{
    core::timing::ClockMapping clock;
    clock.reference_s = 5.0;
    clock.offset_s = offset_s;
    clock.drift = drift;
    clock.span_s = 10.0;
    clock.basis = core::timing::ClockUncertaintyBasis::Spread;
    clock.offset_u_s = 20e-6;
    clock.drift_u = 0.5e-6;
    const auto count = static_cast<std::size_t>(10.0 * rate_hz);
    const std::vector<core::ChannelDescriptor> channels{{"force", "N", core::ChannelKind::Force}};
    const auto id = store.beginSession(metadata, channels, rate_hz);
    core::SampleBlock block(1, count, 0.0, 1.0 / rate_hz, 0);
    for (std::size_t s = 0; s < count; ++s)
        block.channel(0)[s] = clock.host_s(static_cast<double>(s) / rate_hz) >= 4.0 ? 1.0 : 0.0;
    store.appendBlocks(id, std::vector{block});
    store.setClockMapping(id, core::timing::toJson(clock));
    store.endSession(id, core::SessionStatus::Complete);
}

// Where a lane first reads 1 or more, on the session's clock.
double stepAt_s(core::storage::LaneSource& lane)
{
    const auto window = core::storage::readTraceWindow(lane, 0.0, 0, 3.9, 4.1, 2000);
    EXPECT_TRUE(window.exact);
    for (std::size_t i = 0; i < window.t_s.size(); ++i)
        if (window.low[i] >= 1.0) return window.t_s[i];
    return NAN;
}

}  // namespace

TEST(ReviewDevices, EachDevicesChannelsArePlacedByItsClockOnTheSessionsAxis)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("s.tactiscope");
    {
        core::storage::SessionStore store(db.toStdString());
        core::storage::SessionMetadata metadata;
        metadata.mode = core::Mode::Capacitive;
        metadata.subject = "beam-7";
        const auto session = store.beginSessionOfDevices(metadata);
        metadata.partOf = session;
        metadata.deviceName = "beam";
        storePart(store, metadata, 100.0, -0.5, 80e-6);
        metadata.deviceName = "load-cell";
        storePart(store, metadata, 1000.0, 0.0, 0.0);
        store.endSession(session, core::SessionStatus::Complete);
    }
    // The lanes: each step within a sample of 4.000 s, the beam's (10 ms
    // apart) after it, the load cell's (1 ms) too.
    {
        core::storage::SessionStore store(db.toStdString(), core::storage::Database::Access::ReadOnly);
        auto lanes = core::derived::sessionLanes(store, *store.session(1));
        ASSERT_EQ(lanes.lanes.size(), 2u);
        const double beam = stepAt_s(*lanes.lanes[0]), cell = stepAt_s(*lanes.lanes[1]);
        EXPECT_GE(beam, 4.0);
        EXPECT_LT(beam, 4.0 + 0.01);
        EXPECT_GE(cell, 4.0);
        EXPECT_LT(cell, 4.0 + 0.001);
    }
    QString error;
    std::unique_ptr<ui::ReviewWindow> window(ui::ReviewWindow::open(db, 1, nullptr, error));
    ASSERT_NE(window, nullptr) << error.toStdString();
    window->resize(1366, 768);
    window->show();
    window->plot()->reload();
    EXPECT_EQ(window->plot()->laneNames(), (std::vector<std::string>{"beam/force", "load-cell/force"}));
    EXPECT_EQ(window->account(), nullptr);  // each device's analysis is its own part's
    // A row per device with how its clock was mapped.
    ASSERT_EQ(window->recordList()->topLevelItemCount(), 2);
    EXPECT_TRUE(window->recordList()->topLevelItem(0)->text(3).contains(QStringLiteral("clock: ")));
    const auto* header = window->findChild<QLabel*>(QStringLiteral("sessionHeader"));
    ASSERT_NE(header, nullptr);
    EXPECT_TRUE(header->text().contains(QStringLiteral("beam at 100 Hz, load-cell at 1000 Hz")))
        << header->text().toStdString();
    const QString readout = window->plot()->readoutAt(4.05);
    EXPECT_TRUE(readout.contains(QStringLiteral("beam/Force"))) << readout.toStdString();
    window->plot()->setRange(3.95, 4.05);
    tactiscope::testing::saveScreenshot(*window, QStringLiteral("review-devices"));
}

// Issue 52: a beam recorded beside a load cell is reviewed as a beam
// recorded alone would be, its capacitance change, force and deflection
// in its own units beside its stored capacitance, named after its device;
// the load cell's force as stored.
TEST(ReviewDevices, EachPartIsShownWithItsOwnModesQuantities)
{
    QTemporaryDir dir;
    const QString db = dir.filePath("s.tactiscope");
    QProcess beam, cell;
    ASSERT_TRUE(tactiscope::testing::startEmulator(beam, dir.filePath("beam"),
                                                   {"--scenario", "capacitive-weights", "--seed", "3"}));
    ASSERT_TRUE(tactiscope::testing::startEmulator(cell, dir.filePath("cell"), {"--scenario", "load-cell"}));
    const auto recorded =
        tactiscope::testing::runCli({"record", "--port", "beam=" + dir.filePath("beam"), "--port",
                                     "load-cell=" + dir.filePath("cell"), "--seconds", "3", "--db", db});
    tactiscope::testing::stopEmulator(beam);
    tactiscope::testing::stopEmulator(cell);
    ASSERT_EQ(recorded.exitCode, 0) << recorded.err.toStdString();
    const auto session = tactiscope::testing::sessionIdIn(recorded.out);

    QString error;
    std::unique_ptr<ui::ReviewWindow> window(ui::ReviewWindow::open(db, session, nullptr, error));
    ASSERT_NE(window, nullptr) << error.toStdString();
    window->resize(1366, 768);
    window->show();
    window->plot()->reload();
    EXPECT_EQ(window->plot()->laneNames(), (std::vector<std::string>{"beam/capacitance", "beam/delta_c", "beam/force",
                                                                     "beam/deflection", "load-cell/force"}));
    EXPECT_NE(window->plot()->derivedBasis().find("beam: "), std::string::npos) << window->plot()->derivedBasis();
    // The beam's force in its users' µN, titled after its device.
    const QString readout = window->plot()->readoutAt(1.5);
    EXPECT_TRUE(QRegularExpression(QStringLiteral("beam/[^:]*: -?[0-9.,]+ µN")).match(readout).hasMatch())
        << readout.toStdString();
    tactiscope::testing::saveScreenshot(*window, QStringLiteral("review-devices-beam"));
}
