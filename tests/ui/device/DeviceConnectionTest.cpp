// Connecting the main window to a device over a real pseudo-terminal: the
// probe emulator behind a link, opened off the GUI thread; a failure shown
// in a non-modal message with the fix; an unplug during a recording shown as
// lost, then streaming again, with the session keeping both parts and the
// gap. Also the device panel's choices and counters.
#include "core/storage/SessionStore.h"
#include "devices/DeviceDiscovery.h"
#include "devices/emulator/ProbeEmulator.h"
#include "support/MainWindowHelpers.h"
#include "support/Screenshot.h"
#include "support/TempDirectory.h"
#include "support/TempPath.h"
#include "support/TextBoard.h"
#include "support/WaitFor.h"
#include "ui/MainWindow.h"
#include "ui/device/DevicePanel.h"
#include "ui/live/LiveStation.h"
#include "ui/plot/LivePlotWidget.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QSplitter>
#include <QTest>
#include <QTreeWidget>

#include <atomic>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include <filesystem>

using namespace tactiscope;
using devices::WireProtocol;
using devices::emulator::ProbeEmulator;
using tactiscope::testing::child;
using tactiscope::testing::saveScreenshot;
using tactiscope::testing::serialOpener;
using tactiscope::testing::waitFor;

using tactiscope::testing::uniqueTempPath;

namespace {

QString stateText(const ui::MainWindow& window)
{
    return window.findChild<QLabel*>(QStringLiteral("stateLabel"))->text();
}

std::uint64_t counter(const ui::MainWindow& window, const char* name)
{
    return QLocale().toULongLong(child<QLabel>(window, name)->text());
}

}  // namespace

TEST(DeviceConnection, ConnectsToTheEmulatorWithoutBlockingTheWindow)
{
    const std::string link = uniqueTempPath("connect");
    ProbeEmulator emulator({link, WireProtocol::Binary, "palpation", 1000.0, std::nullopt, std::nullopt, 0.0, 10, 2});
    emulator.start();
    ui::MainWindow window;
    window.show();
    window.station().connectDevice(QString::fromStdString(link), serialOpener(link));
    // The handshake runs on a worker thread: the window is "connecting" and
    // still processes events meanwhile.
    EXPECT_TRUE(window.station().isConnecting());
    EXPECT_EQ(stateText(window), QStringLiteral("Connecting…"));
    ASSERT_TRUE(waitFor([&] { return window.station().isConnected(); }, 6000));
    EXPECT_TRUE(waitFor([&] { return stateText(window) == QStringLiteral("Streaming"); }, 2000));
    EXPECT_TRUE(window.windowTitle().contains(QStringLiteral("EMU-2")));
    tactiscope::testing::runEventLoopFor(1500);
    EXPECT_FALSE(saveScreenshot(window, QStringLiteral("main-window-emulator")).isEmpty());
}

TEST(DeviceConnection, AFailedConnectionIsShownNotThrown)
{
    ui::MainWindow window;
    window.show();
    window.station().connectDevice(QStringLiteral("/dev/tactiscope-no-such-port"),
                                   serialOpener("/dev/tactiscope-no-such-port"));
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
    EXPECT_FALSE(window.station().isConnected());
    EXPECT_FALSE(box->isModal());  // nothing else stops for it
    EXPECT_FALSE(saveScreenshot(*box, QStringLiteral("connect-error")).isEmpty());
}

class DeviceConnectionStore : public tactiscope::testing::TempDirectoryTest {
protected:
    // A 500 Hz panel-scan emulator (seed 3) at a new link `name`, the window
    // connected to it, recording for a second.
    void recordFromAnEmulator(const char* name)
    {
        m_link = uniqueTempPath(name);
        m_options = {m_link, WireProtocol::Binary, "panel-scan", 500.0, std::nullopt, std::nullopt, 0.0, 10, 3};
        m_emulator = std::make_unique<ProbeEmulator>(m_options);
        m_emulator->start();
        m_window.setStorePath(QString::fromStdString(file("sessions.tactiscope")));
        m_window.show();
        m_window.station().connectDevice(QString::fromStdString(m_link), serialOpener(m_link));
        ASSERT_TRUE(waitFor([&] { return stateText(m_window) == QStringLiteral("Streaming"); }, 6000));
        ASSERT_TRUE(m_window.startRecording());
        tactiscope::testing::runEventLoopFor(1000);
    }

    std::string m_link;
    devices::emulator::EmulatorOptions m_options;
    std::unique_ptr<ProbeEmulator> m_emulator;
    ui::MainWindow m_window;  // closed before the emulator goes
};

