// How the UI writes numbers: fixed decimals, significant digits, SI
// prefixes, superscript powers of ten, no negative zero. Expected texts are
// written out by hand in the C locale.
#include "ui/common/NumberText.h"

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

TEST_F(NumberText, AColumnSharesTheDecimalsOfItsCoarsestUncertainty)
{
    // Issue 37's By-site column: SDs of 0.034, 0.0021 and none (one press)
    // gave 117.0 / 116.9760 / 116.99282; they share 0.034's three decimals.
    EXPECT_EQ(sharedDecimals({0.034, 0.0021}, 1), 3);
    EXPECT_EQ(sharedDecimals({}, 1), 1);                        // no uncertainty anywhere: the fallback
    EXPECT_EQ(sharedDecimals({0.0, std::nan(""), 1.2}, 4), 1);  // zeros and NaN say nothing
    EXPECT_EQ(valueWithErrorText(2.139301, 0.00029), QStringLiteral("2.13930 ± 0.00029"));
}

TEST_F(NumberText, ARangeWhoseEndsReadTheSameIsOneValue)
{
    EXPECT_EQ(rangeText(117.0, 117.0, 1), QStringLiteral("117.0"));
    EXPECT_EQ(rangeText(116.98, 117.01, 1), QStringLiteral("117.0"));  // equal as written
    EXPECT_EQ(rangeText(116.9, 117.2, 1), QStringLiteral("116.9 – 117.2"));
}

TEST_F(NumberText, OneIsSingularAndCountsAreInTheLocalesDigits)
{
    EXPECT_EQ(countText(1, QStringLiteral("session"), QStringLiteral("sessions")), QStringLiteral("1 session"));
    EXPECT_EQ(countText(0, QStringLiteral("session"), QStringLiteral("sessions")), QStringLiteral("0 sessions"));
    QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
    EXPECT_EQ(countText(8000, QStringLiteral("sample"), QStringLiteral("samples")), QStringLiteral("8,000 samples"));
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    EXPECT_EQ(countText(12345678, QStringLiteral("sample"), QStringLiteral("samples")),
              QStringLiteral("12.345.678 samples"));
}
