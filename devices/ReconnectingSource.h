// A device that may be unplugged and plugged back in: wraps the source of
// one connection and, when it fails, keeps trying to open the same device
// again — matched by its USB serial number when it has one (the port path
// may change, ttyACM0 → ttyACM1), else by the port path.
//
// The acquisition never sees a failure while the device is away: reads time
// out, state() says Lost, then Reconnecting, then Streaming again. Blocks
// after a reconnection continue the stream: their time is the host's time
// since the first connection, and their sample index jumps by the samples
// the outage cost (time away × rate), so Acquisition counts them as lost and
// a recording marks the gap. A device that comes back as another (another
// model or serial number in its INFO, other channels or another rate; a
// text board's rate, timed again, within its uncertainty) ends the source
// for good, with the reason: nothing of it joins the session. A board
// printing lines may come back printing other channels, as it may change
// them while it streams: each is matched to the stream's by its name (a
// name the stream has in another unit is another device), a new one grows
// the stream, and one it no longer prints is a channel of holes.
#pragma once

#include "devices/BlockSource.h"
#include "devices/PortSource.h"

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

namespace tactiscope::devices {

enum class DeviceState { Streaming, Lost, Reconnecting };

const char* toString(DeviceState state);

class ReconnectingSource final : public BlockSource {
public:
    // Opens a connection; throws (whatever the opener throws) when it fails.
    using Opener = std::function<std::unique_ptr<BlockSource>()>;

    // The first connection is opened here and must succeed. A lost one is
    // tried again every `retryInterval`: an outage is told as up to that
    // much longer than the device was away (no port to open costs little).
    ReconnectingSource(Opener opener, std::chrono::milliseconds retryInterval = std::chrono::milliseconds(250));

    std::string name() const override { return m_name; }
    DeviceIdentity identity() const override { return m_identity; }
    std::optional<core::Mode> declaredMode() const override { return m_declaredMode; }
    const std::vector<core::ChannelDescriptor>& channels() const override { return m_channels; }
    double nominalSampleRate_hz() const override { return m_rate_hz; }
    ReadStatus readBlock(core::SampleBlock& out, std::chrono::milliseconds timeout) override;
    std::string lastError() const override { return m_error; }
    bool failedForGood() const override { return m_failedForGood; }
    // Summed over every connection so far.
    protocol::DecoderCounters decoderCounters() const override;
    // Of every connection so far, in the stream's time.
    std::vector<LinkNotice> takeNotices() override;
    // Every connection's new channels, in the stream's order.
    std::optional<std::vector<core::ChannelDescriptor>> takeGrownChannels() override;
    std::optional<std::string> requestShunt(std::size_t channel, bool on) override;
    std::vector<DeviceStatus> takeStatuses() override;
    // Of the current connection.
    std::vector<std::uint8_t> recentBytes() const override;
    bool textProtocol() const override;
    std::optional<std::string> rateNote() const override { return m_rateNote; }
    std::optional<double> rateUncertainty_hz() const override { return m_rateU_hz; }
    // The current connection's, in the stream's time.
    std::optional<core::timing::ClockMapping> hostClock() const override;
    std::optional<double> streamStart_host_s() const override;

    DeviceState state() const { return m_state; }  // any thread
    std::uint64_t reconnections() const { return m_reconnections; }

private:
    bool tryReconnect();
    // Why a device that came back is not this one (another model or serial
    // number, other channels or rate); none when it is.
    std::optional<std::string> differenceFrom(const BlockSource& back) const;
    bool sameRate(const BlockSource& back) const;
    // Matches a connection's channels to the stream's by name, growing the
    // stream by those it lacks; false, with m_error set, when a name comes
    // in another unit.
    bool matchChannels(const std::vector<core::ChannelDescriptor>& connection);
    // A block of the current connection in the stream's channels.
    core::SampleBlock inStreamChannels(const core::SampleBlock& block) const;
    // "; it now prints c (holes before); it no longer prints b (holes from
    // here)": the stream's channels the current connection added (of those
    // after the first `streamChannelsBefore`) and those it does not print;
    // empty when it prints the same.
    std::string layoutChange(std::size_t streamChannelsBefore) const;

    void replaceSource(std::unique_ptr<BlockSource> source);
    std::vector<LinkNotice> takeCurrentNotices();

    Opener m_opener;
    std::chrono::milliseconds m_retryInterval;
    std::unique_ptr<BlockSource> m_source;
    std::string m_name;
    DeviceIdentity m_identity;
    std::optional<core::Mode> m_declaredMode;
    std::vector<core::ChannelDescriptor> m_channels;
    std::vector<core::ChannelDescriptor> m_streamChannels;  // with those grown since
    std::vector<std::size_t> m_channelMap;  // the connection's channel i is the stream's m_channelMap[i]
    bool m_sameLayout = true;               // the map is the identity onto every stream channel
    std::optional<std::vector<core::ChannelDescriptor>> m_grown;  // not yet taken
    double m_rate_hz = 0.0;
    std::optional<std::string> m_rateNote;  // the first connection's: the rate kept
    std::optional<double> m_rateU_hz;       // and its uncertainty
    std::string m_error;
    bool m_failedForGood = false;
    std::atomic<DeviceState> m_state = DeviceState::Streaming;
    std::atomic<std::uint64_t> m_reconnections = 0;
    std::chrono::steady_clock::time_point m_lostAt;
    std::chrono::steady_clock::time_point m_nextRetry;
    std::uint64_t m_endIndex = 0;                           // one past the last sample delivered
    double m_lastEnd_s = 0.0;                               // and its time, just after it
    double m_lostAtTime_s = 0.0;                            // the stream time the link was lost at
    double m_timeOffset_s = 0.0;                            // added to the current connection's times
    std::optional<core::timing::ClockMapping> m_lostClock;  // the lost connection's, on the stream's time
    std::uint64_t m_indexOffset = 0;                        // added to its sample indices
    mutable std::mutex m_countersMutex;                     // guards m_source's replacement and the sum below
    protocol::DecoderCounters m_pastCounters;               // of the connections closed so far
    std::vector<LinkNotice> m_pastNotices;                  // of those, not yet taken
};

// An opener for a serial device: by USB serial number when given (searching
// the ports each time), else by path.
ReconnectingSource::Opener serialOpener(std::string path, std::string usbSerialNumber, int baud,
                                        PortSourceOptions options);

}  // namespace tactiscope::devices
