// Math channels: muParser for the expressions, scaling for their units.
#include "core/math/MathChannels.h"

#include "core/text/NumberFormat.h"

#include <muParser.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <random>

namespace tactiscope::core::math {
namespace {

using units::Dimension;
using units::kBaseDimensions;

bool isIdentifier(std::string_view name)
{
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name.front()))) return false;
    return std::ranges::all_of(name, [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

std::string trimmed(std::string_view text)
{
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
    return std::string(text);
}

// " (the channels: a, b, force)", for a message naming an unknown one.
// The names an expression can use; a filtered channel's ("a.filtered",
// not a word) is not one of them: its channel's name reads it filtered.
std::string knownNames(const std::vector<std::string>& names)
{
    std::string known;
    bool filtered = false;
    for (const std::string& name : names) {
        if (isIdentifier(name))
            known += (known.empty() ? "" : ", ") + name;
        else
            filtered = filtered || name.ends_with(".filtered");
    }
    if (known.empty()) return "";
    return " (the channels: " + known +
           (filtered ? "; a filtered channel is read by its own name, filtered, as live math channels read it)" : ")");
}

// Test points: values a channel may take, away from zero (so a ratio has
// one) and positive (so a square root or a logarithm has one).
constexpr std::size_t kPoints = 12;
// Scales far apart as well as near: a term mixed in with a small factor
// ("displacement + 1e-9 * force") barely moves at ×2 but shows at ×10⁶.
constexpr std::array kScales{2.0, 1e3, 1e6};
constexpr double kAgreement = 1e-6;  // exponents found at the points agree this well

}  // namespace

MathDefinition parseMathDefinition(std::string_view text)
{
    const auto open = text.find('[');
    const auto close = text.find(']');
    const auto equals = text.find('=', close == std::string_view::npos ? 0 : close);
    if (open == std::string_view::npos || close == std::string_view::npos || equals == std::string_view::npos ||
        close < open)
        throw MathError("a math channel is NAME[UNIT]=EXPR (e.g. \"diff[µε]=a - b\"), not '" + std::string(text) + "'");
    MathDefinition definition{trimmed(text.substr(0, open)), trimmed(text.substr(open + 1, close - open - 1)),
                              trimmed(text.substr(equals + 1))};
    if (trimmed(text.substr(close + 1, equals - close - 1)) != "")
        throw MathError("a math channel is NAME[UNIT]=EXPR; '" + std::string(text) + "' has more between ] and =");
    if (definition.name == "t") throw MathError("'t' is the export's time column: a math channel needs another name");
    if (!isIdentifier(definition.name))
        throw MathError("a math channel's name is letters, digits and _, not starting with a digit: '" +
                        definition.name + "'");
    if (!units::parseUnit(definition.unit))
        throw MathError("'" + definition.unit + "' (of " + definition.name +
                        ") is not a unit this program reads (e.g. N/m, mN, pF, µε, m/s^2, 1)");
    if (definition.expression.empty()) throw MathError(definition.name + " has no expression after '='");
    if (definition.expression.size() > kLongestExpression)
        throw MathError(definition.name + "'s expression is longer than " + std::to_string(kLongestExpression) +
                        " characters");
    return definition;
}

struct MathChannels::Compiled {
    mu::Parser parser;
    std::vector<std::size_t> variables;  // indices into m_values it uses
    double toSi = 1.0;                   // of the declared unit
    bool constant = false;
    double constantValue_si = 0.0;
};

namespace {

// Whether the expression's value stays as it is when the `scaled` among
// its `used` values are all multiplied by one factor (a ratio of them):
// tried at a few points; `values` is left as it was.
bool unchangedByScaling(mu::Parser& parser, std::vector<double>& values, const std::vector<std::size_t>& used,
                        const std::vector<std::size_t>& scaled)
{
    const std::vector<double> saved = values;
    std::mt19937 random(11);
    std::uniform_real_distribution<double> value(0.5, 2.0);
    bool unchanged = true;
    int compared = 0;
    for (std::size_t point = 0; point < kPoints && unchanged; ++point) {
        for (const std::size_t v : used) values[v] = value(random);
        try {
            const double plain = parser.Eval();
            for (const std::size_t v : scaled) values[v] *= 1e3;
            const double times = parser.Eval();
            if (!std::isfinite(plain) || !std::isfinite(times)) continue;
            unchanged = std::abs(times - plain) <= 1e-9 * std::max(std::abs(plain), 1e-300);
            ++compared;
        } catch (const mu::Parser::exception_type&) {
            // A point outside the expression's domain says nothing.
        }
    }
    values = saved;
    return unchanged && compared > 0;
}

// The definition's dimension from how it scales; throws MathError.
Dimension dimensionOf(const MathDefinition& definition, mu::Parser& parser, std::vector<double>& values,
                      const std::vector<std::size_t>& used, const std::vector<Dimension>& dimensions,
                      const std::string& usedText)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<double> value(0.5, 2.0);
    std::vector<std::vector<double>> points(kPoints, std::vector<double>(used.size()));
    for (auto& point : points)
        for (double& v : point) v = value(random);
    const auto evaluateAt = [&](const std::vector<double>& point, std::size_t base, double scale) {
        for (std::size_t j = 0; j < used.size(); ++j)
            values[used[j]] = point[j] * std::pow(scale, dimensions[used[j]].exponents[base]);
        try {
            return parser.Eval();
        } catch (const mu::Parser::exception_type&) {
            return std::nan("");
        }
    };
    const std::string mixed = "'" + definition.expression +
                              "' is not one quantity: it adds, subtracts or compares quantities of different units, "
                              "or takes a function of one with a unit (" +
                              usedText + "; a number in an expression has no unit)";
    Dimension result;
    for (std::size_t base = 0; base < kBaseDimensions; ++base) {
        std::vector<double> exponents;
        for (const auto& point : points) {
            const double plain = evaluateAt(point, base, 1.0);
            if (!std::isfinite(plain) || std::abs(plain) < 1e-300) continue;
            for (const double scale : kScales) {
                const double scaled = evaluateAt(point, base, scale);
                if (!std::isfinite(scaled)) continue;
                const double ratio = scaled / plain;
                if (!(ratio > 0.0)) throw MathError(mixed);
                exponents.push_back(std::log(ratio) / std::log(scale));
            }
        }
        if (exponents.size() < 2)
            throw MathError("'" + definition.expression +
                            "' gives 0 or no number for every value tried: its unit cannot be checked");
        const auto [low, high] = std::ranges::minmax(exponents);
        const double half = std::round(2.0 * exponents.front()) / 2.0;
        if (high - low > kAgreement || std::abs(exponents.front() - half) > kAgreement) throw MathError(mixed);
        result.exponents[base] = half;
    }
    return result;
}

}  // namespace

