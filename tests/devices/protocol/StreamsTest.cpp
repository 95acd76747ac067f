// Frames and lines into SampleBlocks: scaling, gaps, clock wrap, rates.
#include "devices/protocol/BinaryStream.h"
#include "devices/protocol/TextStream.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>

using namespace tactiscope::devices::protocol;
using tactiscope::core::ChannelKind;

namespace {

std::vector<std::uint8_t> data(std::uint16_t sequence, std::uint32_t timestamp_us, std::int16_t value,
                               std::uint16_t samples = 4)
{
    DataPayload d{timestamp_us, SampleFormat::Int16, 2, samples, {}};
    for (std::uint16_t s = 0; s < samples; ++s) {
        d.raw.push_back(value + s);
        d.raw.push_back(-(value + s));
    }
    return encodeFrame(FrameType::Data, sequence, encodeData(d));
}

std::vector<std::uint8_t> info()
{
    return encodeFrame(
        FrameType::Info, 0,
        encodeInfo({"Acme",
                    "P2",
                    "SN9",
                    "1.0",
                    1000000,  // 1 kHz
                    {{{"a", "", ChannelKind::Strain}, 1e-6f, 0.0f}, {{"b", "", ChannelKind::Strain}, 2e-6f, 1e-5f}}}));
}

}  // namespace

TEST(BinaryStream, ScalesSamplesWithTheInfoFramesChannels)
{
    BinaryStream stream;
    StreamOutput out;
    auto bytes = info();
    const auto frame = data(0, 5000, 100);
    bytes.insert(bytes.end(), frame.begin(), frame.end());
    stream.push(bytes, 0.0, out);
    EXPECT_TRUE(out.infoChanged);
    ASSERT_EQ(out.blocks.size(), 1u);
    const auto& block = out.blocks[0];
    EXPECT_DOUBLE_EQ(block.dt_s(), 0.001);
    // Scale and offset travel as float32: expect exactly what they encode.
    EXPECT_DOUBLE_EQ(block.value(0, 2), 102 * static_cast<double>(1e-6f));
    EXPECT_DOUBLE_EQ(block.value(1, 2), -102 * static_cast<double>(2e-6f) + static_cast<double>(1e-5f));
    EXPECT_EQ(stream.channels()[1].name, "b");
    EXPECT_EQ(stream.info()->serialNumber, "SN9");
}

TEST(BinaryStream, CountsSamplesLostToSequenceGapsAndLeavesAGapInTheIndex)
{
    BinaryStream stream;
    StreamOutput out;
    stream.push(info(), 0.0, out);
    stream.push(data(10, 0, 0), 0.0, out);
    stream.push(data(11, 4000, 4), 0.0, out);
    stream.push(data(14, 16000, 16), 0.0, out);  // frames 12 and 13 lost
    ASSERT_EQ(out.blocks.size(), 3u);
    EXPECT_EQ(stream.counters().samplesLost, 8u);
    EXPECT_EQ(out.blocks[2].firstSampleIndex(), 16u);
    EXPECT_EQ(out.blocks[2].samplesLostAfter(out.blocks[1].endSampleIndex()), 8u);
    EXPECT_DOUBLE_EQ(out.blocks[2].t0_s(), 0.016);
}

// Every frame sent takes a sequence number (docs/protocol.md): a probe's
// STATUS reply to a command (the shunt check's) between two DATA frames is
// no frame lost and no sequence fault; DATA frames lost before one still are.
TEST(BinaryStream, AStatusFrameBetweenDataFramesTakesItsSequenceNumberAndLosesNothing)
{
    BinaryStream stream;
    StreamOutput out;
    stream.push(info(), 0.0, out);
    stream.push(data(10, 0, 0), 0.004, out);
    stream.push(data(11, 4000, 4), 0.008, out);
    stream.push(encodeFrame(FrameType::Status, 12, encodeStatus({StatusLevel::Ok, "shunt on a"})), 0.009, out);
    stream.push(data(13, 8000, 8), 0.012, out);
    EXPECT_EQ(stream.counters().samplesLost, 0u);
    EXPECT_EQ(stream.counters().sequenceFaults, 0u);
    EXPECT_TRUE(out.notices.empty());
    // Frames 15 and 16 lost, then a reply (17), then DATA 18: 8 samples lost.
    stream.push(data(14, 12000, 12), 0.016, out);
    stream.push(encodeFrame(FrameType::Status, 17, encodeStatus({StatusLevel::Ok, "shunt off a"})), 0.025, out);
    stream.push(data(18, 24000, 24), 0.028, out);
    EXPECT_EQ(stream.counters().samplesLost, 8u);
    EXPECT_EQ(stream.counters().sequenceFaults, 0u);
    ASSERT_EQ(out.blocks.size(), 5u);
    EXPECT_EQ(out.blocks[4].firstSampleIndex(), 24u);
}

