// A maker's board printing text lines on a real pseudo-terminal, with the
// timing such boards have: a crystal of its own (a known true rate), lines
// that leave in bursts (a USB CDC link sends what gathered in a frame) and
// late by a random jitter, bytes split across writes mid-line, and lines
// printed before anyone opened the port (they wait in the pty, as in a
// board's USB buffer). It prints from construction until destruction.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <random>
#include <stop_token>
#include <string>
#include <thread>

#include <fcntl.h>
#include <poll.h>
#include <stdlib.h>
#include <termios.h>
#include <unistd.h>

namespace tactiscope::testing {

struct TextBoardOptions {
    double rate_hz = 100.0;
    // Line n, with its end ("\n" or "\r\n").
    std::function<std::string(std::uint64_t)> line;
    std::size_t linesPerBurst = 1;  // lines gathered before they leave together
    double jitter_s = 0.0;          // each burst leaves up to this late
    bool splitWrites = false;       // each burst written in two pieces, cut mid-line
    // How long a write waits on a full port before what does not fit is
    // lost; a board whose Serial.write blocks waits for as long as it
    // takes, and then catches up on the lines its schedule says are due.
    double longestWait_s = 1.0;
    double linkBytesPerSecond = 0.0;  // the link's pace (a USB CDC link's ~1 MB/s); 0: the pty's
};

class TextBoard {
public:
    TextBoard(std::string link, TextBoardOptions options)
        : m_link(std::move(link)),
          m_options(std::move(options))
    {
        m_master = ::posix_openpt(O_RDWR | O_NOCTTY);
        if (m_master < 0 || ::grantpt(m_master) != 0 || ::unlockpt(m_master) != 0) return;
        const std::string slave = ::ptsname(m_master);
        // The slave stays open here, raw, so that lines printed before the
        // port is opened wait in it and nothing echoes.
        m_slave = ::open(slave.c_str(), O_RDWR | O_NOCTTY);
        termios raw{};
        ::tcgetattr(m_slave, &raw);
        ::cfmakeraw(&raw);
        ::tcsetattr(m_slave, TCSANOW, &raw);
        ::fcntl(m_master, F_SETFL, ::fcntl(m_master, F_GETFL) | O_NONBLOCK);
        std::filesystem::remove(m_link);
        std::filesystem::create_symlink(slave, m_link);
        m_start = std::chrono::steady_clock::now();
        m_thread = std::jthread([this](const std::stop_token& stop) { print(stop); });
    }

    ~TextBoard()
    {
        m_thread = {};
        if (m_slave >= 0) ::close(m_slave);
        if (m_master >= 0) ::close(m_master);
        std::error_code ignored;
        std::filesystem::remove(m_link, ignored);
    }

    TextBoard(const TextBoard&) = delete;
    TextBoard& operator=(const TextBoard&) = delete;

    bool ok() const { return m_slave >= 0; }
    // Lines printed so far (sent or waiting in the port).
    std::uint64_t printed() const { return m_printed; }
    // The line its schedule is at: more than printed() while it is held up
    // (its writes waited on a full port), which it then catches up on.
    std::uint64_t due() const
    {
        const std::chrono::duration<double> since = std::chrono::steady_clock::now() - m_start;
        return static_cast<std::uint64_t>(since.count() * m_options.rate_hz);
    }

private:
    void print(const std::stop_token& stop)
    {
        std::mt19937_64 random(7);
        std::uniform_real_distribution<double> late(0.0, m_options.jitter_s);
        std::uint64_t n = 0;
        while (!stop.stop_requested()) {
            // The burst leaves once its last line was printed, at the board's pace.
            const std::uint64_t last = n + m_options.linesPerBurst - 1;
            const auto due =
                m_start +
                std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(
                    static_cast<double>(last) / m_options.rate_hz + (m_options.jitter_s > 0.0 ? late(random) : 0.0)));
            std::this_thread::sleep_until(due);
            std::string bytes;
            for (; n <= last; ++n) bytes += m_options.line(n);
            if (m_options.splitWrites && bytes.size() > 2) {
                write(bytes.substr(0, bytes.size() / 2 + 1), stop);
                std::this_thread::sleep_for(std::chrono::microseconds(300));
                write(bytes.substr(bytes.size() / 2 + 1), stop);
            } else {
                write(bytes, stop);
            }
            m_printed = n;
        }
    }

    // A board's write waits while the port is full (as Serial.write does),
    // but what does not fit within longestWait_s (a second) is lost, as
    // from a board whose buffer nobody reads; a reader that is merely slow
    // (a busy core, a sanitizer) takes it all. A board being put away
    // stops waiting.
    void write(const std::string& bytes, const std::stop_token& stop)
    {
        if (m_options.linkBytesPerSecond > 0.0) {
            std::this_thread::sleep_until(m_linkFree);
            m_linkFree = std::max(m_linkFree, std::chrono::steady_clock::now()) +
                         std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(
                             static_cast<double>(bytes.size()) / m_options.linkBytesPerSecond));
        }
        std::size_t sent = 0;
        const auto waits = static_cast<int>(1000.0 * m_options.longestWait_s);
        for (int wait = 0; sent < bytes.size() && wait < waits && !stop.stop_requested(); ++wait) {
            const auto written = ::write(m_master, bytes.data() + sent, bytes.size() - sent);
            if (written > 0) sent += static_cast<std::size_t>(written);
            if (sent < bytes.size()) {
                pollfd writable{m_master, POLLOUT, 0};
                ::poll(&writable, 1, 1);
            }
        }
    }

    std::string m_link;
    TextBoardOptions m_options;
    int m_master = -1;
    int m_slave = -1;
    std::chrono::steady_clock::time_point m_start;
    std::chrono::steady_clock::time_point m_linkFree;  // when the link has sent what it was given
    std::atomic<std::uint64_t> m_printed = 0;
    std::jthread m_thread;
};

}  // namespace tactiscope::testing
