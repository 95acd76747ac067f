// PortSource: handshake, reading and protocol dispatch.
#include "devices/PortSource.h"

#include "core/text/ShortQuote.h"
#include "devices/SteadyClock.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace tactiscope::devices {
namespace {

std::string channelNames(const std::vector<core::ChannelDescriptor>& channels)
{
    std::string names;
    for (const auto& channel : channels) names += (names.empty() ? "" : ", ") + channel.name;
    return names;
}

}  // namespace

PortSource::PortSource(std::unique_ptr<transport::Transport> transport, const PortSourceOptions& options)
    : m_transport(std::move(transport)),
      m_options(options)
{
    discardWaiting();
    m_streamStart_s = steadySeconds();
    if (options.protocol == WireProtocol::Text) {
        m_text.emplace(options.textRate_hz, options.textUnits);
        m_drift = DriftWatch(DriftWatch::Subject::TextLines);
    } else {
        if (options.requestRate_hz)
            sendCommand(protocol::CommandCode::SetRate,
                        static_cast<std::uint32_t>(std::llround(*options.requestRate_hz * 1000.0)));
        sendCommand(protocol::CommandCode::RequestInfo);
        sendCommand(protocol::CommandCode::Start);
    }
    const auto start = std::chrono::steady_clock::now();
    auto deadline = start + options.handshakeTimeout;
    while (!layoutKnown() || !rateConfirmed(deadline)) {
        // A text board that prints numbers is waited for as long as its
        // channels and its rate take to settle (two lines, eight periods: a
        // minute at one line in 8 s).
        if (m_text && m_text->heardNumbers()) deadline = std::max(deadline, start + kLongestTextTiming);
        if (std::chrono::steady_clock::now() >= deadline) {
            if (m_text && m_text->counters().frames > 0)
                throw transport::TransportError(m_transport->description() + ": its lines could not be timed in " +
                                                std::to_string(kLongestTextTiming.count()) + " s (" +
                                                std::to_string(m_text->counters().frames) +
                                                " read); give their rate (--rate, or Rate in the device panel)");
            throw transport::TransportError(
                m_transport->description() + ": no " +
                (options.protocol == WireProtocol::Binary ? std::string("TSP/1 frames")
                                                          : std::string("readable lines")) +
                " within " + std::to_string(options.handshakeTimeout.count()) + " ms; check the protocol (" +
                (options.protocol == WireProtocol::Binary ? std::string("a board that prints lines is --protocol text")
                                                          : std::string("a TSP/1 probe is --protocol binary")) +
                "), "
                "the baud rate and that the device is streaming");
        }
        pump(std::chrono::milliseconds(50));
    }
    if (!m_text && m_binary.rateProblem())
        throw transport::TransportError(m_transport->description() + ": " + *m_binary.rateProblem());
    if (const auto twice = core::repeatedChannelName(m_text ? m_text->channels() : m_binary.channels()))
        throw transport::TransportError(m_transport->description() + ": two of its channels are called " +
                                        core::text::quoteShort(*twice) +
                                        "; each needs a name of its own (a recording's export names its columns "
                                        "by them, and could not be read back)");
    if (m_text) {
        if (const auto unknown = m_text->unknownUnitNames(); !unknown.empty())
            throw transport::TransportError(m_transport->description() + ": a unit is given for '" + unknown.front() +
                                            "', which the board does not print; its channels are " +
                                            channelNames(m_text->channels()));
        // The stream begins with the layout of its first block: the board
        // may have printed another while its rate was timed (the blocks
        // then grow, BlockSource::takeGrownChannels).
        m_channels = m_text->channels();
        m_channels.resize(std::min(m_channels.size(), m_queue.front().channelCount()));
        m_streamChannels = m_channels;
        m_rate_hz = *m_text->sampleRate_hz();
        m_streamStart_s = steadySeconds();
    } else {
        m_channels = m_binary.channels();
        m_streamChannels = m_channels;
        m_rate_hz = *m_binary.sampleRate_hz();
    }
}

PortSource::~PortSource()
{
    if (m_text) return;
    try {
        sendCommand(protocol::CommandCode::Stop);
    } catch (const transport::TransportError&) {
        // The device is gone already; nothing to stop.
    }
}

std::string PortSource::name() const
{
    if (const auto info = deviceInfo())
        return info->vendor + " " + info->model + " " + info->serialNumber + " (" + m_transport->description() + ")";
    return m_transport->description();
}

DeviceIdentity PortSource::identity() const
{
    if (const auto info = deviceInfo())
        return {info->vendor + " " + info->model, info->serialNumber, info->firmwareVersion};
    return {m_transport->description(), {}, {}};
}