namespace {

// Ten frames of 4 samples at 1 kHz (sequence 0…9, clock 0…36 ms), each
// arriving on the host when its last sample is taken: 4, 8, … 40 ms.
void tenFrames(BinaryStream& stream, StreamOutput& out)
{
    stream.push(info(), 0.0, out);
    for (std::uint16_t k = 0; k < 10; ++k) stream.push(data(k, 4000u * k, 0), 0.004 * (k + 1), out);
}

}  // namespace

TEST(BinaryStream, ARestartIsAGapOfTheTimeTheHostSawPassNotOfTheSequencesWrap)
{
    BinaryStream stream;
    StreamOutput out;
    tenFrames(stream, out);
    // Silent for 0.5 s, then sequence and clock from 0; the frame arrives
    // 4 ms after its first sample.
    stream.push(data(0, 0, 0), 0.040 + 0.5 + 0.004, out);
    stream.push(data(1, 4000, 0), 0.040 + 0.5 + 0.008, out);
    ASSERT_EQ(out.blocks.size(), 12u);
    EXPECT_EQ(stream.counters().deviceRestarts, 1u);
    EXPECT_EQ(stream.counters().samplesLost, 500u);  // 0.5 s at 1 kHz, not 65 526 frames
    EXPECT_EQ(out.blocks[10].firstSampleIndex(), 540u);
    EXPECT_NEAR(out.blocks[10].t0_s(), 0.540, 1e-9);
    EXPECT_NEAR(out.blocks[11].t0_s(), 0.544, 1e-9);
    ASSERT_EQ(out.notices.size(), 1u);
    EXPECT_NEAR(out.notices[0].time_s, 0.040, 1e-9);
    EXPECT_NE(out.notices[0].text.find("restarted"), std::string::npos) << out.notices[0].text;
    EXPECT_NE(out.notices[0].text.find("0.5 s without samples"), std::string::npos) << out.notices[0].text;
}

TEST(BinaryStream, ASequenceThatNeverMovesIsNoLoss)
{
    BinaryStream stream;
    StreamOutput out;
    stream.push(info(), 0.0, out);
    for (std::uint32_t k = 0; k < 10; ++k) stream.push(data(0, 4000u * k, 0), 0.004 * (k + 1), out);
    ASSERT_EQ(out.blocks.size(), 10u);
    EXPECT_EQ(stream.counters().samplesLost, 0u);
    EXPECT_EQ(out.blocks[9].firstSampleIndex(), 36u);
    EXPECT_NEAR(out.blocks[9].t0_s(), 0.036, 1e-9);
    EXPECT_EQ(stream.counters().sequenceFaults, 9u);
    EXPECT_EQ(out.notices.size(), 1u);  // told once, counted always
}

TEST(BinaryStream, ASequenceJumpTheClockDoesNotConfirmIsNoLoss)
{
    BinaryStream stream;
    StreamOutput out;
    stream.push(info(), 0.0, out);
    for (std::uint16_t k = 0; k < 10; ++k) {
        const std::uint16_t sequence = k == 5 ? static_cast<std::uint16_t>(k + 30000) : k;
        stream.push(data(sequence, 4000u * k, 0), 0.004 * (k + 1), out);
    }
    EXPECT_EQ(stream.counters().samplesLost, 0u);
    EXPECT_EQ(out.blocks[9].firstSampleIndex(), 36u);
    EXPECT_NEAR(out.blocks[9].t0_s(), 0.036, 1e-9);
    EXPECT_EQ(stream.counters().sequenceFaults, 2u);  // the jump, and the step back after it
}

