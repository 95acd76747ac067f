// TSP/1 bytes → SampleBlocks: decodes frames, applies the channel scaling of
// the last INFO frame, unwraps the device's 32-bit microsecond clock and
// numbers samples so that a loss shows as a gap in firstSampleIndex.
//
// Nothing the device says about time is believed alone:
// - A sequence gap is a loss only when the device clock agrees (the frame's
//   timestamp is as far on as the missing frames would take it); otherwise
//   it is a sequence fault, counted, and no sample is invented. A sequence
//   that never moves is thus no loss.
// - A clock that goes back (not a 32-bit wrap) is a device restart: the
//   stream goes on after a gap as long as the host saw pass, with a notice.
// - However the two agree, the samples lost between the first frame and now
//   never exceed what the host clock allows at the device's rate (plus a
//   second of slack for buffering): a device cannot make hours out of
//   seconds.
// - The rate is checked twice: against the device clock over a run of
//   consecutive frames (an INFO rate more than 2 % off it, or two samples
//   of stamping jitter over a short run, is wrong), and
//   against the host's arrivals from its first seconds (10 % off, or a
//   quarter second, whichever is more: clock and rate both wrong, or a
//   bad estimate). Either makes
//   rateProblem() say why; the stream cannot be recorded truthfully then.
//
// Without an INFO frame the channels are ch1…chN, unscaled, and the sample
// interval is taken from the timestamps of the first two DATA frames (the
// first frame waits for the second).
#pragma once

#include "core/SampleBlock.h"
#include "devices/LinkNotice.h"
#include "devices/protocol/BinaryDecoder.h"

#include <deque>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tactiscope::devices::protocol {

struct StreamOutput {
    std::vector<core::SampleBlock> blocks;
    std::vector<StatusPayload> statuses;
    std::vector<LinkNotice> notices;
    bool infoChanged = false;
};

class BinaryStream {
public:
    // hostTime_s: when the bytes arrived, on a steady host clock.
    void push(std::span<const std::uint8_t> bytes, double hostTime_s, StreamOutput& out);

    const std::optional<DeviceInfo>& info() const { return m_info; }
    // Known once an INFO or a second DATA frame has arrived.
    std::optional<double> sampleRate_hz() const;
    std::vector<core::ChannelDescriptor> channels() const;
    const DecoderCounters& counters() const { return m_counters; }
    // The rate by the device clock over the latest run of consecutively
    // numbered frames; none before two such frames have arrived.
    std::optional<double> clockRate_hz() const { return m_clockRate_hz; }
    std::uint64_t dataFrames() const { return m_dataFrames; }
    // Why the rate cannot be believed (see above); none while it can.
    const std::optional<std::string>& rateProblem() const { return m_rateProblem; }
    void reset();

private:
    void onData(const Frame& frame, double hostTime_s, StreamOutput& out);
    // Samples lost before this frame, as far as sequence, clock and host agree.
    std::uint64_t believedLoss(std::uint16_t sequence, std::uint64_t timestamp_us, double hostTime_s,
                               StreamOutput& out);
    void restart(std::uint64_t timestamp_us, std::size_t samples, double hostTime_s, StreamOutput& out);
    void publish(const DataPayload& data, std::uint64_t timestamp_us, StreamOutput& out);
    double streamTime_s(std::uint64_t timestamp_us) const;
    void checkRate(double hostTime_s);
    void checkArrivals(double hostTime_s, double rate);
    void measureClockRate(std::uint16_t sequence, std::uint64_t timestamp_us);

    BinaryDecoder m_decoder;
    DecoderCounters m_counters;
    std::optional<DeviceInfo> m_info;
    std::optional<double> m_estimatedInterval_s;
    std::optional<std::pair<DataPayload, std::uint64_t>> m_waiting;  // first frame, until the interval is known
    std::optional<std::uint16_t> m_lastSequence;
    // INFO and STATUS frames since the last DATA frame: each took a sequence
    // number (+1 per frame sent, docs/protocol.md), so a reply to a command
    // between two DATA frames is no frame lost.
    std::uint16_t m_otherFrames = 0;
    std::uint16_t m_lastSamples = 0;
    std::optional<std::uint32_t> m_lastRawTimestamp;
    std::uint64_t m_lastTimestamp_us = 0;  // unwrapped, of the last frame
    std::uint64_t m_wraps = 0;
    // Device clock → stream time: this device time is this stream time.
    std::optional<std::uint64_t> m_originDevice_us;
    double m_originTime_s = 0.0;
    double m_lastEnd_s = 0.0;  // stream time just after the last published sample
    std::optional<double> m_lastFaultNotice_s;
    std::optional<double> m_hostStart_s;
    double m_lastHost_s = 0.0;
    std::uint64_t m_nextSampleIndex = 0;
    struct ClockRun {
        std::uint64_t start_us = 0;
        std::uint64_t samples = 0;  // from start_us to the newest frame
    };
    std::optional<ClockRun> m_clockRun;  // consecutively numbered frames
    std::optional<double> m_clockRate_hz;
    std::uint64_t m_dataFrames = 0;
    // The host's arrivals against the stated rate (checkArrivals).
    struct Arrivals {
        double start_s = 0.0;  // host time the watch began
        std::uint64_t startIndex = 0;
        double baseline = 0.0;                         // least lead of the host over the samples, first second
        std::deque<std::pair<double, double>> recent;  // host time, lead: the last seconds' least leads
    };
    std::optional<Arrivals> m_arrivals;
    std::optional<std::string> m_rateProblem;
    std::uint32_t m_blockSequence = 0;
    std::size_t m_dataChannels = 0;
    std::vector<Frame> m_frames;  // scratch
};

}  // namespace tactiscope::devices::protocol
