// The real libserialport backend over a pseudo-terminal. Runs in its own
// binary with tests/support/PtyModemShim.c preloaded (see tests/CMakeLists),
// which lets libserialport 0.1.1 accept a pty; everything else is real: the
// probe emulator, the pty, libserialport's termios calls and PortSource.
#include "devices/PortSource.h"

#include "core/SampleBlock.h"
#include "devices/emulator/ProbeEmulator.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/transport/LibSerialPortTransport.h"

#include "support/TempPath.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace tactiscope;
using devices::PortSource;
using devices::ReadStatus;
using devices::WireProtocol;
using devices::emulator::ProbeEmulator;
using devices::transport::LibSerialPortTransport;
using devices::transport::TransportError;

using tactiscope::testing::uniqueTempPath;

namespace {

// libserialport only accepts /dev/ names, so it gets the pty behind the link.
std::string devicePath(const std::string& link)
{
    return std::filesystem::canonical(link).string();
}

}  // namespace

TEST(LibSerialPortPath, HandshakeAndStreamingThroughLibserialport)
{
    const std::string link = uniqueTempPath("binary");
    ProbeEmulator emulator({link, WireProtocol::Binary, "panel-scan", 2000.0, std::nullopt, std::nullopt, 0.0, 10, 4});
    emulator.start();
    const std::string device = devicePath(link);
    ASSERT_EQ(device.rfind("/dev/pts/", 0), 0u);

    PortSource source(std::make_unique<LibSerialPortTransport>(device, 921600), devices::PortSourceOptions{});
    ASSERT_EQ(source.channels().size(), 2u);
    ASSERT_TRUE(source.deviceInfo().has_value());
    EXPECT_EQ(source.deviceInfo()->serialNumber, "EMU-4");
    EXPECT_DOUBLE_EQ(source.nominalSampleRate_hz(), 2000.0);

    // Samples as generated independently from the same scenario and seed.
    constexpr std::size_t kSamples = 1000;
    auto reference = devices::simulator::makeScenario("panel-scan", 4, 2000.0);
    core::SampleBlock expected(2, kSamples, 0.0, 0.0005);
    reference->generate(expected);

    std::size_t index = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (index < kSamples && std::chrono::steady_clock::now() < deadline) {
        core::SampleBlock block;
        const auto status = source.readBlock(block, std::chrono::milliseconds(100));
        ASSERT_NE(status, ReadStatus::Failed) << source.lastError();
        if (status != ReadStatus::Block) continue;
        ASSERT_EQ(block.firstSampleIndex(), index);
        for (std::size_t s = 0; s < block.sampleCount() && index + s < kSamples; ++s)
            for (std::size_t c = 0; c < 2; ++c)
                ASSERT_EQ(block.value(c, s), static_cast<double>(static_cast<float>(expected.value(c, index + s))));
        index += block.sampleCount();
    }
    EXPECT_GE(index, kSamples);
    EXPECT_EQ(source.decoderCounters().crcErrors, 0u);
    EXPECT_EQ(source.decoderCounters().samplesLost, 0u);
}

TEST(LibSerialPortPath, TheFarEndHangingUpIsReportedAsADisconnect)
{
    const std::string link = uniqueTempPath("hangup");
    ProbeEmulator emulator({link, WireProtocol::Binary, "panel-scan", 1000.0, std::nullopt, 0.3, 0.0, 10, 1});
    emulator.start();
    PortSource source(std::make_unique<LibSerialPortTransport>(devicePath(link), 921600), devices::PortSourceOptions{});
    ReadStatus status = ReadStatus::Timeout;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (status != ReadStatus::Failed && std::chrono::steady_clock::now() < deadline) {
        core::SampleBlock block;
        status = source.readBlock(block, std::chrono::milliseconds(100));
    }
    EXPECT_EQ(status, ReadStatus::Failed);
    EXPECT_NE(source.lastError().find("disconnected"), std::string::npos) << source.lastError();
}

TEST(LibSerialPortPath, AMissingPortIsANamedError)
{
    try {
        LibSerialPortTransport transport("/dev/tactiscope-no-such-port", 115200);
        FAIL() << "opened a port that does not exist";
    } catch (const TransportError& error) {
        EXPECT_NE(std::string(error.what()).find("/dev/tactiscope-no-such-port"), std::string::npos);
    }
}
