// A byte-stream connection to a device: a serial port, a pseudo-terminal, or
// HID reports drained into a stream. Decoders sit on top and never know which.
//
// Threading: one reader thread calls read(); write() may be called from
// another thread (commands) and must be safe against a concurrent read().
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

namespace tactiscope::devices::transport {

// The connection is gone (unplugged, closed by the other end) or unusable;
// what() says what happened in words a user can act on.
class TransportError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class Transport {
public:
    virtual ~Transport() = default;

    // E.g. "/dev/ttyACM0 at 921600 baud".
    virtual std::string description() const = 0;
    // Up to buffer.size() bytes, waiting at most `timeout`; 0 on timeout.
    // Throws TransportError when the device is gone.
    virtual std::size_t read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) = 0;
    // All of `bytes`, or TransportError.
    virtual void write(std::span<const std::uint8_t> bytes) = 0;
    // When the bytes the last read() returned reached the host (steady
    // clock seconds), when it knows better than its caller's clock after
    // the call (ReadAheadTransport read them earlier); none otherwise.
    virtual std::optional<double> arrival_s() const { return std::nullopt; }
};

}  // namespace tactiscope::devices::transport
