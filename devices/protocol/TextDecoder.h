// Lines of numbers, as boards print them for the Arduino IDE's Serial
// Plotter: one sample per line, values separated by commas, spaces or tabs,
// optionally as label:value pairs, ended by \n or \r\n.
//
// The first two consecutive lines that parse alike fix the channels (a port
// opened mid-line begins with a fragment): their names come from the
// labels, else ch1…chN. After that, a line with another number of values or
// other labels, or a value that is not a finite number, is counted and
// comes out as a sample without values (a hole: the sample was sent and is
// lost, and the ones after it keep their time); a line longer than kMaxLine
// is skipped and counted. Empty lines are ignored.
#pragma once

#include "devices/protocol/DecoderCounters.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tactiscope::devices::protocol {

struct TextSample {
    double hostTime_s = 0.0;     // when the chunk holding the line's end arrived
    std::vector<double> values;  // empty: a line that could not be read
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
    std::vector<std::string> m_labels;      // as they appeared ("" when unlabelled)
    std::optional<TextSample> m_candidate;  // the first line, until the next one agrees
    std::vector<std::string> m_candidateLabels;
    DecoderCounters m_counters;
};

}  // namespace tactiscope::devices::protocol
