// HID report framing, fed with recorded reports through the ReportReader
// seam: frames split across reports reach PortSource whole, commands leave
// as padded output reports, and malformed reports are counted.
#include "devices/transport/HidTransport.h"

#include "devices/PortSource.h"
#include "devices/protocol/BinaryProtocol.h"

#include <gtest/gtest.h>

#include <deque>

using namespace tactiscope;
using namespace tactiscope::devices;
using transport::HidTransport;
using transport::kHidReportSize;

namespace {

class RecordedReports final : public transport::ReportReader {
public:
    explicit RecordedReports(std::deque<std::vector<std::uint8_t>> reports,
                             std::vector<std::vector<std::uint8_t>>* written)
        : m_reports(std::move(reports)),
          m_written(written)
    {
    }
    std::string description() const override { return "recorded HID reports"; }
    // Like TSP/1 firmware, it answers once the host has spoken (request
    // info, start): a host reads away what waited before it did.
    std::optional<std::vector<std::uint8_t>> readReport(std::chrono::milliseconds) override
    {
        if (m_reports.empty() || m_written->empty()) return std::nullopt;
        auto report = std::move(m_reports.front());
        m_reports.pop_front();
        return report;
    }
    void writeReport(std::span<const std::uint8_t> report) override
    {
        m_written->emplace_back(report.begin(), report.end());
    }

private:
    std::deque<std::vector<std::uint8_t>> m_reports;
    std::vector<std::vector<std::uint8_t>>* m_written;
};

std::deque<std::vector<std::uint8_t>> asReports(const std::vector<std::uint8_t>& bytes)
{
    std::deque<std::vector<std::uint8_t>> reports;
    for (const auto& r : transport::packHidReports(bytes)) reports.emplace_back(r.begin(), r.end());
    return reports;
}

}  // namespace

TEST(HidTransport, ReportsAreCutAndReassembledExactly)
{
    std::vector<std::uint8_t> bytes(150);
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<std::uint8_t>(i);
    const auto reports = transport::packHidReports(bytes);
    ASSERT_EQ(reports.size(), 3u);  // 63 + 63 + 24
    EXPECT_EQ(reports[2][0], 24);
    EXPECT_EQ(reports[2][25], 0);  // padding
    std::vector<std::uint8_t> back;
    for (const auto& r : reports) {
        const auto payload = transport::hidReportPayload(r);
        back.insert(back.end(), payload->begin(), payload->end());
    }
    EXPECT_EQ(back, bytes);
    EXPECT_FALSE(transport::hidReportPayload(std::vector<std::uint8_t>{0, 1, 2}).has_value());  // n = 0
    EXPECT_FALSE(transport::hidReportPayload(std::vector<std::uint8_t>{64}).has_value());       // n > 63
    EXPECT_FALSE(transport::hidReportPayload(std::vector<std::uint8_t>{5, 1, 2}).has_value());  // short report
}

TEST(HidTransport, APortSourceReadsFramesSplitAcrossRecordedReports)
{
    using namespace protocol;
    std::vector<std::uint8_t> stream =
        encodeFrame(FrameType::Info, 0,
                    encodeInfo({"Acme",
                                "HID-probe",
                                "H7",
                                "2.0",
                                1000000,
                                {{{"c", "F", core::ChannelKind::Capacitance}, 1e-15f, 5e-11f}}}));
    for (std::uint16_t s = 1; s <= 5; ++s) {
        DataPayload data{s * 20000u, SampleFormat::Int32, 1, 20, {}};
        for (int i = 0; i < 20; ++i) data.raw.push_back(s * 100 + i);
        const auto frame = encodeFrame(FrameType::Data, s, encodeData(data));  // 98 bytes: spans two reports
        stream.insert(stream.end(), frame.begin(), frame.end());
    }
    auto reports = asReports(stream);
    reports.insert(reports.begin() + 2, std::vector<std::uint8_t>(kHidReportSize, 0));  // a malformed report
    std::vector<std::vector<std::uint8_t>> written;
    auto transport = std::make_unique<HidTransport>(std::make_unique<RecordedReports>(reports, &written));
    auto* hid = transport.get();
    PortSource source(std::move(transport), {});
    EXPECT_EQ(source.channels()[0].kind, core::ChannelKind::Capacitance);
    EXPECT_DOUBLE_EQ(source.nominalSampleRate_hz(), 1000.0);

    std::size_t samples = 0;
    core::SampleBlock block;
    // A malformed report yields no bytes (a timeout): read on until the
    // recording has run dry several times.
    for (int idle = 0; idle < 5;) {
        if (source.readBlock(block, std::chrono::milliseconds(10)) != ReadStatus::Block) {
            ++idle;
            continue;
        }
        // Frame s carries s·100 + i; scale and offset arrive as float32.
        const auto frameNumber = static_cast<double>(block.firstSampleIndex() / 20 + 1);
        EXPECT_DOUBLE_EQ(block.value(0, 0),
                         frameNumber * 100 * static_cast<double>(1e-15f) + static_cast<double>(5e-11f));
        samples += block.sampleCount();
    }
    EXPECT_EQ(samples, 100u);
    EXPECT_EQ(hid->malformedReports(), 1u);
    // The handshake left as padded output reports: request info, then start.
    ASSERT_EQ(written.size(), 2u);
    EXPECT_EQ(written[0].size(), kHidReportSize);
    EXPECT_EQ(parseCommand({written[0].begin() + 1 + kHeaderSize, written[0].begin() + 1 + kHeaderSize + 1})->code,
              CommandCode::RequestInfo);
}

// A probe whose INFO names two channels alike is refused at the handshake,
// naming the name: before, it was recorded, and its export (columns named
// by the channels) could not be imported back.
TEST(PortSourceHandshake, AProbeNamingTwoChannelsAlikeIsRefused)
{
    using namespace protocol;
    const ChannelInfo a{{"a", "", core::ChannelKind::Strain}, 1e-9f, 0.0f};
    std::vector<std::uint8_t> stream =
        encodeFrame(FrameType::Info, 0, encodeInfo({"Acme", "twin", "T1", "1.0", 500000, {a, a}}));
    for (std::uint16_t s = 1; s <= 5; ++s) {
        DataPayload data{s * 20000u, SampleFormat::Int32, 2, 10, {}};
        data.raw.assign(20, 7);
        const auto frame = encodeFrame(FrameType::Data, s, encodeData(data));
        stream.insert(stream.end(), frame.begin(), frame.end());
    }
    std::vector<std::vector<std::uint8_t>> written;
    try {
        PortSource source(
            std::make_unique<HidTransport>(std::make_unique<RecordedReports>(asReports(stream), &written)), {});
        ADD_FAILURE() << "a probe with two channels 'a' was opened";
    } catch (const transport::TransportError& e) {
        EXPECT_NE(std::string(e.what()).find("two of its channels are called 'a'; each needs a name of its own"),
                  std::string::npos)
            << e.what();
    }
}
