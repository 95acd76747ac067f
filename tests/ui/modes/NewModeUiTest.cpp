// A fourth mode's ui part added by this file alone, as a sensor type adds
// its entry (docs/conventions.md, "A new mode"): its definition in core,
// its live unit, and its ui entry (registerModeUi) with a live view, the
// display unit of its lane, and a calibration entry. Nothing in the ui is
// edited, and the main window serves it: the mode is offered, its view is
// made, shown when the device's channels feed it and fed on every poll, its
// calibration is in the Tools menu, and a lane of its name is shown in its
// unit; another mode's lane of the same name is not.
#include "core/ModeCapability.h"
#include "core/SampleBlock.h"
#include "core/modes/ModeDefinition.h"
#include "devices/session/LiveModeUnit.h"
#include "devices/session/LiveSession.h"
#include "support/MainWindowHelpers.h"
#include "support/WaitFor.h"
#include "ui/MainWindow.h"
#include "ui/common/DisplayUnits.h"
#include "ui/live/LiveStation.h"
#include "ui/modes/LiveModeView.h"
#include "ui/modes/ModeUi.h"
#include "ui/plot/LivePlotWidget.h"

#include <QMenu>
#include <QMenuBar>
#include <QVBoxLayout>

#include <gtest/gtest.h>

#include <array>

using namespace tactiscope;

namespace {

constexpr auto kCountMode = static_cast<core::Mode>(42);
constexpr std::array kRoles{core::ChannelRole::CantileverA};

// The mode's processor: counts the samples of cantilever A it was fed.
class CountSink final : public core::BlockSink {
public:
    void consume(const core::SampleBlock& block) override { m_samples += block.sampleCount(); }
    std::size_t samples() const { return m_samples; }

private:
    std::atomic<std::size_t> m_samples{0};
};

class CountUnit final : public devices::session::LiveModeUnit {
public:
    std::shared_ptr<core::BlockSink> sink() const override { return m_sink; }
    std::optional<std::string> tare() override { return "a count has no zero"; }
    void take(const devices::session::LiveTake&) override {}
    std::string storedText(const devices::session::RecordingSummary&) const override { return "nothing stored"; }

    std::shared_ptr<CountSink> m_sink = std::make_shared<CountSink>();
};

// The mode's live view: what the session's unit counted, on each poll.
class CountView final : public ui::LiveModeView {
public:
    explicit CountView(QWidget* parent)
        : LiveModeView(parent),
          m_lanes(new ui::LivePlotWidget(this))
    {
        setObjectName(QStringLiteral("countView"));
        (new QVBoxLayout(this))->addWidget(m_lanes);
    }
    void bind(const devices::session::LiveSession* session) override { bound = session && session->unit(kCountMode); }
    void update(devices::session::LiveSession& session) override
    {
        if (const auto* unit = dynamic_cast<const CountUnit*>(session.unit(kCountMode)))
            counted = unit->m_sink->samples();
        ++polls;
    }
    ui::LivePlotWidget* lanes() const override { return m_lanes; }

    bool bound = false;
    int polls = 0;
    std::size_t counted = 0;

private:
    ui::LivePlotWidget* m_lanes;
};

class Registered {
public:
    Registered()
    {
        static const core::ModeDefinition definition{.mode = kCountMode,
                                                     .name = "sample-count",
                                                     .title = "Sample count",
                                                     .needs = "a strain cantilever",
                                                     .roles = kRoles,
                                                     .noZero = "a count has no zero"};
        core::registerMode(definition);
        devices::session::registerLiveUnit(
            kCountMode, [](const devices::session::LiveUnitSetup&) { return std::make_unique<CountUnit>(); });
        ui::registerModeUi({
            .mode = kCountMode,
            .liveView = [](QWidget* parent) -> ui::LiveModeView* { return new CountView(parent); },
            .laneUnit = [](std::string_view lane) -> std::optional<ui::DisplayUnit> {
                if (lane == "count") return ui::DisplayUnit{1e-3, QStringLiteral("k"), QStringLiteral("Samples")};
                return std::nullopt;
            },
            .calibrateAction = [] { return QStringLiteral("Calibrate the &counter…"); },
        });
    }
    ~Registered()
    {
        ui::unregisterModeUi(kCountMode);
        devices::session::unregisterLiveUnit(kCountMode);
        core::unregisterMode(kCountMode);
    }
    Registered(const Registered&) = delete;
    Registered& operator=(const Registered&) = delete;
};

QAction* toolsEntry(ui::MainWindow& window, const QString& text)
{
    for (QAction* menu : window.menuBar()->actions())
        if (menu->menu())
            for (QAction* entry : menu->menu()->actions())
                if (entry->text() == text) return entry;
    return nullptr;
}

}  // namespace

TEST(NewModeUi, AModeRegisteredAloneHasItsViewLanesAndCalibrationInTheWindow)
{
    const Registered registered;
    ui::MainWindow window;
    window.show();
    EXPECT_NE(toolsEntry(window, QStringLiteral("Calibrate the &counter…")), nullptr);
    auto* view = dynamic_cast<CountView*>(window.modeView(kCountMode));
    ASSERT_NE(view, nullptr);

    window.station().connectSource(tactiscope::testing::liveSimulator("panel-scan"));  // cantilever A is there
    ASSERT_TRUE(window.setMode(kCountMode));
    EXPECT_TRUE(view->bound);
    EXPECT_TRUE(view->isVisible());
    ASSERT_TRUE(tactiscope::testing::waitFor([&] { return view->polls >= 3 && view->counted > 0; }, 5000));

    const core::ChannelDescriptor lane{"count", "", core::ChannelKind::Other};
    const auto unit = ui::laneUnit(lane, kCountMode);
    EXPECT_EQ(unit.symbol, QStringLiteral("k"));
    EXPECT_EQ(unit.scale, 1e-3);
    EXPECT_EQ(ui::laneUnit(lane, core::Mode::PanelScan).quantity, QStringLiteral("count"));  // not its lane
    window.station().disconnectDevices();
    EXPECT_FALSE(view->bound);
}
