// ReconnectingSource: outage detection, reopening and stream continuity.
#include "devices/ReconnectingSource.h"

#include "core/SampleBlock.h"
#include "devices/PortSource.h"
#include "devices/SteadyClock.h"
#include "devices/transport/SerialPorts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <thread>
#include <utility>

namespace tactiscope::devices {

const char* toString(DeviceState state)
{
    switch (state) {
    case DeviceState::Streaming:
        return "streaming";
    case DeviceState::Lost:
        return "lost";
    case DeviceState::Reconnecting:
        return "reconnecting";
    }
    return "?";
}

ReconnectingSource::ReconnectingSource(Opener opener, std::chrono::milliseconds retryInterval)
    : m_opener(std::move(opener)),
      m_retryInterval(retryInterval),
      m_source(m_opener()),
      m_name(m_source->name()),
      m_identity(m_source->identity()),
      m_declaredMode(m_source->declaredMode()),
      m_channels(m_source->channels()),
      m_streamChannels(m_channels),
      m_rate_hz(m_source->nominalSampleRate_hz()),
      m_rateNote(m_source->rateNote()),
      m_rateU_hz(m_source->rateUncertainty_hz())
{
    for (std::size_t c = 0; c < m_channels.size(); ++c) m_channelMap.push_back(c);
}

std::optional<std::string> ReconnectingSource::differenceFrom(const BlockSource& back) const
{
    // A device that names itself (INFO) must come back as the same model and
    // serial number: another probe of the same kind on the port is not it.
    const DeviceIdentity identity = back.identity();
    if (!m_identity.serial.empty() && (identity.model != m_identity.model || identity.serial != m_identity.serial))
        return "another device came back on the port (" + identity.model + " " + identity.serial + ", where " +
               m_identity.model + " " + m_identity.serial +
               " was): what came before is kept, nothing of it is mixed in; connect it as a new session";
    if (!back.textProtocol() && back.channels() != m_channels)
        return "the device came back with other channels; reconnect it by hand";
    if (!sameRate(back)) {
        // One session holds one rate: a sketch with another delay is a new recording.
        char text[200];
        std::snprintf(text, sizeof text,
                      "the device came back at another rate (%.6g Hz, where it was %.6g Hz): what came before is "
                      "kept; record it again as a new session",
                      back.nominalSampleRate_hz(), m_rate_hz);
        return text;
    }
    return std::nullopt;
}

bool ReconnectingSource::matchChannels(const std::vector<core::ChannelDescriptor>& connection)
{
    std::vector<std::size_t> map;
    auto stream = m_streamChannels;
    for (const auto& channel : connection) {
        const auto same = std::ranges::find(stream, channel.name, &core::ChannelDescriptor::name);
        if (same != stream.end() && *same != channel) {
            m_error = "the device came back printing " + channel.name + " in another unit (" +
                      (channel.unit.empty() ? std::string("none") : channel.unit) + ", where it was " +
                      (same->unit.empty() ? std::string("none") : same->unit) + "); reconnect it by hand";
            return false;
        }
        map.push_back(static_cast<std::size_t>(same - stream.begin()));
        if (same == stream.end()) stream.push_back(channel);
    }
    if (stream.size() > m_streamChannels.size()) m_grown = stream;
    m_streamChannels = std::move(stream);
    m_channelMap = std::move(map);
    m_sameLayout = m_channelMap.size() == m_streamChannels.size();
    for (std::size_t c = 0; c < m_channelMap.size(); ++c) m_sameLayout = m_sameLayout && m_channelMap[c] == c;
    return true;
}

std::string ReconnectingSource::layoutChange(std::size_t streamChannelsBefore) const
{
    std::string gone, added;
    for (std::size_t c = 0; c < m_streamChannels.size(); ++c) {
        const std::string& name = m_streamChannels[c].name;
        if (c >= streamChannelsBefore)
            added += (added.empty() ? "" : ", ") + name;
        else if (std::ranges::find(m_channelMap, c) == m_channelMap.end())
            gone += (gone.empty() ? "" : ", ") + name;
    }
    std::string text;
    if (!added.empty()) text += "; it now prints " + added + " (holes before)";
    if (!gone.empty()) text += "; it no longer prints " + gone + " (holes from here)";
    return text;
}

core::SampleBlock ReconnectingSource::inStreamChannels(const core::SampleBlock& block) const
{
    core::SampleBlock out(m_streamChannels.size(), block.sampleCount(), block.t0_s(), block.dt_s(),
                          block.firstSampleIndex(), block.sequence());
    for (std::size_t c = 0; c < out.channelCount(); ++c) std::ranges::fill(out.channel(c), std::nan(""));
    for (std::size_t c = 0; c < std::min(block.channelCount(), m_channelMap.size()); ++c)
        std::ranges::copy(block.channel(c), out.channel(m_channelMap[c]).begin());
    return out;
}

// A rate the device states must be the same; one this program measured (a
// text board timed again when it comes back) agrees within three of the
// two measurements' combined uncertainty.
bool ReconnectingSource::sameRate(const BlockSource& back) const
{
    const double rate_hz = back.nominalSampleRate_hz();
    if (rate_hz == m_rate_hz) return true;
    const auto u_hz = back.rateUncertainty_hz();
    if (!m_rateNote || !back.rateNote() || !m_rateU_hz || !u_hz) return false;
    return std::abs(rate_hz - m_rate_hz) <= 3.0 * std::hypot(*m_rateU_hz, *u_hz);
}

bool ReconnectingSource::tryReconnect()
{
    m_state = DeviceState::Reconnecting;
    try {
        auto source = m_opener();
        const std::size_t streamChannelsBefore = m_streamChannels.size();
        const auto other = differenceFrom(*source);
        if (other) m_error = *other;
        if (other || !matchChannels(source->channels())) {
            // Another device, for the record: what came before is kept, and
            // nothing after is mixed into it.
            m_failedForGood = true;
            m_state = DeviceState::Lost;
            return false;
        }
        // The outage ends where the new connection's first sample was
        // taken: a text board's lines, held while it was timed again, and
        // a handshake's frames come after it.
        auto resumed = std::chrono::steady_clock::now();
        if (const auto clock = source->hostClock()) {
            resumed = std::clamp(steadyInstant(clock->host_s(0.0)), m_lostAt, resumed);
        }
        const double away_s = std::chrono::duration<double>(resumed - m_lostAt).count();
        // Continue after the last delivered sample, leaving room for what the
        // outage cost: the new connection's first sample lies where the lost
        // connection's clock places its host instant (a text board's stream
        // began with lines it was timed on, before the connection was made),
        // or, with no clock, as long after the last as the outage lasted.
        double resumed_s = m_lastEnd_s + away_s;
        if (m_lostClock) resumed_s = std::max(m_lastEnd_s, m_lostClock->device_s(steadySecondsOf(resumed)));
        m_indexOffset = std::max(m_endIndex, static_cast<std::uint64_t>(std::llround(resumed_s * m_rate_hz)));
        {
            const std::lock_guard lock(m_countersMutex);  // the owner reads the offset (notices, clock)
            m_timeOffset_s = static_cast<double>(m_indexOffset) / m_rate_hz;
            m_lostClock.reset();
            char text[96];
            // The samples' outage, not the device's: it may have been back
            // up to a retry interval before it was opened again.
            std::snprintf(text, sizeof text, "the device was lost and came back: no samples for %.1f s", away_s);
            m_pastNotices.push_back({m_lostAtTime_s, text + layoutChange(streamChannelsBefore)});
        }
        replaceSource(std::move(source));
        m_state = DeviceState::Streaming;
        ++m_reconnections;
        return true;
    } catch (const std::exception& e) {
        m_error = e.what();
        m_state = DeviceState::Lost;
        return false;
    }
}

void ReconnectingSource::replaceSource(std::unique_ptr<BlockSource> source)
{
    const std::lock_guard lock(m_countersMutex);
    if (m_source) {
        m_pastCounters += m_source->decoderCounters();
        auto notices = takeCurrentNotices();
        m_pastNotices.insert(m_pastNotices.end(), notices.begin(), notices.end());
    }
    m_source = std::move(source);
}

std::vector<LinkNotice> ReconnectingSource::takeNotices()
{
    const std::lock_guard lock(m_countersMutex);
    auto notices = std::exchange(m_pastNotices, {});
    auto current = takeCurrentNotices();
    notices.insert(notices.end(), current.begin(), current.end());
    return notices;
}

// The current connection's notices, in the stream's time (the offset its
// blocks are given). The caller holds m_countersMutex.
std::vector<LinkNotice> ReconnectingSource::takeCurrentNotices()
{
    if (!m_source) return {};
    auto notices = m_source->takeNotices();
    for (auto& notice : notices) notice.time_s += m_timeOffset_s;
    return notices;
}

std::optional<std::string> ReconnectingSource::requestShunt(std::size_t channel, bool on)
{
    const std::lock_guard lock(m_countersMutex);
    if (!m_source) return "the probe is not connected (it is being waited for)";
    return m_source->requestShunt(channel, on);
}

std::vector<DeviceStatus> ReconnectingSource::takeStatuses()
{
    const std::lock_guard lock(m_countersMutex);
    return m_source ? m_source->takeStatuses() : std::vector<DeviceStatus>{};
}

protocol::DecoderCounters ReconnectingSource::decoderCounters() const
{
    const std::lock_guard lock(m_countersMutex);
    auto sum = m_pastCounters;
    if (m_source) sum += m_source->decoderCounters();
    return sum;
}

std::vector<std::uint8_t> ReconnectingSource::recentBytes() const
{
    const std::lock_guard lock(m_countersMutex);
    return m_source ? m_source->recentBytes() : std::vector<std::uint8_t>{};
}

// The current connection's mapping, for the stream's times: they are its
// block times shifted by the offset it continues at.
std::optional<core::timing::ClockMapping> ReconnectingSource::hostClock() const
{
    const std::lock_guard lock(m_countersMutex);
    // While the link is lost, its last clock still places what it delivered.
    if (!m_source) return m_lostClock;
    auto mapping = m_source->hostClock();
    if (mapping) {
        mapping->reference_s += m_timeOffset_s;
        mapping->offset_s -= m_timeOffset_s;
    }
    return mapping;
}

std::optional<double> ReconnectingSource::streamStart_host_s() const
{
    const std::lock_guard lock(m_countersMutex);
    return m_source ? m_source->streamStart_host_s() : std::nullopt;
}

bool ReconnectingSource::textProtocol() const
{
    const std::lock_guard lock(m_countersMutex);
    return m_source && m_source->textProtocol();
}

std::optional<std::vector<core::ChannelDescriptor>> ReconnectingSource::takeGrownChannels()
{
    return std::exchange(m_grown, std::nullopt);
}

ReadStatus ReconnectingSource::readBlock(core::SampleBlock& out, std::chrono::milliseconds timeout)
{
    if (m_failedForGood) return ReadStatus::Failed;
    if (!m_source) {
        const auto now = std::chrono::steady_clock::now();
        if (now < m_nextRetry) {
            std::this_thread::sleep_for(
                std::min(timeout, std::chrono::duration_cast<std::chrono::milliseconds>(m_nextRetry - now)));
            return ReadStatus::Timeout;
        }
        m_nextRetry = now + m_retryInterval;
        if (!tryReconnect()) return ReadStatus::Timeout;
    }
    const ReadStatus status = m_source->readBlock(out, timeout);
    if (status == ReadStatus::Failed && m_source->failedForGood()) {
        m_error = m_source->lastError();
        m_failedForGood = true;
        return ReadStatus::Failed;  // reopening would fail the same way
    }
    if (status == ReadStatus::Failed) {
        m_error = m_source->lastError();
        const auto clock = hostClock();
        replaceSource(nullptr);
        {
            const std::lock_guard lock(m_countersMutex);
            m_lostClock = clock;
        }
        m_state = DeviceState::Lost;
        m_lostAt = std::chrono::steady_clock::now();
        m_lostAtTime_s = m_lastEnd_s;
        m_nextRetry = m_lostAt + m_retryInterval;
        return ReadStatus::Timeout;
    }
    if (status != ReadStatus::Block) return status;
    // A board's new layout: matched to the stream's channels before its block.
    if (auto grown = m_source->takeGrownChannels(); grown && !matchChannels(*grown)) {
        m_failedForGood = true;
        return ReadStatus::Failed;
    }
    if (!m_sameLayout || out.channelCount() != m_streamChannels.size()) out = inStreamChannels(out);
    out.rebase(m_timeOffset_s, m_indexOffset);
    m_endIndex = out.endSampleIndex();
    m_lastEnd_s = out.endTime_s();
    return ReadStatus::Block;
}

ReconnectingSource::Opener serialOpener(std::string path, std::string usbSerialNumber, int baud,
                                        PortSourceOptions options)
{
    return
        [path = std::move(path), serial = std::move(usbSerialNumber), baud, options]() -> std::unique_ptr<BlockSource> {
            std::string where = path;
            if (!serial.empty()) {
                for (const auto& port : transport::listSerialPorts()) {
                    if (port.usbSerialNumber == serial) where = port.path;
                }
            }
            return std::make_unique<PortSource>(transport::openSerialTransport(where, baud), options);
        };
}

}  // namespace tactiscope::devices
