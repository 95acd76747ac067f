// BinaryStream: frames to SampleBlocks with scaling, clock unwrap, and the
// losses that sequence, device clock and host clock agree on.
#include "devices/protocol/BinaryStream.h"

#include "core/text/CountText.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tactiscope::devices::protocol {
namespace {

// How far the device clock may be from what a sequence gap implies and
// still confirm it, in samples: a frame is stamped when its first sample
// is taken, give or take a sample, and half a frame tells a gap of one
// frame from none.
double agreementSamples(std::uint16_t frameSamples)
{
    return std::max(2.0, 0.5 * frameSamples);
}

// The host may have seen the device for up to this much less than the
// stream spans, and the device's crystal may run this much fast, before a
// loss is cut to what the host saw. The slack is the bytes that waited in
// the port (PortSource reads them away for 50 ms at open) and the host's
// delivery latency (a USB serial adapter's 16 ms timer, a busy host); the
// margin is 1 % (10 000 ppm, fifty times a cheap crystal's error): a
// device whose sequence and clock jump forward together can invent at
// most that much lost time (was 10 % plus 1 s: six minutes an hour).
constexpr double kHostSlack_s = 0.25;
constexpr double kHostRateMargin = 1.01;
// A misbehaving device's contradictions are noticed at most this often.
constexpr double kNoticeInterval_s = 10.0;
// An INFO rate this far off the device's own clock is wrong.
constexpr double kClockRateTolerance = 0.02;
// The host's arrivals are judged from this long after the first frame
// (what was buffered before the first read arrives at once), by the lead
// of the host's clock over the samples' times at the stated rate: its least
// over the first second is the delivery latency; a rate that is wrong makes
// it fall (samples come faster than stated) or rise (slower) in proportion
// to the time. The host's timing allows a quarter second either way
// (kHostSlack_s: a late read) or a tenth of the time since, whichever is
// more; a rise must hold for two seconds (a stall of the host delays
// arrivals, never hastens them). So a device 20 % off is caught within its
// first three seconds (before: after two 5 s windows, so a 6 s panel
// stored as 7.27 s). Smaller drifts are PortSource's (its clock mapping,
// core/timing).
constexpr double kArrivalSettle_s = 0.5;
constexpr double kArrivalBaseline_s = 1.0;
constexpr double kArrivalRise_s = 2.0;
constexpr double kArrivalMismatch = 0.10;

std::string hertz(double rate)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.6g Hz", rate);
    return text;
}

std::string seconds(double s)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.1f s", s);
    return text;
}

}  // namespace

void BinaryStream::reset()
{
    *this = BinaryStream{};
}

std::optional<double> BinaryStream::sampleRate_hz() const
{
    if (m_info && m_info->sampleRate_mhz > 0) return m_info->sampleRate_mhz / 1000.0;
    if (m_estimatedInterval_s) return 1.0 / *m_estimatedInterval_s;
    return std::nullopt;
}

std::vector<core::ChannelDescriptor> BinaryStream::channels() const
{
    std::vector<core::ChannelDescriptor> result;
    if (m_info) {
        for (const auto& c : m_info->channels) result.push_back(c.descriptor);
    } else {
        for (std::size_t c = 0; c < m_dataChannels; ++c)
            result.push_back({"ch" + std::to_string(c + 1), "", core::ChannelKind::Other});
    }
    return result;
}

