// The serial path end to end over real pseudo-terminals: the probe emulator
// behind a pty symlink, the POSIX serial transport and PortSource.
#include "devices/PortSource.h"

#include "core/SampleBlock.h"
#include "devices/emulator/ProbeEmulator.h"
#include "devices/simulator/ScenarioCatalog.h"
#include "devices/transport/PosixSerialTransport.h"

#include "support/TempPath.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <thread>

using namespace tactiscope;
using devices::PortSource;
using devices::ReadStatus;
using devices::WireProtocol;
using devices::emulator::EmulatorOptions;
using devices::emulator::ProbeEmulator;
using devices::transport::PosixSerialTransport;
using devices::transport::TransportError;

using tactiscope::testing::uniqueTempPath;

namespace {

std::unique_ptr<PortSource> connect(const std::string& link, WireProtocol protocol, std::optional<double> rate = {})
{
    return std::make_unique<PortSource>(
        std::make_unique<PosixSerialTransport>(link, 921600),
        devices::PortSourceOptions{protocol, rate, std::chrono::milliseconds(4000), std::nullopt, {}});
}

// Reads until `samples` samples per channel arrived (or the source fails).
std::vector<core::SampleBlock> readSamples(PortSource& source, std::size_t samples)
{
    std::vector<core::SampleBlock> blocks;
    std::size_t got = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (got < samples && std::chrono::steady_clock::now() < deadline) {
        core::SampleBlock block;
        const auto status = source.readBlock(block, std::chrono::milliseconds(100));
        if (status == ReadStatus::Failed) break;
        if (status == ReadStatus::Block) {
            got += block.sampleCount();
            blocks.push_back(std::move(block));
        }
    }
    return blocks;
}

}  // namespace

TEST(EmulatorPort, BinaryHandshakeAndStreamingGiveTheScenariosSamples)
{
    const std::string link = uniqueTempPath("binary");
    ProbeEmulator emulator({link, WireProtocol::Binary, "panel-scan", 2000.0, std::nullopt, std::nullopt, 0.0, 10, 3});
    emulator.start();
    auto source = connect(link, WireProtocol::Binary);
    ASSERT_EQ(source->channels().size(), 2u);
    EXPECT_EQ(source->channels()[0].name, "a");
    EXPECT_EQ(source->channels()[0].kind, core::ChannelKind::Strain);
    EXPECT_DOUBLE_EQ(source->nominalSampleRate_hz(), 2000.0);
    ASSERT_TRUE(source->deviceInfo().has_value());
    EXPECT_EQ(source->deviceInfo()->serialNumber, "EMU-3");
    EXPECT_NE(source->name().find("EMU-3"), std::string::npos);

    const auto blocks = readSamples(*source, 600);
    // The same scenario generated here gives the same samples (to float32).
    auto reference = devices::simulator::makeScenario("panel-scan", 3, 2000.0);
    core::SampleBlock expected(2, 600, 0.0, 0.0005);
    reference->generate(expected);
    std::size_t index = 0;
    for (const auto& block : blocks) {
        EXPECT_EQ(block.firstSampleIndex(), index);
        for (std::size_t s = 0; s < block.sampleCount() && index + s < 600; ++s) {
            ASSERT_EQ(block.value(1, s), static_cast<double>(static_cast<float>(expected.value(1, index + s))));
        }
        index += block.sampleCount();
    }
    EXPECT_GE(index, 600u);
    EXPECT_EQ(source->decoderCounters().crcErrors, 0u);
    EXPECT_EQ(source->decoderCounters().samplesLost, 0u);

    // The newest block has just arrived, so its end on the host clock lies
    // shortly before now (never after: the transport only adds delay).
    const double now_s = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    const double end_s = source->hostTime_s(blocks.back().endTime_s());
    EXPECT_LE(end_s, now_s + 1e-3);
    EXPECT_GT(end_s, now_s - 0.5);
}

TEST(EmulatorPort, TextProtocolWithAGivenRate)
{
    const std::string link = uniqueTempPath("text");
    ProbeEmulator emulator({link, WireProtocol::Text, "palpation", 500.0, std::nullopt, std::nullopt, 0.0, 5, 1});
    emulator.start();
    auto source = connect(link, WireProtocol::Text, 500.0);
    ASSERT_EQ(source->channels().size(), 3u);
    EXPECT_EQ(source->channels()[2].name, "displacement");
    const auto blocks = readSamples(*source, 200);
    ASSERT_FALSE(blocks.empty());
    EXPECT_DOUBLE_EQ(blocks[0].dt_s(), 0.002);
    EXPECT_EQ(source->decoderCounters().linesSkipped, 0u);
}