TEST(BinaryStream, ALossNeverExceedsWhatTheHostSawTimeFor)
{
    BinaryStream stream;
    StreamOutput out;
    tenFrames(stream, out);
    // Sequence and clock agree on 1000 lost frames (4 s), but the host saw
    // 4 ms pass: since the first frame (host 4 ms) at most (0.040 s + 0.25 s
    // of slack) × 1 kHz × 1.01 = 292 samples may have gone by (the bound
    // was 10 % and 1 s looser: 1144).
    stream.push(data(1010, 4000u * 1010, 0), 0.044, out);
    ASSERT_EQ(out.blocks.size(), 11u);
    EXPECT_EQ(out.blocks[10].firstSampleIndex(), 292u);
    EXPECT_EQ(stream.counters().samplesLost, 252u);
    EXPECT_EQ(stream.counters().sequenceFaults, 1u);
}

TEST(BinaryStream, UnwrapsTheDeviceClock)
{
    BinaryStream stream;
    StreamOutput out;
    stream.push(info(), 0.0, out);
    stream.push(data(0, 0xFFFFF830u, 0), 0.0, out);  // 2000 µs before the wrap
    stream.push(data(1, 0x000007D0u, 4), 0.0, out);  // 2000 µs after it
    ASSERT_EQ(out.blocks.size(), 2u);
    EXPECT_NEAR(out.blocks[1].t0_s() - out.blocks[0].t0_s(), 4000e-6, 1e-12);
    EXPECT_EQ(stream.counters().deviceRestarts, 0u);  // a wrap, not a restart
    EXPECT_EQ(stream.counters().sequenceFaults, 0u);
}

TEST(BinaryStream, WithoutInfoTheRateComesFromTheTimestamps)
{
    BinaryStream stream;
    StreamOutput out;
    stream.push(data(0, 1000, 7), 0.0, out);
    EXPECT_TRUE(out.blocks.empty());           // the first frame waits for the interval
    stream.push(data(1, 3000, 11), 0.0, out);  // 4 samples in 2000 µs: 2 kHz
    ASSERT_EQ(out.blocks.size(), 2u);
    EXPECT_DOUBLE_EQ(*stream.sampleRate_hz(), 2000.0);
    EXPECT_EQ(stream.channels()[0].name, "ch1");
    EXPECT_EQ(out.blocks[0].value(0, 0), 7.0);  // unscaled
    EXPECT_EQ(out.blocks[1].firstSampleIndex(), 4u);
}

TEST(BinaryStream, PassesStatusMessagesAndCountsMalformedPayloads)
{
    BinaryStream stream;
    StreamOutput out;
    auto bytes = encodeFrame(FrameType::Status, 0, encodeStatus({StatusLevel::Error, "bridge open"}));
    const auto bad = encodeFrame(FrameType::Data, 1, {1, 2, 3});
    bytes.insert(bytes.end(), bad.begin(), bad.end());
    stream.push(bytes, 0.0, out);
    ASSERT_EQ(out.statuses.size(), 1u);
    EXPECT_EQ(out.statuses[0].message, "bridge open");
    EXPECT_EQ(stream.counters().malformedPayloads, 1u);
}

TEST(TextStream, UsesTheGivenRate)
{
    TextStream stream(250.0);
    std::vector<tactiscope::core::SampleBlock> out;
    const std::string text = "a:1 b:2\na:3 b:4\n";
    stream.push(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()), 0.0, out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_DOUBLE_EQ(out[0].dt_s(), 0.004);
    EXPECT_EQ(out[0].value(1, 1), 4.0);
    EXPECT_EQ(stream.channels()[1].name, "b");
}

