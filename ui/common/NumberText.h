// How every view, dialog and report writes a number: fixed decimals chosen
// from the value's resolution or uncertainty, SI prefixes where a quantity
// spans orders of magnitude, powers of ten as superscripts rather than
// "1e+09", and never a negative zero. The one place the UI formats numbers.
#pragma once

#include <QString>

#include <utility>
#include <vector>

namespace tactiscope::ui {

// A number with `decimals` fixed decimals in the user's locale: never
// "-0.000" (a value that rounds to zero is zero).
QString fixedText(double value, int decimals);

// The decimals that give `significant` digits to numbers of the size of
// `magnitude`, so values read side by side share their decimals
// ("-5.8840 … -3.9928", not "-5.884 … -3.9928"); 0..9.
int decimalsForMagnitude(double magnitude, int significant);

// A measured value to `significant` digits, trailing zeros kept (they are
// digits): "1.800", "0.0123", "12 300". Beyond what fixed decimals say
// well (below 10⁻⁴ or from 10⁹) it is written "1.23 × 10⁻⁵".
QString significantText(double value, int significant);

// A value in an SI unit with the prefix that keeps its digits between 1
// and 1000: siText(6.5e-6, "N", 2) → "6.5 µN", siText(1.2e-12, "F", 3) →
// "1.20 pF". Prefixes p … G; a bare unit for 0.
QString siText(double value_si, const QString& unit, int significant);

// A value's text and its unit, a space between ("2.5 µε"); the value
// alone for a pure number (an empty unit).
QString withUnit(const QString& value, const QString& unit);

// A value someone set or typed, as short as it reads back ("10", "0.5",
// "2.1"), in the locale, with no group separators; plain digits so a field
// can parse it again.
QString typedText(double value);

// A stored factor as short as its digits allow: up to `significant`
// digits, trailing zeros dropped ("2.14", "2"): for settings read back,
// where a trailing zero would claim a precision nobody stated.
QString compactText(double value, int significant);

// A value and its standard error as a reader takes them: the error to two
// significant digits (core::text::uncertaintyDecimals, at most six
// decimals), the value to the same decimal place; no error, no decimals.
std::pair<QString, QString> valueAndErrorTexts(double value, double standardError);
int decimalsFor(double standardError);                           // the decimals of both
QString valueWithErrorText(double value, double standardError);  // "2.13930 ± 0.00029"

// The decimals a column shares: those of its coarsest uncertainty, so no
// row claims digits the others lack and the decimal points line up
// ("117.0 / 116.9 / 117.0", never "117.0 / 116.9760 / 116.99282");
// `fallback` when no row has one.
int sharedDecimals(const std::vector<double>& standardErrors, int fallback);

// A range at `decimals`: "116.9 – 117.2", or the one value when both ends
// read the same ("117.0", never "117.0 – 117.0").
QString rangeText(double low, double high, int decimals);

// A count and its noun, in the locale's digits: "1 session", "3 sessions",
// "8,000 samples". The noun is given in both forms, so English reads right
// without a translation file.
QString countText(long long n, const QString& one, const QString& many);

}  // namespace tactiscope::ui