TEST_F(DeviceConnectionStore, AnUnplugWhileRecordingIsShownAsLostAndTheSessionKeepsBothParts)
{
    recordFromAnEmulator("unplug");
    if (HasFatalFailure()) return;
    EXPECT_EQ(counter(m_window, "lostLabel"), 0u);

    m_emulator.reset();  // the cable is pulled
    // The state moves on from "Device lost" to "Reconnecting…" by itself, so
    // the link label is compared with the state it was read beside.
    EXPECT_TRUE(waitFor(
        [&] {
            const QString state = stateText(m_window);
            return (state == QStringLiteral("Device lost") || state == QStringLiteral("Reconnecting…")) &&
                   child<QLabel>(m_window, "linkLabel")->text().startsWith(state);
        },
        3000));
    EXPECT_TRUE(m_window.station().isConnected());  // the session goes on through the outage
    EXPECT_TRUE(m_window.isRecording());
    tactiscope::testing::runEventLoopFor(1000);

    m_emulator = std::make_unique<ProbeEmulator>(m_options);  // plugged back in
    m_emulator->start();
    ASSERT_TRUE(waitFor([&] { return stateText(m_window) == QStringLiteral("Streaming"); }, 8000));
    // The outage is counted as lost samples, about a second's worth or more.
    EXPECT_TRUE(waitFor([&] { return counter(m_window, "lostLabel") >= 400; }, 3000)) << counter(m_window, "lostLabel");
    EXPECT_GE(counter(m_window, "reconnectLabel"), 1u);
    tactiscope::testing::runEventLoopFor(1000);
    m_window.stopRecording();

    core::storage::SessionStore store(file("sessions.tactiscope"), core::storage::Database::Access::ReadOnly);
    const auto sessions = store.sessions();
    ASSERT_EQ(sessions.size(), 1u);
    const std::int64_t id = sessions[0].id;
    const auto gaps = store.gaps(id);
    ASSERT_EQ(gaps.size(), 1u);
    EXPECT_GE(gaps[0].count, 400u);  // ≥ 0.8 s at 500 Hz
    // Both parts are there: about a second before the gap, another after it.
    const std::uint64_t total = store.sampleCount(id);
    EXPECT_GE(gaps[0].firstIndex, 400u);
    EXPECT_GE(total - (gaps[0].firstIndex + gaps[0].count), 400u);
    const auto before = store.readChannel(id, 0, 0, gaps[0].firstIndex);
    const auto after =
        store.readChannel(id, 0, gaps[0].firstIndex + gaps[0].count, total - gaps[0].firstIndex - gaps[0].count);
    EXPECT_TRUE(std::isfinite(before.back()));
    EXPECT_TRUE(std::isfinite(after.front()));
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
    window.station().connectDevice(QString::fromStdString(silentLink), serialOpener(silentLink));
    window.station().connectDevice(QString::fromStdString(link), serialOpener(link));
    ASSERT_TRUE(waitFor([&] { return window.station().isConnected(); }, 6000));
    EXPECT_TRUE(window.windowTitle().contains(QStringLiteral("EMU-6")));
    // The silent port's attempt ends in a timeout later; that must neither
    // replace the connection nor raise an error.
    tactiscope::testing::runEventLoopFor(5000);
    EXPECT_TRUE(window.station().isConnected());
    EXPECT_TRUE(window.windowTitle().contains(QStringLiteral("EMU-6")));
    EXPECT_EQ(window.findChild<QMessageBox*>(QStringLiteral("connectErrorBox")), nullptr);
    EXPECT_EQ(stateText(window), QStringLiteral("Streaming"));
}

// A maker's board (issue 53): the panel shows the rate its lines were
// timed at, with its uncertainty, and each channel's unit as the board
// gave it (none: a plain number).
TEST(DeviceConnection, ATextBoardShowsTheRateItWasTimedAtAndItsChannelsUnits)
{
    const std::string link = uniqueTempPath("text-board");
    tactiscope::testing::TextBoard board(link,
                                         {100.0,
                                          [](std::uint64_t n) {
                                              return "force[mN]:" + std::to_string(0.01 * static_cast<double>(n % 50)) +
                                                     " pos:" + std::to_string(n % 7) + "\r\n";
                                          },
                                          4, 2e-3, false});
    ASSERT_TRUE(board.ok());
    ui::MainWindow window;
    window.show();
    window.station().connectDevice(
        QString::fromStdString(link),
        serialOpener(link, {WireProtocol::Text, std::nullopt, std::chrono::milliseconds(4000), std::nullopt, {}}));
    ASSERT_TRUE(waitFor([&] { return window.station().isConnected(); }, 8000));
    ASSERT_TRUE(waitFor([&] { return stateText(window) == QStringLiteral("Streaming"); }, 2000));
    tactiscope::testing::runEventLoopFor(1200);
    // "(timed 100.002 ± 0.004 Hz from its lines)": the board's 100 Hz within three of its ±.
    const QString rate = child<QLabel>(window, "rateLabel")->text();
    const auto timed =
        QRegularExpression(QStringLiteral(R"(\(timed ([0-9.]+) ± ([0-9.]+) Hz from its lines\))")).match(rate);
    ASSERT_TRUE(timed.hasMatch()) << rate.toStdString();
    EXPECT_LE(std::abs(timed.captured(1).toDouble() - 100.0), 3.0 * timed.captured(2).toDouble()) << rate.toStdString();
    QStringList labels;
    for (const auto* label : window.findChildren<QLabel*>()) labels << label->text();
    EXPECT_TRUE(labels.contains(QStringLiteral("force [N]:"))) << labels.join(QLatin1Char('|')).toStdString();
    EXPECT_TRUE(labels.contains(QStringLiteral("pos:"))) << labels.join(QLatin1Char('|')).toStdString();
    EXPECT_FALSE(saveScreenshot(window, QStringLiteral("main-window-text-board")).isEmpty());
}