// A label may say the channel's role (docs/protocol.md, "Channel roles"):
// NAME@ROLE, or a role's name; anything else is only a name.
TEST(TextStream, LabelsMayGiveTheChannelsRoles)
{
    TextStream stream(100.0);
    std::vector<tactiscope::core::SampleBlock> out;
    const std::string text = "a@cantilever-a:1 stiff-beam:2 t@kelvin:3 @soft-beam:4\n"
                             "a@cantilever-a:1 stiff-beam:2 t@kelvin:3 @soft-beam:4\n";
    stream.push(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()), 0.0, out);
    const auto channels = stream.channels();
    ASSERT_EQ(channels.size(), 4u);
    EXPECT_EQ(channels[0].name, "a");
    EXPECT_EQ(channels[0].role, tactiscope::core::ChannelRole::CantileverA);
    EXPECT_EQ(channels[1].name, "stiff-beam");
    EXPECT_EQ(channels[1].role, tactiscope::core::ChannelRole::StiffBeam);
    EXPECT_EQ(channels[2].name, "t@kelvin");  // not a role: the label is the name
    EXPECT_FALSE(channels[2].role);
    EXPECT_EQ(channels[3].name, "@soft-beam");  // no name before the @: the label is the name
    EXPECT_FALSE(channels[3].role);
    for (const auto& channel : channels) EXPECT_EQ(channel.kind, ChannelKind::Other);
}

TEST(TextStream, MeasuresTheRateFromTheArrivalsAndHoldsTheLinesUntilThen)
{
    TextStream stream;
    std::vector<tactiscope::core::SampleBlock> out;
    // 100 lines per second, arriving in bursts of five every 50 ms: timed
    // from the first read after 0.5 s (0.55 s) on, over at least 2 s, and
    // until the ± is within 100 ppm or the lines span 10 s.
    int burst = 0;
    for (; burst < 300 && !stream.sampleRate_hz(); ++burst) {
        std::string text;
        for (int i = 0; i < 5; ++i) text += std::to_string(burst * 5 + i) + "\n";
        stream.push(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()), burst * 0.05, out);
    }
    ASSERT_TRUE(stream.sampleRate_hz().has_value());
    const double timedOver_s = (burst - 1) * 0.05 - 0.55;
    EXPECT_GE(timedOver_s, LineRate::kWindow_s);
    EXPECT_LE(timedOver_s, 1.1 * LineRate::kLongestWindow_s + 0.05);  // looked at as the lines grow by a tenth
    EXPECT_TRUE(*stream.measuredRate()->u_hz <= LineRate::kSettledU * 100.0 ||
                timedOver_s >= LineRate::kLongestWindow_s);
    // Five lines arrive at once: each is up to 40 ms late, in a sawtooth
    // the stated uncertainty covers.
    ASSERT_TRUE(stream.measuredRate() && stream.measuredRate()->u_hz);
    EXPECT_NEAR(*stream.sampleRate_hz(), 100.0, 2.0 * *stream.measuredRate()->u_hz);
    EXPECT_LT(*stream.measuredRate()->u_hz, 0.5);
    EXPECT_FALSE(stream.measuredRate()->boardClock);
    ASSERT_FALSE(out.empty());
    EXPECT_EQ(out[0].value(0, 0), 0.0);                      // held lines come out first, in order
    EXPECT_EQ(out.size(), static_cast<std::size_t>(burst));  // a block per read
}

TEST(BinaryStream, AnInfoRateItsOwnClockContradictsIsAProblem)
{
    BinaryStream stream;
    StreamOutput out;
    tenFrames(stream, out);  // INFO says 1 kHz, and the clock agrees
    EXPECT_NEAR(*stream.clockRate_hz(), 1000.0, 1e-9);
    EXPECT_FALSE(stream.rateProblem());

    BinaryStream lying;
    StreamOutput lies;
    lying.push(info(), 0.0, lies);
    // 4 samples every 2 ms: 2 kHz by the device's own clock, 100 % off.
    for (std::uint16_t k = 0; k < 3; ++k) lying.push(data(k, 2000u * k, 0), 0.002 * (k + 1), lies);
    ASSERT_TRUE(lying.rateProblem());
    EXPECT_NE(lying.rateProblem()->find("says it samples at 1000 Hz"), std::string::npos) << *lying.rateProblem();
    EXPECT_NE(lying.rateProblem()->find("2000 Hz"), std::string::npos) << *lying.rateProblem();
}

