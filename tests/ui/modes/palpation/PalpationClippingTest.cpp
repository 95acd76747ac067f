// A stiff object pressed deep drives the stiff beam's ADC to its limit: the
// palpation view says so in red while the press goes on ("press less
// deep"), the press is listed as clipped with no number, and a recording
// stores no reading for it.
#include "devices/simulator/PalpationScenario.h"
#include "devices/simulator/SimulatorSource.h"
#include "support/MainWindowHelpers.h"
#include "support/WaitFor.h"
#include "ui/MainWindow.h"
#include "ui/live/LiveStation.h"
#include "ui/modes/palpation/PalpationView.h"

#include <QLabel>
#include <QTableWidget>

#include <gtest/gtest.h>

using namespace tactiscope;
using tactiscope::testing::child;
using tactiscope::testing::waitFor;

TEST(PalpationClipping, TheViewWarnsWhileAPressClipsAndListsItWithoutANumber)
{
    devices::simulator::PalpationParameters stiff;
    stiff.objectStiffness_n_per_m = 100000.0;  // the stiff beam clips beyond about 5 mm
    stiff.pressDepths_m = {0.008};
    devices::simulator::SimulatorOptions pace;
    pace.speed = 4.0;
    ui::MainWindow window;
    window.show();
    window.setMode(core::Mode::Palpation);
    window.station().connectSource(std::make_unique<devices::simulator::SimulatorSource>(
        std::make_unique<devices::simulator::PalpationScenario>(stiff), pace));
    auto* view = window.findChild<ui::PalpationView*>();
    ASSERT_NE(view, nullptr);
    auto* status = child<QLabel>(*view, "palpationStatus");
    ASSERT_TRUE(waitFor([&] { return status->text().contains(QStringLiteral("at its limit")); }, 15000))
        << status->text().toStdString();
    EXPECT_TRUE(status->text().contains(QStringLiteral("Stiff beam"))) << status->text().toStdString();
    EXPECT_TRUE(status->text().contains(QStringLiteral("press less deep")));
    EXPECT_TRUE(status->styleSheet().contains(QStringLiteral("#b00020")));

    auto* table = child<QTableWidget>(*view, "pressTable");
    ASSERT_TRUE(waitFor([&] { return table->rowCount() >= 1; }, 15000));
    EXPECT_TRUE(table->item(0, 1)->text().startsWith(QStringLiteral("clipped")))
        << table->item(0, 1)->text().toStdString();
    EXPECT_EQ(table->item(0, 2)->text(), QStringLiteral("—"));
}
