// Math channels: quantities the user defines over a session's channels,
// "NAME[UNIT]=EXPR" ("diff[µε]=a - b", "k[N/m]=F_stiff / displacement",
// "dc[1]=(c - c0) / c0" with "c0[pF]=51.44" defined before it). muParser,
// the field's well-kept expression library, parses and evaluates them;
// the units are checked here by dimensional analysis: an expression is
// evaluated again with each base unit (m, kg, s, A, count) scaled, and a
// homogeneous one scales as a power of it, which is its dimension. A sum
// of a force and a length (mN + mm), or sin() of a force, scales as no
// power and is refused, as is a result whose dimension is not the unit
// declared. Numbers in an expression are pure numbers; a definition that
// is a number alone is a constant in its declared unit.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/units/Dimension.h"

#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace tactiscope::core::math {

// What a definition cannot be, in words for the user.
class MathError : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

struct MathDefinition {
    std::string name;
    std::string unit;  // as typed; "" or "1" for a pure number
    std::string expression;

    std::string text() const { return name + "[" + unit + "]=" + expression; }
};

// "NAME[UNIT]=EXPR". Throws MathError.
MathDefinition parseMathDefinition(std::string_view text);

// A channel an expression may name; its values are given in SI.
struct MathInput {
    std::string name;
    units::Dimension dimension;
    std::string unit;  // as stored, for messages
};

class MathChannels {
public:
    // Checks every definition in order (each may use the inputs and the
    // definitions before it). Throws MathError naming the definition.
    MathChannels(std::vector<MathInput> inputs, std::vector<MathDefinition> definitions);
    ~MathChannels();
    MathChannels(const MathChannels&) = delete;
    MathChannels& operator=(const MathChannels&) = delete;

    const std::vector<MathDefinition>& definitions() const { return m_definitions; }
    // Which inputs the definitions use, by index into the inputs.
    const std::vector<std::size_t>& usedInputs() const { return m_usedInputs; }

    // Rows of every input (SI; NaN where missing) → rows of every
    // definition, each in its declared unit; outputs are resized.
    void evaluate(std::span<const std::span<const double>> inputs, std::vector<std::vector<double>>& outputs);

private:
    struct Compiled;
    std::vector<MathInput> m_inputs;
    std::vector<MathDefinition> m_definitions;
    std::vector<std::unique_ptr<Compiled>> m_compiled;
    std::vector<double> m_values;  // inputs then definitions, SI: the parsers' variables
    std::vector<std::size_t> m_usedInputs;
};

// The inputs a session's channels give: name, dimension and unit of each
// whose unit this program reads (values in SI, as stored).
std::vector<MathInput> mathInputs(const std::vector<ChannelDescriptor>& channels);

// The longest expression taken: a screenful, so a parse and an evaluation
// stay bounded whatever is typed.
inline constexpr std::size_t kLongestExpression = 500;

}  // namespace tactiscope::core::math