void BinaryStream::push(std::span<const std::uint8_t> bytes, double hostTime_s, StreamOutput& out)
{
    m_frames.clear();
    m_decoder.push(bytes, m_frames);
    for (const Frame& frame : m_frames) {
        if (frame.type == FrameType::Info || frame.type == FrameType::Status) ++m_otherFrames;
        switch (frame.type) {
        case FrameType::Info:
            if (auto info = parseInfo(frame.payload)) {
                m_info = std::move(info);
                out.infoChanged = true;
            } else {
                ++m_counters.malformedPayloads;
            }
            break;
        case FrameType::Data:
            onData(frame, hostTime_s, out);
            break;
        case FrameType::Status:
            if (auto status = parseStatus(frame.payload))
                out.statuses.push_back(std::move(*status));
            else
                ++m_counters.malformedPayloads;
            break;
        case FrameType::Command:
            break;  // an echo or a loopback: not ours to act on
        default:
            ++m_counters.malformedPayloads;
        }
    }
    const auto& d = m_decoder.counters();
    m_counters.bytes = d.bytes;
    m_counters.frames = d.frames;
    m_counters.crcErrors = d.crcErrors;
    m_counters.resyncs = d.resyncs;
}

double BinaryStream::streamTime_s(std::uint64_t timestamp_us) const
{
    return m_originTime_s + (static_cast<double>(timestamp_us) - static_cast<double>(*m_originDevice_us)) * 1e-6;
}

void BinaryStream::onData(const Frame& frame, double hostTime_s, StreamOutput& out)
{
    auto data = parseData(frame.payload);
    if (!data || (m_info && data->channelCount != m_info->channels.size())) {
        ++m_counters.malformedPayloads;
        return;
    }
    if (!m_hostStart_s) m_hostStart_s = hostTime_s;
    ++m_dataFrames;
    // The clock going back by less than half its range is no wrap: the
    // device began counting again.
    const std::uint32_t raw = data->timestamp_us;
    const bool clockWentBack =
        m_lastRawTimestamp && raw < *m_lastRawTimestamp && *m_lastRawTimestamp - raw <= 0x80000000u;
    if (clockWentBack)
        m_wraps = 0;
    else if (m_lastRawTimestamp && raw < *m_lastRawTimestamp)
        ++m_wraps;
    m_lastRawTimestamp = raw;
    const std::uint64_t timestamp = (m_wraps << 32) + raw;

    if (!m_originDevice_us) m_originDevice_us = timestamp;
    if (clockWentBack && m_waiting) {
        // Restarted before the interval was known: the waiting frame has no
        // clock to be placed on any more.
        m_counters.samplesLost += m_waiting->first.samplesPerChannel;
        ++m_counters.deviceRestarts;
        m_waiting.reset();
        m_originDevice_us = timestamp;
    } else if (clockWentBack) {
        restart(timestamp, data->samplesPerChannel, hostTime_s, out);
    } else if (m_lastSequence && !m_waiting) {
        // The number it would have had without the frames of other types.
        const auto sequence = static_cast<std::uint16_t>(frame.sequence - m_otherFrames);
        const std::uint64_t lost = believedLoss(sequence, timestamp, hostTime_s, out);
        m_counters.samplesLost += lost;
        m_nextSampleIndex += lost;
        measureClockRate(sequence, timestamp);
    }
    m_lastSequence = frame.sequence;
    m_otherFrames = 0;
    m_lastSamples = data->samplesPerChannel;
    m_lastTimestamp_us = timestamp;
    m_lastHost_s = hostTime_s;
    m_dataChannels = data->channelCount;

    if (!sampleRate_hz()) {
        if (!m_waiting) {
            m_waiting.emplace(std::move(*data), timestamp);
            return;
        }
        const auto& [first, firstTime] = *m_waiting;
        if (timestamp > firstTime && first.samplesPerChannel > 0)
            m_estimatedInterval_s = static_cast<double>(timestamp - firstTime) * 1e-6 / first.samplesPerChannel;
        else
            m_estimatedInterval_s = 1e-3;  // nothing better to go on; corrected by INFO if it comes
    }
    if (m_waiting) {
        auto waiting = std::move(*m_waiting);
        m_waiting.reset();
        publish(waiting.first, waiting.second, out);
    }
    publish(*data, timestamp, out);
    checkRate(hostTime_s);
}

