// A serial port through libserialport: 8N1, no flow control, blocking reads
// with a timeout. See SerialPorts.h for when it is used.
#pragma once

#include "devices/transport/Transport.h"

#include <mutex>

struct sp_port;

namespace tactiscope::devices::transport {

class LibSerialPortTransport final : public Transport {
public:
    // Throws TransportError (with libserialport's message) when the port
    // cannot be found, opened or configured.
    LibSerialPortTransport(const std::string& path, int baud);
    ~LibSerialPortTransport() override;

    LibSerialPortTransport(const LibSerialPortTransport&) = delete;
    LibSerialPortTransport& operator=(const LibSerialPortTransport&) = delete;

    std::string description() const override;
    std::size_t read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override;
    void write(std::span<const std::uint8_t> bytes) override;

private:
    // libserialport 0.1.1 reads a hung-up tty's end-of-file as "no data yet"
    // and would time out forever after an unplug; poll tells them apart.
    bool hungUp() const;

    std::string m_path;
    int m_baud;
    sp_port* m_port = nullptr;
    std::mutex m_writeMutex;
};

}  // namespace tactiscope::devices::transport
