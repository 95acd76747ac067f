// Connecting the main window to a device over a real pseudo-terminal: the
// probe emulator behind a link, opened off the GUI thread; a failure shown
// in a message box; an unplug shown as lost, then streaming again. Also the
// connect dialog's request and look.
#include "devices/DeviceDiscovery.h"
#include "devices/emulator/ProbeEmulator.h"
#include "support/Screenshot.h"
#include "support/TempPath.h"
#include "support/WaitFor.h"
#include "ui/ConnectDialog.h"
#include "ui/MainWindow.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMessageBox>

#include <gtest/gtest.h>

#include <filesystem>

using namespace tactiscope;
using devices::WireProtocol;
using devices::emulator::ProbeEmulator;
using tactiscope::testing::saveScreenshot;
using tactiscope::testing::waitFor;

using tactiscope::testing::uniqueTempPath;

namespace {

QString stateText(const ui::MainWindow& window)
{
    return window.findChild<QLabel*>(QStringLiteral("stateLabel"))->text();
}

devices::ReconnectingSource::Opener serialOpener(const std::string& link)
{
    return devices::deviceOpener({devices::DeviceBus::Serial, link, {}, link}, 921600, devices::PortSourceOptions{});
}

}  // namespace

TEST(DeviceConnection, ConnectsToTheEmulatorWithoutBlockingTheWindow)
{
    const std::string link = uniqueTempPath("connect");
    ProbeEmulator emulator({link, WireProtocol::Binary, "palpation", 1000.0, std::nullopt, std::nullopt, 0.0, 10, 2});
    emulator.start();
    ui::MainWindow window;
    window.show();
    window.connectDevice(QString::fromStdString(link), serialOpener(link));
    // The handshake runs on a worker thread: the window is "connecting" and
    // still processes events meanwhile.
    EXPECT_TRUE(window.isConnecting());
    EXPECT_EQ(stateText(window), QStringLiteral("Connecting…"));
    ASSERT_TRUE(waitFor([&] { return window.isConnected(); }, 6000));
    EXPECT_TRUE(waitFor([&] { return stateText(window) == QStringLiteral("Streaming"); }, 2000));
    EXPECT_TRUE(window.windowTitle().contains(QStringLiteral("EMU-2")));
    tactiscope::testing::runEventLoopFor(1500);
    EXPECT_FALSE(saveScreenshot(window, QStringLiteral("main-window-emulator")).isEmpty());
}

TEST(DeviceConnection, AFailedConnectionIsShownNotThrown)
{
    ui::MainWindow window;
    window.show();
    window.connectDevice(QStringLiteral("/dev/tactiscope-no-such-port"), serialOpener("/dev/tactiscope-no-such-port"));
    QMessageBox* box = nullptr;
    ASSERT_TRUE(waitFor(
        [&] {
            box = window.findChild<QMessageBox*>(QStringLiteral("connectErrorBox"));
            return box && box->isVisible();
        },
        6000));
    EXPECT_TRUE(box->text().contains(QStringLiteral("/dev/tactiscope-no-such-port")));
    EXPECT_TRUE(box->informativeText().contains(QStringLiteral("No such file")));
    EXPECT_EQ(stateText(window), QStringLiteral("Connection failed"));
    EXPECT_FALSE(window.isConnected());
    EXPECT_FALSE(saveScreenshot(*box, QStringLiteral("connect-error")).isEmpty());
}