// What waits in the port when it opens was sent before this connection
// (by a device left streaming): it belongs to no session and would give the
// text rate estimate a burst. Read away for at most 50 ms, since a device
// that streams on keeps the port from ever being empty.
void PortSource::discardWaiting()
{
    const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(50);
    while (std::chrono::steady_clock::now() < until && m_transport->read(m_chunk, std::chrono::milliseconds(1)) > 0) {
    }
}

std::optional<std::string> PortSource::rateNote() const
{
    if (!m_text || !m_text->measuredRate()) return std::nullopt;
    const auto& rate = *m_text->measuredRate();
    // The rate to its uncertainty's second digit, in plain decimals.
    char measured[96];
    if (rate.u_hz && *rate.u_hz > 0.0) {
        const int decimals = std::clamp(1 - static_cast<int>(std::floor(std::log10(*rate.u_hz))), 0, 12);
        std::snprintf(measured, sizeof measured, "%.*f ± %.*f Hz", decimals, rate.rate_hz, decimals, *rate.u_hz);
    } else {
        std::snprintf(measured, sizeof measured, "%.7g Hz", rate.rate_hz);
    }
    char basis[96];
    if (rate.boardClock)
        std::snprintf(basis, sizeof basis, "by the board's own clock (%s) over %zu samples",
                      rate.boardSecondsPerUnit == 1.0    ? "in s"
                      : rate.boardSecondsPerUnit == 1e-3 ? "in ms"
                                                         : "in µs",
                      rate.lines);
    else
        std::snprintf(basis, sizeof basis, "from the arrival times of %zu samples over %.1f s", rate.lines,
                      rate.span_s);
    char text[400];
    std::snprintf(text, sizeof text,
                  "the sample rate, %s (standard uncertainty), was measured %s: a text device states no rate, so "
                  "every time in this recording rests on it",
                  measured, basis);
    return text;
}

std::optional<double> PortSource::rateUncertainty_hz() const
{
    return m_text && m_text->measuredRate() ? m_text->measuredRate()->u_hz : std::nullopt;
}

// A TSP/1 device's INFO rate is checked against its clock before anyone
// records with it: the handshake waits for two consecutively numbered
// frames, among the first four at most (a device whose sequence does not
// count, or a slow one, is checked in the stream instead).
bool PortSource::rateConfirmed(std::chrono::steady_clock::time_point deadline) const
{
    if (m_text || !m_binary.info() || m_binary.clockRate_hz() || m_binary.rateProblem()) return true;
    return m_binary.dataFrames() >= 4 || std::chrono::steady_clock::now() >= deadline - std::chrono::milliseconds(100);
}

bool PortSource::layoutKnown() const
{
    if (m_text) return m_text->sampleRate_hz().has_value() && !m_queue.empty();
    return m_binary.sampleRate_hz().has_value() && !m_binary.channels().empty() &&
           (m_binary.info() || !m_queue.empty());
}

void PortSource::sendCommand(protocol::CommandCode code, std::uint32_t argument)
{
    const std::lock_guard lock(m_writeMutex);
    m_transport->write(protocol::encodeFrame(protocol::FrameType::Command, m_commandSequence++,
                                             protocol::encodeCommand({code, argument})));
}

std::optional<std::string> PortSource::requestShunt(std::size_t channel, bool on)
{
    if (m_text) return "a text-protocol device takes no commands";
    if (channel >= m_channels.size() || channel > 255) return "there is no channel " + std::to_string(channel + 1);
    protocol::CommandPayload command;
    command.code = protocol::CommandCode::Shunt;
    command.channel = static_cast<std::uint8_t>(channel);
    command.on = on;
    try {
        const std::lock_guard lock(m_writeMutex);
        m_transport->write(
            protocol::encodeFrame(protocol::FrameType::Command, m_commandSequence++, protocol::encodeCommand(command)));
    } catch (const transport::TransportError& e) {
        return std::string("the command could not be sent: ") + e.what();
    }
    return std::nullopt;
}

std::vector<DeviceStatus> PortSource::takeStatuses()
{
    const std::lock_guard lock(m_statusMutex);
    return std::exchange(m_statuses, {});
}