TEST(BinaryStream, AnEstimatedRateTheArrivalsContradictIsAProblem)
{
    BinaryStream stream;
    StreamOutput out;
    // No INFO; the first two frames are stamped 40 ms apart for 4 samples
    // (an estimate of 100 Hz), but frames of 4 samples arrive every 4 ms,
    // as a 1 kHz device's do: caught within its first two seconds.
    stream.push(data(0, 0, 0), 0.004, out);
    for (std::uint16_t k = 1; k < 500 && !stream.rateProblem(); ++k)
        stream.push(data(k, 40000u * k, 0), 0.004 * (k + 1), out);
    EXPECT_DOUBLE_EQ(*stream.sampleRate_hz(), 100.0);
    ASSERT_TRUE(stream.rateProblem());
    EXPECT_NE(stream.rateProblem()->find("arrive at about"), std::string::npos) << *stream.rateProblem();
}

// The arrival check against the host's own timing: a device 20 % faster or
// slower than it says is caught within its first 3.5 or 6 s; a true one
// is not, through a host that stops reading for 1.5 s and then gets the
// backlog at once, or one whose reads come up to 0.2 s late at random.
TEST(BinaryStream, ArrivalsTwentyPercentOffAreCaughtEarlyAndAStallingHostIsNot)
{
    // Frames of 4 samples stamped 4 ms apart (1 kHz by INFO and clock),
    // which the host sees every 4 ms × `pace` (the true rate is 1/pace kHz);
    // `arrival` may delay a frame's reading (never before it was sent).
    const auto firstProblem = [](double pace, const std::function<double(double)>& arrival) -> std::optional<double> {
        BinaryStream stream;
        StreamOutput out;
        stream.push(info(), 0.0, out);
        double last = 0.0;
        for (std::uint16_t k = 0; k < 3000; ++k) {
            const double sent = 0.004 * pace * (k + 1);
            last = std::max(last, arrival(sent));
            stream.push(data(k, 4000u * k, 0), last, out);
            if (stream.rateProblem()) return sent;
        }
        return std::nullopt;
    };
    const auto onTime = [](double sent) { return sent; };
    const auto fast = firstProblem(1.0 / 1.2, onTime);
    ASSERT_TRUE(fast);
    EXPECT_LT(*fast, 3.5);
    const auto slow = firstProblem(1.0 / 0.8, onTime);
    ASSERT_TRUE(slow);
    EXPECT_LT(*slow, 6.0);
    EXPECT_FALSE(firstProblem(1.0, onTime));
    EXPECT_FALSE(firstProblem(1.0, [](double sent) { return sent > 3.0 && sent < 4.5 ? 4.5 : sent; }));
    std::mt19937 random(7);
    std::uniform_real_distribution<double> late(0.0, 0.2);
    EXPECT_FALSE(firstProblem(1.0, [&](double sent) { return sent + late(random); }));
}

namespace {

void pushText(TextStream& stream, const std::string& text, double hostTime_s,
              std::vector<tactiscope::core::SampleBlock>& out)
{
    stream.push(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()), hostTime_s, out);
}

}  // namespace

TEST(TextStream, LinesThatWaitedInThePortDoNotCountInTheRate)
{
    TextStream stream;
    std::vector<tactiscope::core::SampleBlock> out;
    // The first read brings 1000 lines that waited; then 100 lines per
    // second in bursts of five. Counting the backlog too gives 600 Hz.
    std::string waited;
    for (int i = 0; i < 1000; ++i) waited += "1,2\n";
    pushText(stream, waited, 0.0, out);
    for (int burst = 1; burst <= 300 && !stream.sampleRate_hz(); ++burst)
        pushText(stream, "3,4\n3,4\n3,4\n3,4\n3,4\n", burst * 0.05, out);
    ASSERT_TRUE(stream.sampleRate_hz());
    EXPECT_NEAR(*stream.sampleRate_hz(), 100.0, 2.0 * *stream.measuredRate()->u_hz + 1e-9);
    EXPECT_LT(*stream.measuredRate()->u_hz, 0.5);
}