MathChannels::MathChannels(std::vector<MathInput> inputs, std::vector<MathDefinition> definitions)
    : m_inputs(std::move(inputs)),
      m_definitions(std::move(definitions)),
      m_values(m_inputs.size() + m_definitions.size(), 1.0)
{
    std::vector<std::string> names;
    std::vector<Dimension> dimensions;
    std::vector<std::string> units;
    for (const MathInput& input : m_inputs) {
        names.push_back(input.name);
        dimensions.push_back(input.dimension);
        units.push_back(input.unit);
    }
    for (std::size_t d = 0; d < m_definitions.size(); ++d) {
        const MathDefinition& definition = m_definitions[d];
        if (std::ranges::find(names, definition.name) != names.end())
            throw MathError("'" + definition.name + "' is already a channel's name");
        const units::Unit declared = units::parseUnit(definition.unit).value_or(units::Unit{});
        auto compiled = std::make_unique<Compiled>();
        compiled->toSi = declared.toSi;
        mu::Parser& parser = compiled->parser;
        try {
            for (std::size_t i = 0; i < names.size(); ++i)
                if (isIdentifier(names[i])) parser.DefineVar(names[i], &m_values[i]);
            parser.SetExpr(definition.expression);
            for (const auto& [name, address] : parser.GetUsedVar()) {
                if (address < m_values.data() || address >= m_values.data() + m_values.size())
                    throw MathError(definition.name + ": '" + name + "' is not a channel here" + knownNames(names));
                compiled->variables.push_back(static_cast<std::size_t>(address - m_values.data()));
            }
        } catch (const mu::Parser::exception_type& e) {
            throw MathError(definition.name + ": " + e.GetMsg() + knownNames(names));
        }
        try {
            int results = 0;
            parser.Eval(results);
            if (results != 1)
                throw MathError(definition.name + ": '" + definition.expression +
                                "' gives several values (a comma between them); a math channel is one");
        } catch (const mu::Parser::exception_type&) {
            // An evaluation error at the test values is judged by the unit check below.
        }
        if (compiled->variables.empty()) {
            // A number alone: a constant in its declared unit.
            try {
                compiled->constant = true;
                compiled->constantValue_si = parser.Eval() * declared.toSi;
            } catch (const mu::Parser::exception_type& e) {
                throw MathError(definition.name + ": " + e.GetMsg());
            }
            if (!std::isfinite(compiled->constantValue_si))
                throw MathError(definition.name + " is not a finite number");
        } else {
            std::string usedText;
            for (const std::size_t v : compiled->variables)
                usedText +=
                    (usedText.empty() ? "" : ", ") + names[v] + " [" + (units[v].empty() ? "1" : units[v]) + "]";
            const std::vector<double> saved = m_values;
            const Dimension found =
                dimensionOf(definition, parser, m_values, compiled->variables, dimensions, usedText);
            m_values = saved;
            if (!(found == declared.dimension)) {
                const auto inWords = [](const Dimension& dimension) {
                    return dimension.dimensionless() ? std::string("a pure number") : "in " + dimension.text();
                };
                throw MathError(definition.name + ": '" + definition.expression + "' is " + inWords(found) + " (" +
                                usedText + "), but [" + definition.unit + "] is " + inWords(declared.dimension));
            }
            // A channel with no unit (a board's numbers before --units) is a
            // pure number; a scaled pure unit such as µε or % would take its
            // numbers for that quantity in SI, a million times off for µε.
            std::vector<std::size_t> unitless;
            for (const std::size_t v : compiled->variables)
                if (v < m_inputs.size() && units[v].empty()) unitless.push_back(v);
            std::ranges::sort(unitless);  // in the channels' order
            // A ratio of them ((a - b) / b in %) is a pure number whatever their unit.
            if (declared.toSi != 1.0 && !unitless.empty() &&
                !unchangedByScaling(parser, m_values, compiled->variables, unitless)) {
                std::string which;
                for (std::size_t i = 0; i < unitless.size(); ++i)
                    which += (i == 0 ? "" : i + 1 == unitless.size() ? " and " : ", ") + names[unitless[i]];
                throw MathError(definition.name + ": " + which + (unitless.size() == 1 ? " has" : " have") +
                                " no unit, so [" + definition.unit +
                                "] would take the numbers for a quantity they may not be: give the channels their "
                                "units (a board's: --units " +
                                names[unitless.front()] + "=µε, …), or declare " + definition.name +
                                "[] (a pure number)");
            }
        }
        for (const std::size_t v : compiled->variables)
            if (v < m_inputs.size() && std::ranges::find(m_usedInputs, v) == m_usedInputs.end())
                m_usedInputs.push_back(v);
        names.push_back(definition.name);
        dimensions.push_back(declared.dimension);
        units.push_back(definition.unit);
        m_compiled.push_back(std::move(compiled));
    }
}