// The rate by the device clock over the current run of consecutively
// numbered frames: averaged so a timestamp's jitter of a sample or two
// does not look like a wrong rate.
void BinaryStream::measureClockRate(std::uint16_t sequence, std::uint64_t timestamp_us)
{
    if (sequence != static_cast<std::uint16_t>(*m_lastSequence + 1) || timestamp_us <= m_lastTimestamp_us) {
        m_clockRun.reset();
        return;
    }
    if (!m_clockRun) m_clockRun = ClockRun{m_lastTimestamp_us, 0};
    m_clockRun->samples += m_lastSamples;
    m_clockRate_hz =
        static_cast<double>(m_clockRun->samples) / (static_cast<double>(timestamp_us - m_clockRun->start_us) * 1e-6);
}

void BinaryStream::checkRate(double hostTime_s)
{
    if (m_rateProblem) return;
    const double rate = *sampleRate_hz();
    // Two samples of stamping jitter over the run, and never less than 2 %.
    const double tolerance =
        m_clockRun ? std::max(kClockRateTolerance, 2.0 / static_cast<double>(m_clockRun->samples)) : 1.0;
    if (m_info && m_clockRate_hz && std::abs(*m_clockRate_hz / rate - 1.0) > tolerance) {
        m_rateProblem = "the device says it samples at " + hertz(rate) + " but its own clock puts " +
                        hertz(*m_clockRate_hz) +
                        " between its frames: its rate is wrong, and so would every time in "
                        "the recording be; correct the firmware's sample rate";
        return;
    }
    checkArrivals(hostTime_s, rate);
}

void BinaryStream::checkArrivals(double hostTime_s, double rate)
{
    if (hostTime_s - *m_hostStart_s < kArrivalSettle_s) return;
    const double lead = hostTime_s - static_cast<double>(m_nextSampleIndex) / rate;
    if (!m_arrivals) m_arrivals = Arrivals{hostTime_s, m_nextSampleIndex, lead, {}};
    Arrivals& a = *m_arrivals;
    const double elapsed = hostTime_s - a.start_s;
    if (elapsed <= kArrivalBaseline_s) a.baseline = std::min(a.baseline, lead);
    // The least lead of the last kArrivalRise_s: a window's minimum, kept
    // in order of time with every value above a later one dropped.
    while (!a.recent.empty() && a.recent.back().second >= lead) a.recent.pop_back();
    a.recent.emplace_back(hostTime_s, lead);
    while (a.recent.front().first < hostTime_s - kArrivalRise_s) a.recent.pop_front();
    if (elapsed <= kArrivalBaseline_s) return;
    const double allowed = std::max(kHostSlack_s, kArrivalMismatch * elapsed);
    const bool fast = lead < a.baseline - allowed;
    const bool slow = elapsed >= kArrivalBaseline_s + kArrivalRise_s && a.recent.front().second > a.baseline + allowed;
    if (!fast && !slow) return;
    const double arriving = static_cast<double>(m_nextSampleIndex - a.startIndex) / elapsed;
    char span[32];
    std::snprintf(span, sizeof span, "%.1f", elapsed);
    m_rateProblem = "the device's samples arrive at about " + hertz(arriving) + ", not at the " + hertz(rate) +
                    (m_info ? " it says" : " its first timestamps gave") + " (over its first " + span +
                    " s): the rate is wrong, and so would every time in the recording be";
}