void PortSource::pump(std::chrono::milliseconds timeout)
{
    const std::size_t n = m_transport->read(m_chunk, timeout);
    if (n == 0) return;
    const std::span<const std::uint8_t> bytes(m_chunk.data(), n);
    const double arrival_s = m_transport->arrival_s().value_or(steadySeconds());
    // Every new block teaches the clock mapping when its last sample
    // arrived (a block cannot leave before it; a text block's lines were
    // held while its rate settled, each block with its own arrival),
    // unless the device's clock broke off since: then the mapping begins
    // again.
    const auto enqueue = [&](std::vector<core::SampleBlock>& blocks, const protocol::DecoderCounters& counters,
                             const std::vector<double>& arrivals) {
        if (const auto breaks = counters.deviceRestarts + counters.sequenceFaults; breaks != m_clockBreaks) {
            m_clockBreaks = breaks;
            m_clock = core::timing::ClockAlignment();
        }
        for (std::size_t i = 0; i < blocks.size(); ++i) {
            auto& b = blocks[i];
            m_clock.add(b.endTime_s() - b.dt_s(), i < arrivals.size() ? arrivals[i] : arrival_s);
            if (auto drift = m_drift.check(m_clock, b.endTime_s())) m_notices.push_back({b.endTime_s(), *drift});
            m_queue.push_back(std::move(b));
        }
    };
    {
        const std::lock_guard lock(m_statusMutex);
        m_recent.insert(m_recent.end(), bytes.begin(), bytes.end());
        while (m_recent.size() > kRecentBytes) m_recent.pop_front();
    }
    if (m_text) {
        std::vector<core::SampleBlock> blocks;
        std::vector<double> arrivals;
        m_text->push(bytes, arrival_s, blocks, &arrivals);
        const std::lock_guard lock(m_statusMutex);
        m_counters = m_text->counters();
        enqueue(blocks, m_counters, arrivals);
        if (auto warning = m_text->takeRateWarning())
            m_notices.push_back({blocks.empty() ? 0.0 : blocks.back().endTime_s(), std::move(*warning)});
        for (auto& change : m_text->takeLayoutChanges())
            m_notices.push_back({static_cast<double>(change.sampleIndex) / *m_text->sampleRate_hz(),
                                 std::move(change.what), false, true});
    } else {
        protocol::StreamOutput out;
        m_binary.push(bytes, arrival_s, out);
        const std::lock_guard lock(m_statusMutex);
        m_counters = m_binary.counters();
        enqueue(out.blocks, m_counters, {});
        m_notices.insert(m_notices.end(), std::make_move_iterator(out.notices.begin()),
                         std::make_move_iterator(out.notices.end()));
        if (out.infoChanged) m_info = m_binary.info();
        for (auto& status : out.statuses)
            m_statuses.push_back({static_cast<int>(status.level), std::move(status.message)});
    }
}

ReadStatus PortSource::readBlock(core::SampleBlock& out, std::chrono::milliseconds timeout)
{
    try {
        if (m_queue.empty()) pump(timeout);
    } catch (const transport::TransportError& e) {
        m_error = e.what();
        return ReadStatus::Failed;
    }
    if (!m_text && m_binary.rateProblem()) {
        m_error = *m_binary.rateProblem();
        m_failedForGood = true;
        return ReadStatus::Failed;
    }
    if (m_queue.empty()) return ReadStatus::Timeout;
    // A text board's new layout: its blocks hold the channels it grew to.
    if (m_text && m_queue.front().channelCount() > m_streamChannels.size()) {
        m_streamChannels = m_text->channels();
        m_streamChannels.resize(m_queue.front().channelCount());
        m_grownChannels = m_streamChannels;
    }
    if (m_queue.front().channelCount() != m_streamChannels.size()) {
        m_error = "the device changed its channels while streaming (" + std::to_string(m_channels.size()) + " to " +
                  std::to_string(m_queue.front().channelCount()) + "); reconnect it by hand to record the new ones";
        m_failedForGood = true;  // reopened, it would be another recording's device
        return ReadStatus::Failed;
    }
    out = std::move(m_queue.front());
    m_queue.pop_front();
    return ReadStatus::Block;
}

std::optional<core::timing::ClockMapping> PortSource::hostClock() const
{
    const std::lock_guard lock(m_statusMutex);
    auto mapping = m_clock.mapping();
    // Its samples' instants are known to within a period of their stamps (ClockMapping::samplePeriod_s).
    if (mapping && m_rate_hz > 0.0) mapping->samplePeriod_s = 1.0 / m_rate_hz;
    return mapping;
}

double PortSource::hostTime_s(double blockTime_s) const
{
    const auto mapping = hostClock();
    return mapping ? mapping->host_s(blockTime_s) : blockTime_s;
}

std::vector<LinkNotice> PortSource::takeNotices()
{
    const std::lock_guard lock(m_statusMutex);
    return std::exchange(m_notices, {});
}

protocol::DecoderCounters PortSource::decoderCounters() const
{
    const std::lock_guard lock(m_statusMutex);
    return m_counters;
}

std::vector<std::uint8_t> PortSource::recentBytes() const
{
    const std::lock_guard lock(m_statusMutex);
    return {m_recent.begin(), m_recent.end()};
}

std::optional<protocol::DeviceInfo> PortSource::deviceInfo() const
{
    const std::lock_guard lock(m_statusMutex);
    return m_info;
}

}  // namespace tactiscope::devices
