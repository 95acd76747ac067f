// libserialport backend.
#include "devices/transport/LibSerialPortTransport.h"

#include <libserialport.h>
#include <poll.h>

namespace tactiscope::devices::transport {
namespace {

std::string lastError()
{
    char* message = sp_last_error_message();
    std::string text = message ? message : "unknown error";
    sp_free_error_message(message);
    return text;
}

}  // namespace

LibSerialPortTransport::LibSerialPortTransport(const std::string& path, int baud)
    : m_path(path),
      m_baud(baud)
{
    if (sp_get_port_by_name(path.c_str(), &m_port) != SP_OK)
        throw TransportError("cannot find " + path + ": " + lastError());
    if (sp_open(m_port, SP_MODE_READ_WRITE) != SP_OK) {
        const std::string error = lastError();
        sp_free_port(m_port);
        m_port = nullptr;
        throw TransportError("cannot open " + path + ": " + error);
    }
    if (sp_set_baudrate(m_port, baud) != SP_OK || sp_set_bits(m_port, 8) != SP_OK ||
        sp_set_parity(m_port, SP_PARITY_NONE) != SP_OK || sp_set_stopbits(m_port, 1) != SP_OK ||
        sp_set_flowcontrol(m_port, SP_FLOWCONTROL_NONE) != SP_OK) {
        const std::string error = lastError();
        sp_close(m_port);
        sp_free_port(m_port);
        m_port = nullptr;
        throw TransportError("cannot configure " + path + ": " + error);
    }
}

LibSerialPortTransport::~LibSerialPortTransport()
{
    if (m_port) {
        sp_close(m_port);
        sp_free_port(m_port);
    }
}

std::string LibSerialPortTransport::description() const
{
    return m_path + " at " + std::to_string(m_baud) + " baud";
}

std::size_t LibSerialPortTransport::read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout)
{
    const int n = sp_blocking_read_next(m_port, buffer.data(), buffer.size(), static_cast<unsigned>(timeout.count()));
    if (n < 0) throw TransportError(m_path + ": the device was disconnected (" + lastError() + ")");
    if (n == 0 && hungUp()) throw TransportError(m_path + ": the device was disconnected (hang-up)");
    return static_cast<std::size_t>(n);
}

bool LibSerialPortTransport::hungUp() const
{
    int fd = -1;
    if (sp_get_port_handle(m_port, &fd) != SP_OK || fd < 0) return true;
    pollfd entry{fd, POLLIN, 0};
    return ::poll(&entry, 1, 0) > 0 && (entry.revents & (POLLHUP | POLLERR | POLLNVAL)) != 0;
}

void LibSerialPortTransport::write(std::span<const std::uint8_t> bytes)
{
    const std::lock_guard lock(m_writeMutex);
    const int n = sp_blocking_write(m_port, bytes.data(), bytes.size(), 1000);
    if (n < 0 || static_cast<std::size_t>(n) != bytes.size())
        throw TransportError(m_path + ": write failed (" + lastError() + ")");
}

}  // namespace tactiscope::devices::transport
