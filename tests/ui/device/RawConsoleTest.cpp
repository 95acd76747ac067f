// The raw-data console: complete text lines and a hex dump of the newest
// bytes (by hand), and in the main window the emulator's real wire through
// a pseudo-terminal, in text and in binary, with the decoder's counters.
#include "ui/device/RawConsole.h"

#include "devices/DeviceDiscovery.h"
#include "devices/emulator/ProbeEmulator.h"
#include "support/MainWindowHelpers.h"
#include "support/Screenshot.h"
#include "support/TempPath.h"
#include "support/WaitFor.h"
#include "ui/MainWindow.h"
#include "ui/live/LiveStation.h"

#include <QDockWidget>
#include <QLabel>
#include <QPlainTextEdit>
#include <QRegularExpression>

#include <gtest/gtest.h>

using namespace tactiscope;
using tactiscope::testing::child;
using tactiscope::testing::waitFor;

TEST(RawConsole, ShowsCompleteLinesAndAHexDumpOfTheNewestBytes)
{
    const std::string text = "2,3\nt,a\n1.5,2.5\n3.5,4.5\n5.";
    const std::vector<std::uint8_t> bytes(text.begin(), text.end());
    // The first line may be cut and the last is unfinished: neither is shown.
    EXPECT_EQ(ui::lastLines(bytes, 10), QStringLiteral("t,a\n1.5,2.5\n3.5,4.5"));
    EXPECT_EQ(ui::lastLines(bytes, 1), QStringLiteral("3.5,4.5"));

    std::vector<std::uint8_t> binary(40);
    for (std::size_t i = 0; i < binary.size(); ++i) binary[i] = static_cast<std::uint8_t>(0x30 + i);
    const QStringList rows = ui::hexDump(binary, 20).split(QLatin1Char('\n'));
    ASSERT_EQ(rows.size(), 2);  // the last 20 bytes: 0x44 … 0x57
    EXPECT_TRUE(rows[0].startsWith(QStringLiteral("-0014  44 45 46"))) << rows[0].toStdString();
    EXPECT_TRUE(rows[0].endsWith(QStringLiteral("DEFGHIJKLMNOPQRS"))) << rows[0].toStdString();
    EXPECT_TRUE(rows[1].startsWith(QStringLiteral("-0004  54 55 56 57"))) << rows[1].toStdString();
}

namespace {

// What the console shows once it holds more than `lines` lines.
QString consoleTextAfterConnecting(ui::MainWindow& window, devices::WireProtocol protocol, const char* name,
                                   qsizetype lines)
{
    const std::string link = tactiscope::testing::uniqueTempPath(name);
    devices::emulator::ProbeEmulator emulator(
        {link, protocol, "panel-scan", 200.0, std::nullopt, std::nullopt, 0.0, 10, 4});
    emulator.start();
    devices::PortSourceOptions options;
    options.protocol = protocol;
    options.textRate_hz = 200.0;
    window.station().connectDevice(QString::fromStdString(link), tactiscope::testing::serialOpener(link, options));
    child<QDockWidget>(window, "consoleDock")->show();
    auto* text = child<QPlainTextEdit>(window, "rawText");
    EXPECT_TRUE(waitFor([&] { return text->toPlainText().count(QLatin1Char('\n')) > lines; }, 6000));
    const QString shown = text->toPlainText();
    tactiscope::testing::saveScreenshot(window, QString::fromLatin1(name));
    window.station().disconnectDevices();
    return shown;
}

}  // namespace

TEST(RawConsole, ShowsTheEmulatorsWireInTextAndInBinaryWithTheCounters)
{
    ui::MainWindow window;
    window.resize(1200, 900);
    window.show();
    const QString lines = consoleTextAfterConnecting(window, devices::WireProtocol::Text, "raw-text", 10);
    // Serial-Plotter lines of two labelled numbers.
    EXPECT_TRUE(
        QRegularExpression(QStringLiteral("^a:-?[0-9.e+-]+ b:-?[0-9.e+-]+$"), QRegularExpression::MultilineOption)
            .match(lines)
            .hasMatch())
        << lines.left(200).toStdString();

    const QString hex =
        consoleTextAfterConnecting(window, devices::WireProtocol::Binary, "raw-binary", 30);  // 512 bytes
    EXPECT_TRUE(hex.startsWith(QStringLiteral("-0200  "))) << hex.left(80).toStdString();
    EXPECT_EQ(child<QLabel>(window, "decoderCounters")->text(), QStringLiteral("Not connected."));

    window.station().connectSource(tactiscope::testing::liveSimulator());
    EXPECT_TRUE(waitFor(
        [&] { return child<QLabel>(window, "decoderCounters")->text().contains(QStringLiteral("no wire")); }, 2000));
}
