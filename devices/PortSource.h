// A device on a byte-stream transport as a BlockSource: transport →
// protocol stream (binary TSP/1 or Serial-Plotter text) → SampleBlocks.
//
// The constructor does the handshake: for TSP/1 it asks for the INFO frame
// and sends start (a device that only streams data works too), then reads
// until the channels and the sample rate are known, keeping the blocks that
// arrived meanwhile. The destructor sends stop.
#pragma once

#include "core/timing/ClockAlignment.h"
#include "devices/BlockSource.h"
#include "devices/DriftWatch.h"
#include "devices/protocol/BinaryStream.h"
#include "devices/protocol/TextStream.h"
#include "devices/transport/Transport.h"

#include <chrono>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>

namespace tactiscope::devices {

enum class WireProtocol { Binary, Text };

struct PortSourceOptions {
    WireProtocol protocol = WireProtocol::Binary;
    std::optional<double> textRate_hz;  // text only: else measured (protocol/LineRate.h)
    std::chrono::milliseconds handshakeTimeout{4000};
    std::optional<double> requestRate_hz;  // binary only: asked of the device with "set rate"; it may refuse
    // Text only: a unit for channels by name, over their labels' (a board
    // that prints plain numbers: "a" → "µε"). A name the board does not
    // print is refused at the handshake.
    std::map<std::string, std::string> textUnits;
};

class PortSource final : public BlockSource {
public:
    // Throws transport::TransportError when the transport fails or nothing
    // usable arrives within the handshake timeout.
    PortSource(std::unique_ptr<transport::Transport> transport, const PortSourceOptions& options);
    ~PortSource() override;

    std::string name() const override;
    DeviceIdentity identity() const override;
    const std::vector<core::ChannelDescriptor>& channels() const override { return m_channels; }
    double nominalSampleRate_hz() const override { return m_rate_hz; }
    ReadStatus readBlock(core::SampleBlock& out, std::chrono::milliseconds timeout) override;
    std::string lastError() const override { return m_error; }
    bool failedForGood() const override { return m_failedForGood; }

    // Thread-safe snapshots for the UI and the record summary.
    protocol::DecoderCounters decoderCounters() const override;
    std::vector<LinkNotice> takeNotices() override;
    std::optional<std::vector<core::ChannelDescriptor>> takeGrownChannels() override
    {
        return std::exchange(m_grownChannels, std::nullopt);
    }
    std::vector<std::uint8_t> recentBytes() const override;
    bool textProtocol() const override { return m_text.has_value(); }
    std::optional<std::string> rateNote() const override;
    std::optional<double> rateUncertainty_hz() const override;
    std::optional<protocol::DeviceInfo> deviceInfo() const;
    std::optional<std::string> requestShunt(std::size_t channel, bool on) override;
    std::vector<DeviceStatus> takeStatuses() override;
    // The stream's clock on the host's (core/timing/ClockAlignment.h), from
    // each block's last sample and its arrival. Block times count the
    // device's clock (binary) or samples at the sample rate (text); either
    // way the mapping learns the offset and the rate error. Begun again
    // where the device's clock stops placing the samples (a restart, a
    // sequence fault). Any thread.
    std::optional<core::timing::ClockMapping> hostClock() const override;
    // When the device was asked to start (what waited in the port read
    // away), or, for a text board, when its rate was known: a recording
    // begins once it is (protocol/TextStream.h).
    std::optional<double> streamStart_host_s() const override { return m_streamStart_s; }
    // Host steady-clock time (seconds) of a block time; the block time
    // itself before the mapping is known.
    double hostTime_s(double blockTime_s) const;

    // How long a text board that prints may take to be timed.
    static constexpr std::chrono::seconds kLongestTextTiming{60};

private:
    void sendCommand(protocol::CommandCode code, std::uint32_t argument = 0);
    bool rateConfirmed(std::chrono::steady_clock::time_point deadline) const;
    void discardWaiting();
    // Reads one chunk into the stream; queues blocks. Throws TransportError.
    void pump(std::chrono::milliseconds timeout);
    bool layoutKnown() const;

    std::unique_ptr<transport::Transport> m_transport;
    PortSourceOptions m_options;
    protocol::BinaryStream m_binary;
    std::optional<protocol::TextStream> m_text;
    std::deque<core::SampleBlock> m_queue;
    std::vector<core::ChannelDescriptor> m_channels;  // as the handshake found them
    // The reading thread's: the channels of the blocks read, and those they
    // grew to with the last block read, until taken.
    std::vector<core::ChannelDescriptor> m_streamChannels;
    std::optional<std::vector<core::ChannelDescriptor>> m_grownChannels;
    double m_rate_hz = 0.0;
    std::string m_error;
    bool m_failedForGood = false;
    std::uint16_t m_commandSequence = 0;
    static constexpr std::size_t kRecentBytes = 4096;
    std::vector<std::uint8_t> m_chunk = std::vector<std::uint8_t>(4096);
    mutable std::mutex m_statusMutex;  // guards the snapshots below
    protocol::DecoderCounters m_counters;
    std::vector<LinkNotice> m_notices;     // not yet taken
    std::vector<DeviceStatus> m_statuses;  // not yet taken
    std::mutex m_writeMutex;               // a command from the owner while the handshake's or the stop's goes out
    std::deque<std::uint8_t> m_recent;     // the last kRecentBytes received
    std::optional<protocol::DeviceInfo> m_info;
    core::timing::ClockAlignment m_clock;
    double m_streamStart_s = 0.0;
    std::uint64_t m_clockBreaks = 0;  // restarts and sequence faults the mapping began again after
    DriftWatch m_drift;
};

}  // namespace tactiscope::devices
