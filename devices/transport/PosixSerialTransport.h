// A serial port through POSIX termios: raw 8N1 at a given baud rate, reads
// with poll() so the reader can stop within its timeout. Used for
// pseudo-terminals, which Debian's libserialport 0.1.1 cannot open (its
// sp_get_port_by_name wants a /sys/class/tty entry, and sp_open fails on the
// modem-line ioctl TIOCMGET), and for any port libserialport refuses for that
// reason; see openSerialTransport().
#pragma once

#include "devices/transport/Transport.h"

#include <mutex>

namespace tactiscope::devices::transport {

class PosixSerialTransport final : public Transport {
public:
    // Throws TransportError with the reason (no such port, permission
    // denied — with how to fix it on Linux —, not a terminal, busy).
    PosixSerialTransport(const std::string& path, int baud);
    ~PosixSerialTransport() override;

    PosixSerialTransport(const PosixSerialTransport&) = delete;
    PosixSerialTransport& operator=(const PosixSerialTransport&) = delete;

    std::string description() const override;
    std::size_t read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override;
    void write(std::span<const std::uint8_t> bytes) override;

private:
    std::string m_path;
    int m_baud;
    int m_fd = -1;
    std::mutex m_writeMutex;
};

// The baud rate constant for termios, or nothing for an unsupported rate.
int termiosSpeed(int baud);

}  // namespace tactiscope::devices::transport