MathChannels::~MathChannels() = default;

void MathChannels::evaluate(std::span<const std::span<const double>> inputs, std::vector<std::vector<double>>& outputs)
{
    const std::size_t rows = inputs.empty() ? 0 : inputs.front().size();
    outputs.resize(m_definitions.size());
    for (auto& output : outputs) output.resize(rows);
    for (std::size_t r = 0; r < rows; ++r) {
        for (const std::size_t i : m_usedInputs) m_values[i] = inputs[i][r];
        for (std::size_t d = 0; d < m_compiled.size(); ++d) {
            Compiled& compiled = *m_compiled[d];
            double si = compiled.constantValue_si;
            if (!compiled.constant) {
                // A lost sample stays lost, whatever the expression does
                // with it (a comparison would turn NaN into 0).
                const bool lost =
                    std::ranges::any_of(compiled.variables, [&](std::size_t v) { return std::isnan(m_values[v]); });
                try {
                    si = lost ? std::nan("") : compiled.parser.Eval();
                } catch (const mu::Parser::exception_type&) {
                    si = std::nan("");
                }
            }
            m_values[m_inputs.size() + d] = si;
            outputs[d][r] = si / compiled.toSi;
        }
    }
}

std::vector<MathInput> mathInputs(const std::vector<ChannelDescriptor>& channels)
{
    std::vector<MathInput> inputs;
    for (const ChannelDescriptor& channel : channels) {
        // A unit this program does not read is a dimension of its own
        // nobody else has: such a channel can only be scaled, never mixed.
        const auto unit = units::parseUnit(channel.unit);
        const bool strain = channel.kind == ChannelKind::Strain && channel.unit.empty();
        inputs.push_back({channel.name, unit ? unit->dimension : units::Dimension{{0, 0, 0, 0, 7}},
                          strain ? "strain" : channel.unit});
    }
    return inputs;
}

}  // namespace tactiscope::core::math
