// Math channels: their definitions, their unit algebra and refusals, their
// values against the same arithmetic done here, and a fuzz of random
// expressions that must be refused or evaluated, never crash.
#include "core/math/MathChannels.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <random>

using namespace tactiscope::core;
using math::MathChannels;
using math::MathDefinition;
using math::MathError;
using math::MathInput;
using math::parseMathDefinition;

namespace {

MathInput input(const std::string& name, const std::string& unit)
{
    return {name, units::parseUnit(unit).value().dimension, unit};
}

// A palpation probe's and a capacitive beam's channels, as stored (SI).
std::vector<MathInput> probeInputs()
{
    return {input("a", "strain"),       input("b", "strain"), input("F_stiff", "N"), input("F_soft", "N"),
            input("displacement", "m"), input("c", "F"),      input("raw", "count")};
}

std::vector<MathDefinition> definitions(std::initializer_list<const char*> texts)
{
    std::vector<MathDefinition> result;
    for (const char* text : texts) result.push_back(parseMathDefinition(text));
    return result;
}

std::string refusal(std::initializer_list<const char*> texts)
{
    try {
        MathChannels channels(probeInputs(), definitions(texts));
    } catch (const MathError& e) {
        return e.what();
    }
    return {};
}

}  // namespace

TEST(Units, ProductsQuotientsPrefixesAndPowers)
{
    const auto n_per_m = units::parseUnit("N/m").value();
    EXPECT_EQ(n_per_m.dimension.text(), "kg s^-2");
    EXPECT_DOUBLE_EQ(n_per_m.toSi, 1.0);
    EXPECT_EQ(units::parseUnit("mN/mm").value().dimension, n_per_m.dimension);
    EXPECT_DOUBLE_EQ(units::parseUnit("mN/mm").value().toSi, 1.0);
    EXPECT_DOUBLE_EQ(units::parseUnit("pF").value().toSi, 1e-12);
    EXPECT_DOUBLE_EQ(units::parseUnit("µε").value().toSi, 1e-6);
    EXPECT_TRUE(units::parseUnit("µε").value().dimension.dimensionless());
    EXPECT_EQ(units::parseUnit("m/s^2").value().dimension.text(), "m s^-2");
    EXPECT_EQ(units::parseUnit("N·m").value().dimension, units::parseUnit("N*m").value().dimension);
    EXPECT_DOUBLE_EQ(units::parseUnit("kg").value().toSi, 1.0);
    EXPECT_TRUE(units::parseUnit("1").value().dimension.dimensionless());
    EXPECT_TRUE(units::parseUnit("").has_value());
    for (const char* bad : {"furlong", "N/m/s", "m^x", "kcount", "N^0", "mN+"})
        EXPECT_FALSE(units::parseUnit(bad)) << bad;
}

TEST(MathChannels, DefinitionsAreReadAsNameUnitExpression)
{
    const MathDefinition d = parseMathDefinition("k[N/m] = F_stiff / displacement");
    EXPECT_EQ(d.name, "k");
    EXPECT_EQ(d.unit, "N/m");
    EXPECT_EQ(d.expression, "F_stiff / displacement");
    for (const char* bad : {"k=F", "k[N/m]", "[N]=F", "2k[N]=F", "k[N]x=F", "k[N]=", "k[bushel]=F"})
        EXPECT_THROW(parseMathDefinition(bad), MathError) << bad;
}

TEST(MathChannels, UnitAlgebraAcceptsWhatIsOneQuantity)
{
    EXPECT_EQ(refusal({"diff[µε]=a - b"}), "");
    EXPECT_EQ(refusal({"k[N/m]=F_stiff / displacement"}), "");
    EXPECT_EQ(refusal({"k[mN/mm]=(F_stiff - F_soft) / displacement"}), "");
    EXPECT_EQ(refusal({"c0[pF]=51.44", "dc[1]=(c - c0) / c0"}), "");
    EXPECT_EQ(refusal({"q[1]=F_soft / F_stiff", "qq[%]=q"}), "");  // a fraction, shown in %
    EXPECT_EQ(refusal({"rms[N]=sqrt(F_stiff^2 + F_soft^2)"}), "");
    EXPECT_EQ(refusal({"root[m^1]=sqrt(displacement * displacement)"}), "");
    EXPECT_EQ(refusal({"e[1]=exp(a / b)", "mean[N]=(F_stiff + F_soft) / 2"}), "");
    EXPECT_EQ(refusal({"work[N*m]=F_stiff * displacement"}), "");
    EXPECT_EQ(refusal({"twice[count]=2 * raw"}), "");
}