TEST(DeviceConnection, AnUnplugIsShownAsLostThenStreamingAgain)
{
    const std::string link = uniqueTempPath("unplug");
    const devices::emulator::EmulatorOptions options{
        link, WireProtocol::Binary, "panel-scan", 500.0, std::nullopt, std::nullopt, 0.0, 10, 3};
    auto emulator = std::make_unique<ProbeEmulator>(options);
    emulator->start();
    ui::MainWindow window;
    window.show();
    window.connectDevice(QString::fromStdString(link), serialOpener(link));
    ASSERT_TRUE(waitFor([&] { return stateText(window) == QStringLiteral("Streaming"); }, 6000));

    emulator.reset();  // the cable is pulled
    EXPECT_TRUE(waitFor(
        [&] {
            const QString state = stateText(window);
            return state == QStringLiteral("Device lost") || state == QStringLiteral("Reconnecting…");
        },
        3000));
    EXPECT_TRUE(window.isConnected());  // the session goes on through the outage

    emulator = std::make_unique<ProbeEmulator>(options);  // plugged back in
    emulator->start();
    EXPECT_TRUE(waitFor([&] { return stateText(window) == QStringLiteral("Streaming"); }, 8000));
}

TEST(DeviceConnection, ANewerConnectSupersedesOneStillInItsHandshake)
{
    // A port where nothing answers: its handshake runs until the timeout.
    const std::string silentLink = uniqueTempPath("silent");
    ProbeEmulator silent(
        {silentLink, WireProtocol::Binary, "panel-scan", 500.0, std::nullopt, std::nullopt, 0.0, 10, 1});
    const std::string link = uniqueTempPath("answering");
    ProbeEmulator answering({link, WireProtocol::Binary, "palpation", 500.0, std::nullopt, std::nullopt, 0.0, 10, 6});
    answering.start();

    ui::MainWindow window;
    window.show();
    window.connectDevice(QString::fromStdString(silentLink), serialOpener(silentLink));
    window.connectDevice(QString::fromStdString(link), serialOpener(link));
    ASSERT_TRUE(waitFor([&] { return window.isConnected(); }, 6000));
    EXPECT_TRUE(window.windowTitle().contains(QStringLiteral("EMU-6")));
    // The silent port's attempt ends in a timeout later; that must neither
    // replace the connection nor raise an error.
    tactiscope::testing::runEventLoopFor(5000);
    EXPECT_TRUE(window.isConnected());
    EXPECT_TRUE(window.windowTitle().contains(QStringLiteral("EMU-6")));
    EXPECT_EQ(window.findChild<QMessageBox*>(QStringLiteral("connectErrorBox")), nullptr);
    EXPECT_EQ(stateText(window), QStringLiteral("Streaming"));
}

TEST(ConnectDialog, ReturnsTheChosenPortAndLinkSettings)
{
    ui::ConnectDialog dialog;
    dialog.show();
    dialog.setPath(QStringLiteral("/tmp/probe"));
    auto* protocol = dialog.findChild<QComboBox*>(QStringLiteral("protocolBox"));
    auto* baud = dialog.findChild<QComboBox*>(QStringLiteral("baudBox"));
    auto* rate = dialog.findChild<QDoubleSpinBox*>(QStringLiteral("textRateBox"));
    ASSERT_TRUE(protocol && baud && rate);
    EXPECT_FALSE(rate->isEnabled());  // only the text protocol needs a rate
    EXPECT_EQ(baud->currentText(), QStringLiteral("921600"));

    protocol->setCurrentIndex(1);
    EXPECT_TRUE(rate->isEnabled());
    baud->setCurrentText(QStringLiteral("115200"));
    auto request = dialog.request();
    EXPECT_EQ(request.device.path, "/tmp/probe");
    EXPECT_EQ(request.device.bus, devices::DeviceBus::Serial);
    EXPECT_EQ(request.baud, 115200);
    EXPECT_EQ(request.options.protocol, WireProtocol::Text);
    EXPECT_FALSE(request.options.textRate_hz.has_value());  // estimated

    rate->setValue(250.0);
    request = dialog.request();
    ASSERT_TRUE(request.options.textRate_hz.has_value());
    EXPECT_DOUBLE_EQ(*request.options.textRate_hz, 250.0);
    EXPECT_FALSE(saveScreenshot(dialog, QStringLiteral("connect-dialog")).isEmpty());
}
