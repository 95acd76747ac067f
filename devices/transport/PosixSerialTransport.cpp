// POSIX termios serial transport.
#include "devices/transport/PosixSerialTransport.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/file.h>
#include <termios.h>
#include <unistd.h>

namespace tactiscope::devices::transport {

int termiosSpeed(int baud)
{
    switch (baud) {
    case 9600:
        return B9600;
    case 19200:
        return B19200;
    case 38400:
        return B38400;
    case 57600:
        return B57600;
    case 115200:
        return B115200;
    case 230400:
        return B230400;
    case 460800:
        return B460800;
    case 500000:
        return B500000;
    case 921600:
        return B921600;
    case 1000000:
        return B1000000;
    case 2000000:
        return B2000000;
    default:
        return 0;
    }
}

namespace {

std::string openError(const std::string& path, int error)
{
    std::string message = "cannot open " + path + ": " + std::strerror(error);
    if (error == EACCES)
        message += " (add yourself to the 'dialout' group, or install the Tactiscope udev rules, then log in again)";
    if (error == EBUSY) message += " (another program is using the port)";
    return message;
}

}  // namespace

PosixSerialTransport::PosixSerialTransport(const std::string& path, int baud)
    : m_path(path),
      m_baud(baud)
{
    const int speed = termiosSpeed(baud);
    if (speed == 0) throw TransportError("unsupported baud rate " + std::to_string(baud));
    m_fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (m_fd < 0) throw TransportError(openError(path, errno));
    // One program per port: a second recorder on the same port would steal bytes.
    if (::flock(m_fd, LOCK_EX | LOCK_NB) != 0) {
        ::close(m_fd);
        throw TransportError(openError(path, EBUSY));
    }
    termios tty{};
    if (::tcgetattr(m_fd, &tty) != 0) {
        const int error = errno;
        ::close(m_fd);
        throw TransportError(path + " is not a serial port (" + std::strerror(error) + ")");
    }
    ::cfmakeraw(&tty);
    tty.c_cflag |= CLOCAL | CREAD;
    tty.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | PARENB | CRTSCTS);
    tty.c_cc[VMIN] = 0;
    tty.c_cc[VTIME] = 0;
    ::cfsetispeed(&tty, static_cast<speed_t>(speed));
    ::cfsetospeed(&tty, static_cast<speed_t>(speed));
    if (::tcsetattr(m_fd, TCSANOW, &tty) != 0) {
        const int error = errno;
        ::close(m_fd);
        throw TransportError("cannot configure " + path + ": " + std::strerror(error));
    }
}

PosixSerialTransport::~PosixSerialTransport()
{
    if (m_fd >= 0) ::close(m_fd);
}

std::string PosixSerialTransport::description() const
{
    return m_path + " at " + std::to_string(m_baud) + " baud";
}

std::size_t PosixSerialTransport::read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout)
{
    pollfd p{m_fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(timeout.count()));
    if (ready < 0) {
        if (errno == EINTR) return 0;
        throw TransportError(m_path + ": " + std::strerror(errno));
    }
    if (ready == 0) return 0;
    const ssize_t n = ::read(m_fd, buffer.data(), buffer.size());
    if (n > 0) return static_cast<std::size_t>(n);
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) return 0;
    // EOF, EIO or POLLHUP: the device (or the pty's other end) went away.
    throw TransportError(m_path + ": the device was disconnected");
}

void PosixSerialTransport::write(std::span<const std::uint8_t> bytes)
{
    const std::lock_guard lock(m_writeMutex);
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(m_fd, bytes.data() + done, bytes.size() - done);
        if (n > 0) {
            done += static_cast<std::size_t>(n);
            continue;
        }
        if (n < 0 && (errno == EAGAIN || errno == EINTR)) {
            pollfd p{m_fd, POLLOUT, 0};
            if (::poll(&p, 1, 1000) <= 0) throw TransportError(m_path + ": write timed out");
            continue;
        }
        throw TransportError(m_path + ": " + std::strerror(errno));
    }
}

}  // namespace tactiscope::devices::transport
