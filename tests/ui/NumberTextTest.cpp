// How the UI writes numbers: fixed decimals, significant digits, SI
// prefixes, superscript powers of ten, no negative zero. Expected texts are
// written out by hand in the C locale.
#include "ui/NumberText.h"

#include <QLocale>

#include <gtest/gtest.h>

using namespace tactiscope::ui;

namespace {

// The C locale for the hand-written texts; the user's locale back after.
class NumberText : public ::testing::Test {
protected:
    void SetUp() override { QLocale::setDefault(QLocale::c()); }
    void TearDown() override { QLocale::setDefault(m_saved); }

private:
    QLocale m_saved;
};

}  // namespace

TEST_F(NumberText, ANumberThatRoundsToZeroHasNoSign)
{
    // A baseline's −0.0004 pF of noise is "0.000 pF", not "-0.000 pF".
    EXPECT_EQ(fixedText(-0.0004, 3), QStringLiteral("0.000"));
    EXPECT_EQ(fixedText(-0.0006, 3), QStringLiteral("-0.001"));
    EXPECT_EQ(fixedText(-0.04, 1), QStringLiteral("0.0"));
    EXPECT_EQ(significantText(-1e-12, 3), QStringLiteral("-1.00 × 10⁻¹²"));
}

TEST_F(NumberText, ValuesReadSideBySideShareTheirDecimals)
{
    // Five significant digits at the larger of a stretch's extremes.
    EXPECT_EQ(decimalsForMagnitude(5.884, 5), 4);  // -5.8840 … -3.9928
    EXPECT_EQ(decimalsForMagnitude(117.0, 5), 2);  // 116.98
    EXPECT_EQ(decimalsForMagnitude(51440.0, 5), 0);
    EXPECT_EQ(decimalsForMagnitude(0.0, 5), 4);
}

TEST_F(NumberText, SignificantDigitsKeepTheirTrailingZerosAndNeverAnExponentOfE)
{
    EXPECT_EQ(significantText(1.8, 4), QStringLiteral("1.800"));
    EXPECT_EQ(significantText(0.012345, 3), QStringLiteral("0.0123"));
    EXPECT_EQ(significantText(12345.0, 3), QStringLiteral("12345"));  // never fewer digits than the integer has
    EXPECT_EQ(significantText(6.5536, 3), QStringLiteral("6.55"));
    EXPECT_EQ(significantText(0.0, 3), QStringLiteral("0.00"));
    // Beyond fixed decimals' reach: a superscript power of ten, not "1e+09".
    EXPECT_EQ(significantText(1e9, 2), QStringLiteral("1.0 × 10⁹"));
    EXPECT_EQ(significantText(2.5e-5, 2), QStringLiteral("2.5 × 10⁻⁵"));
    EXPECT_EQ(significantText(9.9996e-6, 4), QStringLiteral("1.000 × 10⁻⁵"));  // the carry
}

TEST_F(NumberText, SiPrefixesKeepTheDigitsBetweenOneAndAThousand)
{
    EXPECT_EQ(siText(6.5e-6, QStringLiteral("N"), 2), QStringLiteral("6.5 µN"));
    EXPECT_EQ(siText(1.2e-12, QStringLiteral("F"), 3), QStringLiteral("1.20 pF"));
    EXPECT_EQ(siText(0.0123, QStringLiteral("m"), 3), QStringLiteral("12.3 mm"));
    EXPECT_EQ(siText(-2.5e3, QStringLiteral("Pa"), 2), QStringLiteral("-2.5 kPa"));
    EXPECT_EQ(siText(117.0, QStringLiteral("N/m"), 3), QStringLiteral("117 N/m"));
    EXPECT_EQ(siText(210e9, QStringLiteral("Pa"), 3), QStringLiteral("210 GPa"));
    EXPECT_EQ(siText(0.0, QStringLiteral("N"), 2), QStringLiteral("0.0 N"));
    // 999.96 µN to three digits rounds to 1000 µN: said as 1.00 mN.
    EXPECT_EQ(siText(999.96e-6, QStringLiteral("N"), 3), QStringLiteral("1.00 mN"));
    // Below the smallest prefix, the smallest prefix.
    EXPECT_EQ(siText(3e-15, QStringLiteral("F"), 2), QStringLiteral("0.0030 pF"));
}

TEST_F(NumberText, AStoredFactorIsAsShortAsItsDigits)
{
    EXPECT_EQ(compactText(2.14, 4), QStringLiteral("2.14"));
    EXPECT_EQ(compactText(2.0, 4), QStringLiteral("2"));
    EXPECT_EQ(compactText(2.139876, 4), QStringLiteral("2.14"));  // rounded to four digits first
    EXPECT_EQ(compactText(1200.0, 3), QStringLiteral("1200"));
}

TEST_F(NumberText, ATypedValueReadsBackAsTyped)
{
    EXPECT_EQ(typedText(10.0), QStringLiteral("10"));
    EXPECT_EQ(typedText(0.5), QStringLiteral("0.5"));
    EXPECT_EQ(typedText(0.1 + 0.2), QStringLiteral("0.3"));  // binary noise hidden
    EXPECT_EQ(typedText(12345.678), QStringLiteral("12345.678"));
    EXPECT_EQ(typedText(1e12), QStringLiteral("1e+12"));  // parseable by a field
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    EXPECT_EQ(typedText(2.25), QStringLiteral("2,25"));
    EXPECT_EQ(typedText(12345.5), QStringLiteral("12345,5"));  // no group separator, which nobody types
    bool ok = false;
    EXPECT_EQ(QLocale().toDouble(typedText(0.001234), &ok), 0.001234);
    EXPECT_TRUE(ok);
}