TEST(TextStream, AnUnreadableLineIsALostSampleAndTheRestKeepTheirTime)
{
    TextStream stream(100.0);
    std::vector<tactiscope::core::SampleBlock> out;
    pushText(stream, "1,2\n3,4\n5,#\n7,8\n", 0.0, out);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out[1].firstSampleIndex(), 3u);  // "7,8" is the fourth sample sent
    EXPECT_DOUBLE_EQ(out[1].t0_s(), 0.03);
    EXPECT_EQ(out[1].samplesLostAfter(out[0].endSampleIndex()), 1u);
    EXPECT_EQ(stream.counters().samplesLost, 1u);
    EXPECT_EQ(stream.counters().linesSkipped, 1u);
}

TEST(BinaryStream, ATimestampsJitterIsNoWrongRateButASmallSteadyErrorIs)
{
    // 10 samples per frame at 1 kHz, each frame stamped a sample early or
    // late at random: a single pair of frames may say 800 or 1250 Hz.
    BinaryStream jittery;
    StreamOutput out;
    jittery.push(info(), 0.0, out);
    std::mt19937 random(3);
    for (std::uint16_t k = 0; k < 200; ++k) {
        const auto jitter = static_cast<std::int32_t>(random() % 3) - 1;  // −1, 0, +1 sample
        const auto stamp = static_cast<std::uint32_t>(10000 * k + 1000 * jitter + 1000);
        jittery.push(data(k, stamp, 0, 10), 0.010 * (k + 1), out);
    }
    EXPECT_FALSE(jittery.rateProblem()) << *jittery.rateProblem();

    // INFO says 1 kHz; the clock says 1.05 kHz, steadily: wrong by 5 %.
    BinaryStream fast;
    StreamOutput fastOut;
    fast.push(info(), 0.0, fastOut);
    for (std::uint16_t k = 0; k < 200; ++k)
        fast.push(data(k, static_cast<std::uint32_t>(std::llround(10000 * k / 1.05)), 0, 10), 0.010 * (k + 1), fastOut);
    ASSERT_TRUE(fast.rateProblem());
    EXPECT_NE(fast.rateProblem()->find("clock puts 1050"), std::string::npos) << *fast.rateProblem();
}

TEST(BinaryStream, TheClockRateIsMeasuredAfreshAfterARestart)
{
    BinaryStream stream;
    StreamOutput out;
    tenFrames(stream, out);
    for (std::uint16_t k = 0; k < 5; ++k) stream.push(data(k, 4000u * k, 0), 0.544 + 0.004 * k, out);
    EXPECT_EQ(stream.counters().deviceRestarts, 1u);
    EXPECT_NEAR(*stream.clockRate_hz(), 1000.0, 1e-9);
    EXPECT_FALSE(stream.rateProblem()) << *stream.rateProblem();
}

// A board's new layout continues the stream: its blocks hold the channels
// it grew to, a new channel's unit is its label's, and where it began is
// said with its sample index.
TEST(TextStream, ANewLayoutGrowsTheBlocksFromTheSampleItBeganAt)
{
    TextStream stream(100.0);
    std::vector<tactiscope::core::SampleBlock> out;
    pushText(stream, "a:1\na:2\na:3\n", 0.0, out);
    pushText(stream, "a:4 f[mN]:500\na:5 f[mN]:600\n", 0.05, out);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out[0].channelCount(), 1u);
    EXPECT_EQ(out[1].channelCount(), 2u);
    EXPECT_EQ(out[1].firstSampleIndex(), 3u);
    EXPECT_EQ(out[1].value(0, 1), 5.0);
    EXPECT_DOUBLE_EQ(out[1].value(1, 0), 0.5);  // N
    const auto channels = stream.channels();
    ASSERT_EQ(channels.size(), 2u);
    EXPECT_EQ(channels[1].name, "f");
    EXPECT_EQ(channels[1].unit, "N");
    const auto changes = stream.takeLayoutChanges();
    ASSERT_EQ(changes.size(), 1u);
    EXPECT_EQ(changes[0].sampleIndex, 3u);
    EXPECT_NE(changes[0].what.find("f appeared"), std::string::npos) << changes[0].what;
    EXPECT_TRUE(stream.takeLayoutChanges().empty());
}
