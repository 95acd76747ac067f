// The text protocol over a real pseudo-terminal written by hand, the way a
// maker's board prints: unlabelled and labelled lines, CRLF and LF, tabs,
// spaces and commas, and junk lines that are counted and skipped.
#include "devices/PortSource.h"

#include "core/SampleBlock.h"
#include "devices/transport/PosixSerialTransport.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <stdlib.h>
#include <string_view>
#include <thread>
#include <unistd.h>

using namespace tactiscope;
using devices::PortSource;
using devices::ReadStatus;

namespace {

// The master side of a new pty; the slave's path comes back in `slave`.
int openPtyMaster(std::string& slave)
{
    const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0) return -1;
    slave = ::ptsname(master);
    return master;
}

// Opens the port (raw mode is set before anything is written), writes
// `text` as the board would, and reads `samples` samples at a given rate.
std::pair<std::unique_ptr<PortSource>, std::vector<double>> readText(std::string_view text, std::size_t channel,
                                                                     std::size_t samples)
{
    std::string slave;
    const int master = openPtyMaster(slave);
    EXPECT_GE(master, 0);
    auto transport = std::make_unique<devices::transport::PosixSerialTransport>(slave, 115200);
    // The board prints once the port is open (what waits before is read
    // away as another session's).
    std::jthread board([master, text] {
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        EXPECT_EQ(::write(master, text.data(), text.size()), static_cast<ssize_t>(text.size()));
    });
    auto source = std::make_unique<PortSource>(
        std::move(transport),
        devices::PortSourceOptions{
            devices::WireProtocol::Text, 100.0, std::chrono::milliseconds(3000), std::nullopt, {}});
    board.join();
    std::vector<double> values;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (values.size() < samples && std::chrono::steady_clock::now() < deadline) {
        core::SampleBlock block;
        if (source->readBlock(block, std::chrono::milliseconds(100)) != ReadStatus::Block) continue;
        for (std::size_t s = 0; s < block.sampleCount(); ++s) values.push_back(block.value(channel, s));
    }
    ::close(master);
    return {std::move(source), values};
}

}  // namespace

TEST(TextPort, UnlabelledLinesWithMixedSeparatorsAndEndingsAndJunk)
{
    const auto [source, second] = readText("1.5,2.5\r\n3 4\nthis is not a sample\n5\t6\r\n7, 8\n", 1, 4);
    ASSERT_EQ(source->channels().size(), 2u);
    EXPECT_EQ(source->channels()[0].name, "ch1");
    EXPECT_EQ(source->channels()[1].name, "ch2");
    EXPECT_EQ(second, (std::vector<double>{2.5, 4.0, 6.0, 8.0}));
    EXPECT_EQ(source->decoderCounters().linesSkipped, 1u);
    EXPECT_DOUBLE_EQ(source->nominalSampleRate_hz(), 100.0);
}

TEST(TextPort, LabelledLinesNameTheChannels)
{
    const auto [source, force] =
        readText("force:0.25 pos:-1\r\nforce:0.5 pos:-2\r\n#debug: reset\r\nforce:0.75\tpos:-3\r\n", 0, 3);
    ASSERT_EQ(source->channels().size(), 2u);
    EXPECT_EQ(source->channels()[0].name, "force");
    EXPECT_EQ(source->channels()[1].name, "pos");
    EXPECT_EQ(force, (std::vector<double>{0.25, 0.5, 0.75}));
    EXPECT_EQ(source->decoderCounters().linesSkipped, 1u);
}
