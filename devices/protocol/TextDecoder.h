// Lines of numbers, as boards print them for the Arduino IDE's Serial
// Plotter: one sample per line, values separated by commas, spaces or tabs,
// optionally as label:value pairs, ended by \n or \r\n.
//
// The first line that parses fixes the channels: their names come from the
// labels, else ch1…chN. A later line with another number of values or other
// labels, a value that is not a finite number, or a line longer than
// kMaxLine is skipped and counted, never fatal. Empty lines are ignored.
#pragma once

#include "devices/protocol/DecoderCounters.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace tactiscope::devices::protocol {

struct TextSample {
    double hostTime_s = 0.0;  // when the chunk holding the line's end arrived
    std::vector<double> values;
};

class TextDecoder {
public:
    static constexpr std::size_t kMaxLine = 1024;

    void push(std::span<const std::uint8_t> bytes, double hostTime_s, std::vector<TextSample>& out);
    // Empty until the first line has parsed.
    const std::vector<std::string>& channelNames() const { return m_names; }
    const DecoderCounters& counters() const { return m_counters; }
    void reset();

private:
    void parseLine(double hostTime_s, std::vector<TextSample>& out);

    std::string m_line;
    bool m_overlong = false;
    std::vector<std::string> m_names;
    std::vector<std::string> m_labels;  // as they appeared ("" when unlabelled)
    DecoderCounters m_counters;
};

}  // namespace tactiscope::devices::protocol