std::uint64_t BinaryStream::believedLoss(std::uint16_t sequence, std::uint64_t timestamp_us, double hostTime_s,
                                         StreamOutput& out)
{
    const double rate = *sampleRate_hz();
    const auto gap = static_cast<std::uint16_t>(sequence - *m_lastSequence - 1);
    const double claimed = static_cast<double>(gap) * m_lastSamples;
    // What the device clock says is missing between the last frame's end and this frame.
    const double byClock =
        (static_cast<double>(timestamp_us) - static_cast<double>(m_lastTimestamp_us)) * 1e-6 * rate - m_lastSamples;
    const bool agree = std::abs(byClock - claimed) <= std::max(agreementSamples(m_lastSamples), 0.01 * claimed);
    auto lost = static_cast<std::uint64_t>(agree ? claimed : 0.0);
    // The host's bound: never more samples than the host saw time for.
    const double allowed = (hostTime_s - *m_hostStart_s + kHostSlack_s) * rate * kHostRateMargin;
    const bool beyondHost = lost > 0 && static_cast<double>(m_nextSampleIndex + lost) > allowed;
    if (beyondHost) lost = static_cast<std::uint64_t>(std::max(0.0, allowed - static_cast<double>(m_nextSampleIndex)));
    if (agree && !beyondHost) return lost;

    ++m_counters.sequenceFaults;
    // This frame follows the last one after the loss believed: the device's
    // clock no longer places it, nor measures the rate across it.
    m_clockRun.reset();
    m_originDevice_us = timestamp_us;
    m_originTime_s = m_lastEnd_s + static_cast<double>(lost) / rate;
    if (!m_lastFaultNotice_s || m_lastEnd_s - *m_lastFaultNotice_s >= kNoticeInterval_s) {
        m_lastFaultNotice_s = m_lastEnd_s;
        const std::string moved = seconds(static_cast<double>(timestamp_us - m_lastTimestamp_us) * 1e-6);
        std::string text;
        if (beyondHost)
            text = "the device claimed " + std::to_string(static_cast<std::uint64_t>(claimed)) +
                   " samples lost, more than the time that passed allows; " + std::to_string(lost) + " counted";
        else if (gap == 0)
            text = "the device's clock moved " + moved +
                   " between two consecutive frames: the samples are placed "
                   "by their count";
        else
            text = "the device's sequence number skipped " + core::text::countText(gap, "frame", "frames") +
                   " while its clock moved " + moved + ": no sample counted lost for it";
        out.notices.push_back({m_lastEnd_s, text});
    }
    return lost;
}

void BinaryStream::restart(std::uint64_t timestamp_us, std::size_t samples, double hostTime_s, StreamOutput& out)
{
    const double rate = *sampleRate_hz();
    // The device was away from the end of its last frame until this frame's
    // first sample, taken about the frame's length before it arrived.
    const double away_s = std::max(0.0, hostTime_s - static_cast<double>(samples) / rate - m_lastHost_s);
    const auto gap = static_cast<std::uint64_t>(std::llround(away_s * rate));
    ++m_counters.deviceRestarts;
    m_clockRun.reset();  // its clock began again
    m_counters.samplesLost += gap;
    m_nextSampleIndex += gap;
    m_originDevice_us = timestamp_us;
    m_originTime_s = m_lastEnd_s + static_cast<double>(gap) / rate;
    out.notices.push_back({m_lastEnd_s, "the device restarted (its clock and sequence began again): " +
                                            seconds(static_cast<double>(gap) / rate) + " without samples"});
}

void BinaryStream::publish(const DataPayload& data, std::uint64_t timestamp_us, StreamOutput& out)
{
    const double dt = 1.0 / *sampleRate_hz();
    const double t0 = streamTime_s(timestamp_us);
    core::SampleBlock block(data.channelCount, data.samplesPerChannel, t0, dt, m_nextSampleIndex, m_blockSequence++);
    for (std::size_t c = 0; c < data.channelCount; ++c) {
        const double scale = m_info ? static_cast<double>(m_info->channels[c].scale) : 1.0;
        const double offset = m_info ? static_cast<double>(m_info->channels[c].offset) : 0.0;
        auto channel = block.channel(c);
        for (std::size_t s = 0; s < data.samplesPerChannel; ++s)
            channel[s] = data.raw[s * data.channelCount + c] * scale + offset;
    }
    m_nextSampleIndex += data.samplesPerChannel;
    m_lastEnd_s = t0 + static_cast<double>(data.samplesPerChannel) * dt;
    out.blocks.push_back(std::move(block));
}

}  // namespace tactiscope::devices::protocol
