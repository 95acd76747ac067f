// A BlockSource is anything that yields SampleBlocks of one device: the
// built-in simulator now, a transport plus protocol decoder later. It is
// driven by exactly one acquisition thread, which calls readBlock() in a loop
// and relies on its timeout to stay responsive to a stop request.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/Vocabulary.h"
#include "core/timing/ClockAlignment.h"
#include "devices/LinkNotice.h"
#include "devices/protocol/DecoderCounters.h"

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tactiscope::core {
class SampleBlock;
}

namespace tactiscope::devices {

// Who a device is, for a session's record: from a TSP/1 device's INFO, or
// the simulator's scenario; a device that does not say has only its model
// (the port's description).
struct DeviceIdentity {
    std::string model;
    std::string serial;
    std::string firmware;
};

enum class ReadStatus {
    Block,     // `out` holds a new block
    Timeout,   // nothing within the timeout; call again
    Finished,  // the source has ended normally (e.g. a finite simulation)
    Failed,    // the source cannot continue; see lastError()
};

// A device's STATUS frame: 0 ok, 1 warning, 2 error, and its message.
struct DeviceStatus {
    int level = 0;
    std::string message;
};

class BlockSource {
public:
    virtual ~BlockSource() = default;

    // Human-readable identity, e.g. "Simulator — panel scan".
    virtual std::string name() const = 0;
    // Known once constructed; a reconnection keeps the first connection's.
    virtual DeviceIdentity identity() const { return {name(), {}, {}}; }
    // The mode the source is made for, when it says so (a simulator
    // scenario does; a port's device is judged by its channels instead).
    virtual std::optional<core::Mode> declaredMode() const { return std::nullopt; }
    virtual const std::vector<core::ChannelDescriptor>& channels() const = 0;
    virtual double nominalSampleRate_hz() const = 0;

    // Blocks for at most `timeout`. Called on the acquisition thread only.
    virtual ReadStatus readBlock(core::SampleBlock& out, std::chrono::milliseconds timeout) = 0;

    // Why the last readBlock() returned Failed, in words a user can act on.
    virtual std::string lastError() const { return {}; }
    // Whether that failure is the device's own (a rate it lies about):
    // reopening it would only fail again, so nobody should retry.
    virtual bool failedForGood() const { return false; }

    // What the wire protocol has counted (bytes, CRC errors, resyncs, …);
    // all zero for sources without one. Callable from any thread.
    virtual protocol::DecoderCounters decoderCounters() const { return {}; }

    // What the link noticed since the last call (a device restart, a
    // sequence its clock contradicted), oldest first. Any thread.
    virtual std::vector<LinkNotice> takeNotices() { return {}; }
    // All the channels, when the block readBlock() just gave holds more
    // than those before (a board printing lines began to print another
    // value: channels() stays as connected); none otherwise. The reading
    // thread's, after readBlock().
    virtual std::optional<std::vector<core::ChannelDescriptor>> takeGrownChannels() { return std::nullopt; }
    // The last bytes received on the wire (at most a few kB), for the raw
    // data console; empty for sources without a wire. Any thread.
    virtual std::vector<std::uint8_t> recentBytes() const { return {}; }
    // Whether the wire carries text lines (else binary frames).
    virtual bool textProtocol() const { return false; }
    // How the rate was found when it is not the device's own word (a text
    // device's estimate), for the record; none otherwise.
    virtual std::optional<std::string> rateNote() const { return std::nullopt; }
    // The standard uncertainty of a rate this program measured (a text
    // device's: protocol/LineRate.h); none for a rate the device states.
    virtual std::optional<double> rateUncertainty_hz() const { return std::nullopt; }

    // Asks the device to switch the shunt across channel `channel`'s bridge
    // (TSP/1 command 6); the answer comes as a status (takeStatuses()), or
    // never from a device that does not know the command. Returns why it
    // cannot even be asked (a text-protocol device takes no commands), none
    // when asked. Any thread.
    virtual std::optional<std::string> requestShunt(std::size_t /*channel*/, bool /*on*/)
    {
        return "this device takes no commands";
    }
    // What the device said in its STATUS frames since the last call, oldest
    // first. Any thread.
    virtual std::vector<DeviceStatus> takeStatuses() { return {}; }
    // The device's clock on the host's steady clock: block time → host
    // time (core/timing/ClockAlignment.h); none from a source whose block
    // times are the host's own or before enough blocks. Any thread.
    virtual std::optional<core::timing::ClockMapping> hostClock() const { return std::nullopt; }
    // For a recording begun before the stream: the host instant (steady
    // clock, seconds) its stream begins at, by hostClock(). What it
    // delivers that was due earlier (what waited in the port, lines a board
    // catches up on once it is read) belongs to no session. None: from its
    // first block. Any thread.
    virtual std::optional<double> streamStart_host_s() const { return std::nullopt; }
};

}  // namespace tactiscope::devices
