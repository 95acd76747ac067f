// One line of a text board, read into named values (docs/protocol.md,
// "Text"). The dialects makers print:
//   - the Arduino IDE's Serial Plotter: values separated by commas, spaces
//     or tabs, each optionally LABEL:VALUE ("1.5,2.5", "force:0.25 pos:-1");
//   - NAME=VALUE pairs ("a=0.5,b=-1", "a=0.5 b=-1");
//   - Teleplot: one variable a line, ">NAME:VALUE" or ">NAME:TIMESTAMP:VALUE"
//     (milliseconds), with an optional unit after '§' and flags after '|'.
// A label may carry a unit in brackets ("force[mN]:1.2"). A value may have
// a leading '+' ("%+.2f"); one that is no number ("nan", "inf", "ovf") is
// NaN, a hole in its channel alone. A labelled t, time, millis or micros value, and
// Teleplot's timestamp, is the board's own clock, not a channel.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tactiscope::devices::protocol {

struct TextField {
    std::string label;  // "" when unlabelled
    std::string unit;   // "" when none was given
    double value = 0.0;
};

// The board's own time stamp on a line, in its unit.
struct BoardTime {
    double value = 0.0;
    // Seconds per unit when the label or a bracket says it ("millis": 1e-3);
    // none for a plain t or time, whose unit the arrivals tell.
    std::optional<double> seconds_per_unit;
};

struct TextLine {
    std::vector<TextField> fields;
    std::optional<BoardTime> boardTime;
    // A Teleplot line names one variable; the lines of one instant are
    // gathered into one sample.
    bool teleplot = false;
};

// Why a line is no sample: nothing in it (blank), or text that is not
// numbers (a debug print, a header, a fragment).
enum class LineRefusal { Blank, NotNumbers };

struct ParsedLine {
    std::optional<TextLine> line;
    LineRefusal refusal = LineRefusal::NotNumbers;  // when no line
};

ParsedLine parseTextLine(std::string_view text);

// Whether any field of a line that is no sample reads as a number (a
// sample cut or garbled) rather than words (the board's log).
bool hasNumber(std::string_view text);

// A number as boards print it: optional sign (a leading '+' too), digits,
// decimal point, exponent. NaN and infinities are refused.
std::optional<double> parseBoardNumber(std::string_view token);

// A value as boards print it: a number, or what they print for none
// (core/text/NoNumber.h: "nan", "inf", "ovf"), which is NaN, a hole in
// that channel alone. None for anything else.
std::optional<double> parseBoardValue(std::string_view token);

}  // namespace tactiscope::devices::protocol