TEST(EmulatorPort, ATextProbeOpenedMidStreamIsTimedByWhatArrivesAfterwards)
{
    // A text probe streams from power-up: by the time the port is opened,
    // old lines fill its buffer, the last one cut mid-line. Before, the rate
    // was estimated at 1162 to 2312 Hz for this 1000 Hz probe (the waiting
    // lines counted as arrivals), or the fragment fixed the column count.
    const std::string link = uniqueTempPath("text-waiting");
    EmulatorOptions options;
    options.linkPath = link;
    options.protocol = WireProtocol::Text;
    options.scenario = "panel-scan";
    options.rate_hz = 1000.0;
    options.samplesPerFrame = 7;  // lines come in odd bursts, so an opening cuts one
    ProbeEmulator emulator(options);
    emulator.start();
    std::this_thread::sleep_for(std::chrono::seconds(1));
    auto source = connect(link, WireProtocol::Text);
    EXPECT_EQ(source->channels().size(), 2u);
    EXPECT_NEAR(source->nominalSampleRate_hz(), 1000.0, 1.0);
    ASSERT_TRUE(source->rateNote());
    EXPECT_NE(source->rateNote()->find("was measured from the arrival times"), std::string::npos)
        << *source->rateNote();
    EXPECT_NE(source->rateNote()->find(" ± "), std::string::npos) << *source->rateNote();
}

TEST(EmulatorPort, InjectedGarbageIsCountedAndNoGoodFrameIsLost)
{
    const std::string link = uniqueTempPath("garbage");
    ProbeEmulator emulator({link, WireProtocol::Binary, "panel-scan", 4000.0, 4u, 1.0, 0.3, 8, 5});
    emulator.start();
    auto source = connect(link, WireProtocol::Binary);
    ASSERT_EQ(source->channels().size(), 4u);
    EXPECT_EQ(source->channels()[3].name, "b2");
    std::size_t received = 0;
    for (;;) {
        core::SampleBlock block;
        const auto status = source->readBlock(block, std::chrono::milliseconds(200));
        if (status == ReadStatus::Failed) break;  // the emulator hung up after 1 s
        if (status == ReadStatus::Block) received += block.sampleCount();
    }
    const auto sent = emulator.stats();
    const auto seen = source->decoderCounters();
    EXPECT_GT(sent.corruptedFrames, 10u);
    EXPECT_GT(sent.garbageBursts, 10u);
    EXPECT_EQ(sent.droppedFrames, 0u);
    EXPECT_EQ(seen.crcErrors, sent.corruptedFrames);
    EXPECT_LE(seen.resyncs, sent.garbageBursts + sent.corruptedFrames);
    EXPECT_EQ(received, sent.samplesSent);                  // every intact frame arrived
    EXPECT_EQ(seen.samplesLost, sent.corruptedFrames * 8);  // the sequence gaps
}

TEST(EmulatorPort, TheFarEndHangingUpIsReportedAsADisconnect)
{
    const std::string link = uniqueTempPath("hangup");
    ProbeEmulator emulator({link, WireProtocol::Binary, "panel-scan", 1000.0, std::nullopt, 0.3, 0.0, 10, 1});
    emulator.start();
    auto source = connect(link, WireProtocol::Binary);
    core::SampleBlock block;
    ReadStatus status = ReadStatus::Timeout;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (status != ReadStatus::Failed && std::chrono::steady_clock::now() < deadline)
        status = source->readBlock(block, std::chrono::milliseconds(100));
    ASSERT_EQ(status, ReadStatus::Failed);
    EXPECT_NE(source->lastError().find("disconnected"), std::string::npos) << source->lastError();
    EXPECT_TRUE(emulator.finished());
}

TEST(EmulatorPort, ClearErrorsForMissingBusyAndSilentPorts)
{
    try {
        PosixSerialTransport("/dev/nonexistent-tactiscope-port", 115200);
        FAIL();
    } catch (const TransportError& e) {
        EXPECT_NE(std::string(e.what()).find("No such file"), std::string::npos) << e.what();
    }
    const std::string link = uniqueTempPath("busy");
    ProbeEmulator emulator({link, WireProtocol::Binary, "panel-scan", 500.0, std::nullopt, std::nullopt, 0.0, 10, 1});
    {
        PosixSerialTransport first(link, 115200);
        try {
            PosixSerialTransport second(link, 115200);
            FAIL();
        } catch (const TransportError& e) {
            EXPECT_NE(std::string(e.what()).find("another program is using the port"), std::string::npos) << e.what();
        }
    }
    // The emulator was never started: nothing answers the handshake.
    try {
        PortSource silent(std::make_unique<PosixSerialTransport>(uniqueTempPath("busy"), 9600),
                          {WireProtocol::Binary, std::nullopt, std::chrono::milliseconds(300), std::nullopt, {}});
        FAIL();
    } catch (const TransportError& e) {
        EXPECT_NE(std::string(e.what()).find("no TSP/1 frames within 300 ms"), std::string::npos) << e.what();
    }
}