// A board's numbers before it is given units are pure numbers: a math
// channel over them may be one too, but not a scaled pure unit such as µε,
// which would take them for strain in SI (3.0 read as 3,000,000 µε).
TEST(MathChannels, AChannelWithNoUnitIsNotTakenForStrain)
{
    const std::vector<MathInput> board{input("n", ""), input("m", ""), input("a", "strain")};
    const auto refused = [&](const char* text) {
        try {
            MathChannels channels(board, definitions({text}));
        } catch (const MathError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    const std::string asStrain = refused("diff[µε]=n - m");
    EXPECT_NE(asStrain.find("n and m have no unit, so [µε] would take the numbers"), std::string::npos) << asStrain;
    EXPECT_NE(asStrain.find("--units n=µε"), std::string::npos) << asStrain;
    EXPECT_NE(refused("share[%]=n / 2").find("n has no unit"), std::string::npos);
    EXPECT_EQ(refused("change[%]=(n - m) / m"), "") << "a ratio of them is a pure number whatever their unit";
    EXPECT_EQ(refused("diff[]=n - m"), "");
    EXPECT_EQ(refused("ratio[1]=n / m"), "");
    EXPECT_EQ(refused("gauge[µε]=a"), "");  // a probe's strain channel is strain
}

// A filtered channel's name ("a.filtered") is no word an expression can
// hold: a refusal lists the names it can, and says how a filtered one is read.
TEST(MathChannels, ARefusalListsOnlyNamesAnExpressionCanUse)
{
    try {
        MathChannels channels({input("a", "strain"), input("a.filtered", "strain")}, definitions({"x[1]=q"}));
        FAIL() << "q is no channel";
    } catch (const MathError& e) {
        const std::string said = e.what();
        EXPECT_NE(said.find("(the channels: a; a filtered channel is read by its own name"), std::string::npos) << said;
        EXPECT_EQ(said.find("a.filtered"), std::string::npos) << said;
    }
}

TEST(MathChannels, UnitAlgebraRefusesWhatMixesUnitsWithAMessage)
{
    // mN + mm: a force and a length.
    const std::string sum = refusal({"bad[N]=F_stiff + displacement"});
    EXPECT_NE(sum.find("not one quantity"), std::string::npos) << sum;
    EXPECT_NE(sum.find("F_stiff [N]"), std::string::npos) << sum;
    EXPECT_NE(sum.find("displacement [m]"), std::string::npos) << sum;
    EXPECT_NE(refusal({"s[1]=sin(F_stiff)"}).find("not one quantity"), std::string::npos);
    EXPECT_NE(refusal({"small[m]=displacement + 1e-9 * F_stiff"}).find("not one quantity"), std::string::npos);
    EXPECT_NE(refusal({"plus[N]=F_stiff + 1"}).find("a number in an expression has no unit"), std::string::npos);
    EXPECT_NE(refusal({"u[N]=raw + F_stiff"}).find("not one quantity"), std::string::npos);  // counts are not newtons
    EXPECT_NE(refusal({"v[N]=F_stiff > displacement"}).find("not one quantity"), std::string::npos);
    // The right algebra in the wrong unit.
    const std::string wrong = refusal({"k[N]=F_stiff / displacement"});
    EXPECT_NE(wrong.find("is in kg s^-2"), std::string::npos) << wrong;
    EXPECT_NE(wrong.find("[N] is in m kg s^-2"), std::string::npos) << wrong;
    EXPECT_NE(refusal({"w[1]=nothere * 2"}).find("the channels: a, b"), std::string::npos);
    EXPECT_NE(refusal({"a[1]=b"}).find("already a channel"), std::string::npos);
    EXPECT_NE(refusal({"z[1]=a - a"}).find("cannot be checked"), std::string::npos);
    EXPECT_NE(refusal({"p[1]=(a"}).find("p:"), std::string::npos);
    EXPECT_NE(refusal({"two[1]=a, b"}).find("several values"), std::string::npos);
    EXPECT_THROW(parseMathDefinition("t[1]=a"), MathError);  // the export's time column
}

TEST(MathChannels, ValuesAreTheArithmeticInTheDeclaredUnit)
{
    std::mt19937 random(3);
    std::uniform_real_distribution<double> strain(-3e-4, 3e-4);
    std::uniform_real_distribution<double> force(1e-3, 2.0);
    const std::size_t n = 1000;
    std::vector<std::vector<double>> columns(7, std::vector<double>(n));
    for (std::size_t i = 0; i < n; ++i) {
        columns[0][i] = strain(random);
        columns[1][i] = strain(random);
        columns[2][i] = force(random);
        columns[3][i] = force(random) / 3.0;
        columns[4][i] = 1e-3 + 1e-3 * force(random);
        columns[5][i] = 51.44e-12 + 1e-13 * force(random);
        columns[6][i] = std::round(1e5 * force(random));
    }
    columns[0][17] = std::nan("");  // a lost sample stays lost
    MathChannels channels(probeInputs(), definitions({"diff[µε]=a - b", "k[mN/mm]=(F_stiff - F_soft) / displacement",
                                                      "c0[pF]=51.44", "dc[%]=(c - c0) / c0", "up[1]=a > b"}));
    const std::vector<std::span<const double>> inputs(columns.begin(), columns.end());
    std::vector<std::vector<double>> out;
    channels.evaluate(inputs, out);
    ASSERT_EQ(out.size(), 5u);
    for (std::size_t i = 0; i < n; ++i) {
        if (i == 17) {
            EXPECT_TRUE(std::isnan(out[0][i]));
            EXPECT_TRUE(std::isnan(out[4][i]));  // a comparison would have said 0
            continue;
        }
        EXPECT_EQ(out[4][i], columns[0][i] > columns[1][i] ? 1.0 : 0.0);
        const double diff = (columns[0][i] - columns[1][i]) * 1e6;
        const double k = (columns[2][i] - columns[3][i]) / columns[4][i];  // N/m is mN/mm
        const double dc = 100.0 * (columns[5][i] - 51.44e-12) / 51.44e-12;
        EXPECT_NEAR(out[0][i], diff, 1e-12 * std::abs(diff) + 1e-300) << i;
        EXPECT_NEAR(out[1][i], k, 1e-12 * std::abs(k)) << i;
        EXPECT_NEAR(out[2][i], 51.44, 1e-12 * 51.44);
        EXPECT_NEAR(out[3][i], dc, 1e-9 * std::abs(dc)) << i;  // a small difference of two capacitances
    }
}

TEST(MathChannels, TenThousandRandomExpressionsAreRefusedOrEvaluatedNeverACrash)
{
    // Tokens of every kind muParser knows, strung at random: most are not
    // expressions at all. Each must be refused with a message or evaluated.
    const std::vector<std::string> tokens{"a",    "b",    "F_stiff", "displacement",
                                          "c",    "raw",  "q",       "1",
                                          "0",    "2.5",  "1e308",   "-1e-308",
                                          "+",    "-",    "*",       "/",
                                          "^",    "(",    ")",       "(",
                                          ")",    "sin(", "sqrt(",   "log(",
                                          "exp(", ",",    "?",       ":",
                                          "<",    ">=",   "==",      "&&",
                                          "||",   "!",    "_pi",     "min(",
                                          "max(", "sum(", "avg(",    "rint("};
    std::mt19937 random(57);
    std::uniform_int_distribution<std::size_t> pick(0, tokens.size() - 1);
    std::uniform_int_distribution<int> length(1, 40);
    std::vector<std::vector<double>> columns(7, std::vector<double>(64, 0.5));
    const std::vector<std::span<const double>> inputs(columns.begin(), columns.end());
    // Half strings of tokens, half grammatical expressions over the pure
    // numbers a and b (most of which are one quantity and are evaluated).
    const std::vector<std::string> operators{" + ", " - ", " * ", " / ", "^", " < ", " == "};
    const std::vector<std::string> functions{"sin", "cos", "sqrt", "log", "exp", "abs", "tanh", "rint"};
    std::function<std::string(int)> grammatical = [&](int depth) -> std::string {
        switch (depth <= 0 ? 0 : random() % 4) {
        case 0:
            return std::vector<std::string>{"a", "b", "2", "0.5", "1e-3"}[random() % 5];
        case 1:
            return grammatical(depth - 1) + operators[random() % operators.size()] + grammatical(depth - 1);
        case 2:
            return functions[random() % functions.size()] + "(" + grammatical(depth - 1) + ")";
        default:
            return "(" + grammatical(depth - 1) + ")";
        }
    };
    int evaluated = 0;
    double slowest_s = 0.0;
    for (int trial = 0; trial < 10000; ++trial) {
        std::string expression;
        if (trial % 2 == 0) {
            for (int t = length(random); t > 0; --t) expression += tokens[pick(random)] + " ";
        } else {
            expression = grammatical(6);
            if (expression.size() > math::kLongestExpression) expression.resize(math::kLongestExpression);
        }
        const auto started = std::chrono::steady_clock::now();
        try {
            MathChannels channels(probeInputs(), {parseMathDefinition("x[1]=" + expression)});
            std::vector<std::vector<double>> out;
            channels.evaluate(inputs, out);
            ++evaluated;
        } catch (const MathError& e) {
            EXPECT_GT(std::string(e.what()).size(), 5u);
        }
        slowest_s =
            std::max(slowest_s, std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
    }
    EXPECT_GT(evaluated, 0);
    // Reported, not asserted (a loaded machine is slow): the bound is 100 ms.
    std::cout << "random expressions: " << evaluated << " of 10000 evaluated; slowest check and evaluation "
              << slowest_s * 1e3 << " ms\n";
}