// A board that begins to print another value while the window shows it:
// the traces gain the new channel (holes before its first value), the
// others keep their history.
TEST(DeviceConnection, ATextBoardsNewChannelJoinsTheTraces)
{
    const std::string link = uniqueTempPath("text-board-grows");
    std::atomic<std::uint64_t> grows = std::numeric_limits<std::uint64_t>::max();
    tactiscope::testing::TextBoard board(link, {100.0,
                                                [&](std::uint64_t n) {
                                                    std::string line = "a:" + std::to_string(n % 50);
                                                    if (n >= grows) line += " b:" + std::to_string(n % 9);
                                                    return line + "\r\n";
                                                },
                                                1, 1e-3, false});
    ASSERT_TRUE(board.ok());
    ui::MainWindow window;
    window.show();
    window.station().connectDevice(
        QString::fromStdString(link),
        serialOpener(link, {WireProtocol::Text, 100.0, std::chrono::milliseconds(4000), std::nullopt, {}}));
    ASSERT_TRUE(waitFor([&] { return window.station().isConnected(); }, 8000));
    auto* traces = qobject_cast<ui::LivePlotWidget*>(child<QSplitter>(window, "centreSplitter")->widget(0));
    ASSERT_TRUE(traces);
    tactiscope::testing::runEventLoopFor(500);
    EXPECT_GT(traces->drawnPointCount(0), 0);
    EXPECT_EQ(traces->drawnPointCount(1), 0);
    grows = board.printed() + 20;
    EXPECT_TRUE(waitFor([&] { return traces->drawnPointCount(1) > 0; }, 4000));
    EXPECT_GT(traces->drawnPointCount(0), 0);
    ASSERT_EQ(window.station().device()->channels().size(), 2u);
    EXPECT_EQ(window.station().device()->channels()[1].name, "b");
}

TEST(DevicePanel, ReturnsTheChosenPortAndLinkSettings)
{
    ui::DevicePanel panel;
    panel.show();
    panel.setPath(QStringLiteral("/tmp/probe"));
    auto* protocol = child<QComboBox>(panel, "protocolBox");
    auto* baud = child<QComboBox>(panel, "baudBox");
    auto* rate = child<QDoubleSpinBox>(panel, "textRateBox");
    EXPECT_FALSE(rate->isEnabled());  // only the text protocol needs a rate
    EXPECT_EQ(baud->currentText(), QStringLiteral("921600"));

    protocol->setCurrentIndex(1);
    EXPECT_TRUE(rate->isEnabled());
    baud->setCurrentText(QStringLiteral("115200"));
    auto request = panel.request();
    ASSERT_TRUE(request.has_value());
    EXPECT_EQ(request->kind, ui::SourceKind::Port);
    EXPECT_EQ(request->device.path, "/tmp/probe");
    EXPECT_EQ(request->device.bus, devices::DeviceBus::Serial);
    EXPECT_EQ(request->baud, 115200);
    EXPECT_EQ(request->options.protocol, WireProtocol::Text);
    EXPECT_FALSE(request->options.textRate_hz.has_value());  // estimated

    rate->setValue(250.0);
    request = panel.request();
    ASSERT_TRUE(request->options.textRate_hz.has_value());
    EXPECT_DOUBLE_EQ(*request->options.textRate_hz, 250.0);

    // A simulator needs no link: the port fields are off.
    panel.selectSimulator(QStringLiteral("palpation"));
    request = panel.request();
    EXPECT_EQ(request->kind, ui::SourceKind::Simulator);
    EXPECT_EQ(request->scenario, "palpation");
    EXPECT_FALSE(child<QLineEdit>(panel, "pathEdit")->isEnabled());

    panel.setPath(QString());
    EXPECT_FALSE(panel.request().has_value());
    EXPECT_FALSE(child<QPushButton>(panel, "connectButton")->isEnabled());
}

