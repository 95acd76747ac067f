// A text board's bytes into samples: lines (ended by \n or \r\n, up to
// kMaxLine) read by parseTextLine (TextLine.h, every dialect), Teleplot's
// one-variable lines gathered into one sample per instant (a sample ends
// when a variable comes again, or the timestamp moves on).
//
// The first two consecutive samples that agree fix the channels (a port
// opened mid-line begins with a fragment): their names come from the
// labels, else ch1…chN, their units from the labels' brackets or
// Teleplot's '§'. Labelled values are matched by name, so their order on
// the line may change. A value that is no number ("nan", "inf", beyond
// what a stored sample holds) is NaN: a hole in its channel alone, the
// others' values kept.
//
// A board may change what it prints: two consecutive lines with other
// labels (or another count of unlabelled values) are its new layout. The
// channels only grow: a label not seen before is a new channel after the
// others (its samples before are holes), a channel no longer printed is a
// hole from there, a renamed one is both. Teleplot's variables come and
// go one by one: a new one is a channel at once, one missing from an
// instant a hole in it. A sample of a new layout carries what changed.
// One line with other labels is counted and comes out as a sample without
// values (a hole: the sample was sent and is lost, and the ones after it
// keep their time); a longer line than kMaxLine is skipped and counted.
// Blank lines are ignored, and so are (counted) lines with no number in
// them and the lines beside Teleplot's: the board's log.
#pragma once

#include "devices/protocol/DecoderCounters.h"
#include "devices/protocol/TextLine.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tactiscope::devices::protocol {

struct TextSample {
    double hostTime_s = 0.0;     // when the chunk holding the sample's last line arrived
    std::vector<double> values;  // empty: a line that could not be read
    std::optional<BoardTime> boardTime;
    // The first sample of a new layout: what changed, in words ("c appeared").
    std::optional<std::string> layoutChange;
};

class TextDecoder {
public:
    // 200 channels of long numbers fit many times over.
    static constexpr std::size_t kMaxLine = 64 * 1024;

    void push(std::span<const std::uint8_t> bytes, double hostTime_s, std::vector<TextSample>& out);
    // Empty until the first sample has been read; grows with the layouts.
    const std::vector<std::string>& channelNames() const { return m_names; }
    const std::vector<std::string>& channelUnits() const { return m_units; }
    const DecoderCounters& counters() const { return m_counters; }
    // Whether a line of numbers has come (the channels may wait for a second).
    bool heardNumbers() const { return m_candidate || m_gathering || !m_labels.empty(); }

private:
    void onLine(double hostTime_s, std::vector<TextSample>& out);
    void onSample(TextLine line, double hostTime_s, std::vector<TextSample>& out);
    // The line's values in the channels' order (NaN in those it does not
    // print); none when its labels are not the layout's.
    std::optional<std::vector<double>> inLayout(const TextLine& line) const;
    // The k-th channel without a label: the k-th unlabelled value's.
    std::size_t unlabelledChannel(std::size_t k) const;
    // Takes the line's labels as the layout, adding channels for those not
    // seen before; says what changed (none for the first layout).
    std::optional<std::string> adopt(const TextLine& line);
    void putOut(const TextLine& line, std::vector<double> values, double hostTime_s, std::optional<std::string> change,
                std::vector<TextSample>& out);
    void hole(double hostTime_s, std::vector<TextSample>& out);
    void flushGathering(std::vector<TextSample>& out);
    void flushNewLayout(std::vector<TextSample>& out);  // the line that was not followed: a hole

    std::string m_line;
    bool m_overlong = false;
    std::vector<std::string> m_labels;  // each channel's, as they appeared ("" when unlabelled)
    std::vector<std::string> m_names;
    std::vector<std::string> m_units;
    std::vector<std::string> m_layout;           // the labels the board prints now, sorted
    std::vector<std::string> m_layoutAsPrinted;  // and in the order of the line that began it
    bool m_teleplot = false;                     // the layout is Teleplot's: other lines are the board's log
    std::optional<std::pair<TextLine, double>> m_candidate;  // the first sample, until the next one agrees
    std::optional<std::pair<TextLine, double>> m_newLayout;  // a line of other labels, until the next one agrees
    std::optional<std::pair<TextLine, double>> m_gathering;  // Teleplot lines of one instant
    DecoderCounters m_counters;
};

}  // namespace tactiscope::devices::protocol