TEST(DevicePanel, TheEmulatorChosenInThePanelStreamsThroughAPtyWithItsCounters)
{
    ui::MainWindow window;
    window.resize(1200, 760);
    window.show();
    auto* tree = child<QTreeWidget>(window, "sourceTree");
    // "Emulator" is the second heading; palpation is among its entries.
    QTreeWidgetItem* heading = tree->topLevelItem(1);
    QTreeWidgetItem* emulator = nullptr;
    for (int i = 0; i < heading->childCount() && !emulator; ++i)
        if (heading->child(i)->text(0).startsWith(QStringLiteral("Palpation"))) emulator = heading->child(i);
    ASSERT_NE(emulator, nullptr);
    // Issue 52: told apart from the simulator's entry, and in TSP/1 even
    // after a text board's connection left the protocol on text lines.
    EXPECT_EQ(emulator->text(0), QStringLiteral("Palpation — compliance probe (emulated port)"));
    child<QComboBox>(window, "protocolBox")->setCurrentIndex(1);
    tree->setCurrentItem(emulator);
    EXPECT_EQ(child<QComboBox>(window, "protocolBox")->currentIndex(), 0);
    // The Port field stays put as the device's channel roles appear below.
    auto* path = child<QLineEdit>(window, "pathEdit");
    const QPoint portBefore = path->mapTo(&window, QPoint(0, 0));
    QTest::mouseClick(child<QPushButton>(window, "connectButton"), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return window.station().isConnected(); }, 6000));
    EXPECT_TRUE(window.windowTitle().contains(QStringLiteral("EMU-")));  // the firmware's answer over the pty
    ASSERT_TRUE(waitFor([&] { return stateText(window) == QStringLiteral("Streaming"); }, 3000));
    ASSERT_TRUE(waitFor([&] { return counter(window, "samplesLabel") > 1000; }, 4000))
        << child<QLabel>(window, "samplesLabel")->text().toStdString() << " " << stateText(window).toStdString();
    EXPECT_EQ(child<QLabel>(window, "crcLabel")->text(), QStringLiteral("0"));
    EXPECT_EQ(counter(window, "lostLabel"), 0u);
    // The rate is measured over a second; under load it may still be measuring.
    EXPECT_TRUE(waitFor(
        [&] { return child<QLabel>(window, "rateLabel")->text().contains(QStringLiteral(" Hz (nominal 1,000 Hz)")); },
        3000))
        << child<QLabel>(window, "rateLabel")->text().toStdString();
    EXPECT_EQ(path->mapTo(&window, QPoint(0, 0)), portBefore);
    EXPECT_FALSE(saveScreenshot(window, QStringLiteral("device-panel")).isEmpty());

    QTest::mouseClick(child<QPushButton>(window, "disconnectButton"), Qt::LeftButton);
    EXPECT_FALSE(window.station().isConnected());
    EXPECT_EQ(stateText(window), QStringLiteral("—"));
}

// Another probe of the same kind on the port after an unplug (the
// emulator's serial number is EMU-<seed>): the recording ends with the
// first probe's samples, the operator is told why in a problem box, and
// nothing of the second probe joins the session.
TEST_F(DeviceConnectionStore, AnotherProbeOnThePortEndsTheRecordingAndSaysWhy)
{
    recordFromAnEmulator("other");
    if (HasFatalFailure()) return;

    m_emulator.reset();  // the cable is pulled, and another probe plugged in
    m_options.seed = 4;
    m_emulator = std::make_unique<ProbeEmulator>(m_options);
    m_emulator->start();
    ASSERT_TRUE(waitFor([&] { return !m_window.isRecording(); }, 8000));
    QMessageBox* box = nullptr;
    ASSERT_TRUE(waitFor(
        [&] {
            for (auto* candidate : m_window.findChildren<QMessageBox*>())
                if (candidate->detailedText().contains(QStringLiteral("another device came back on the port")) ||
                    candidate->informativeText().contains(QStringLiteral("another device came back on the port")) ||
                    candidate->text().contains(QStringLiteral("another device came back on the port")))
                    box = candidate;
            return box != nullptr;
        },
        3000));
    EXPECT_FALSE(saveScreenshot(*box, QStringLiteral("another-probe")).isEmpty());

    core::storage::SessionStore store(file("sessions.tactiscope"), core::storage::Database::Access::ReadOnly);
    const auto sessions = store.sessions();
    ASSERT_EQ(sessions.size(), 1u);
    std::uint64_t lost = 0;
    for (const auto& gap : store.gaps(sessions[0].id)) lost += gap.count;
    EXPECT_LT(store.sampleCount(sessions[0].id) - lost, 1000u);  // about the first probe's second at 500 Hz
}
