// Number texts for every view, dialog and report.
#include "ui/common/NumberText.h"

#include "core/text/UncertaintyFormat.h"

#include <QLocale>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace tactiscope::ui {

namespace {

// Fixed decimals read well from 10⁻⁴ ("0.000123") up to 10⁹; outside that
// a reader counts zeros, so the power of ten is written out.
constexpr double kSmallestFixed = 1e-4;
constexpr double kLargestFixed = 1e9;

QString superscript(int exponent)
{
    static const std::array<QChar, 10> digits = {u'⁰', u'¹', u'²', u'³', u'⁴', u'⁵', u'⁶', u'⁷', u'⁸', u'⁹'};
    QString text = exponent < 0 ? QString(u'⁻') : QString();
    for (const QChar c : QString::number(std::abs(exponent))) text += digits[static_cast<std::size_t>(c.digitValue())];
    return text;
}

int exponentOf(double value)
{
    return static_cast<int>(std::floor(std::log10(std::abs(value))));
}

}  // namespace

QString fixedText(double value, int decimals)
{
    // "-0.000": a tiny negative rounded away; the sign would claim what the digits do not.
    if (std::abs(value) * std::pow(10.0, decimals) < 0.5) value = 0.0;
    return QLocale().toString(value, 'f', decimals);
}

int decimalsForMagnitude(double magnitude, int significant)
{
    if (!(std::abs(magnitude) > 0.0) || !std::isfinite(magnitude)) return std::max(0, significant - 1);
    return std::clamp(significant - 1 - exponentOf(magnitude), 0, 9);
}

QString significantText(double value, int significant)
{
    if (!std::isfinite(value)) return QLocale().toString(value);
    const double size = std::abs(value);
    if (size == 0.0 || (size >= kSmallestFixed && size < kLargestFixed))
        return fixedText(value, decimalsForMagnitude(value, significant));
    int exponent = exponentOf(value);
    double mantissa = value / std::pow(10.0, exponent);
    // 9.9996 to four digits is 10.00: carry into the exponent.
    if (std::abs(std::round(mantissa * std::pow(10.0, significant - 1))) >= std::pow(10.0, significant)) {
        mantissa /= 10.0;
        ++exponent;
    }
    return QStringLiteral("%1 × 10%2").arg(fixedText(mantissa, std::max(0, significant - 1)), superscript(exponent));
}

QString compactText(double value, int significant)
{
    QString text = significantText(value, significant);
    const QLocale locale;
    if (text.contains(u'×') || !text.contains(locale.decimalPoint())) return text;
    while (text.endsWith(locale.zeroDigit())) text.chop(1);
    if (text.endsWith(locale.decimalPoint())) text.chop(locale.decimalPoint().size());
    return text;
}

QString siText(double value_si, const QString& unit, int significant)
{
    static const std::array<QString, 8> prefixes = {QStringLiteral("p"), QStringLiteral("n"), QStringLiteral("µ"),
                                                    QStringLiteral("m"), QString(),           QStringLiteral("k"),
                                                    QStringLiteral("M"), QStringLiteral("G")};
    constexpr int kUnprefixed = 4;  // index of the bare unit
    if (value_si == 0.0 || !std::isfinite(value_si)) return significantText(value_si, significant) + u' ' + unit;
    int index = std::clamp(static_cast<int>(std::floor(exponentOf(value_si) / 3.0)) + kUnprefixed, 0,
                           static_cast<int>(prefixes.size()) - 1);
    double scaled = value_si / std::pow(1000.0, index - kUnprefixed);
    // 999.96 µN to three digits would read "1000 µN": say 1.00 mN.
    const int decimals = decimalsForMagnitude(scaled, significant);
    if (std::abs(std::round(scaled * std::pow(10.0, decimals))) >= 1000.0 * std::pow(10.0, decimals) &&
        index + 1 < static_cast<int>(prefixes.size())) {
        ++index;
        scaled = std::round(scaled * std::pow(10.0, decimals)) / std::pow(10.0, decimals) / 1000.0;
    }
    return significantText(scaled, significant) + u' ' + prefixes[static_cast<std::size_t>(index)] + unit;
}

QString withUnit(const QString& value, const QString& unit)
{
    return unit.isEmpty() ? value : value + QStringLiteral(" ") + unit;
}

QString typedText(double value)
{
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    const double size = std::abs(value);
    if (size == 0.0 || !std::isfinite(value) || size < kSmallestFixed || size >= kLargestFixed)
        return locale.toString(value, 'g', QLocale::FloatingPointShortest);
    // Ten significant digits hide binary noise (0.1 + 0.2) and keep what anyone types.
    QString text = locale.toString(value, 'f', decimalsForMagnitude(value, 10));
    if (text.contains(locale.decimalPoint())) {
        while (text.endsWith(locale.zeroDigit())) text.chop(1);
        if (text.endsWith(locale.decimalPoint())) text.chop(locale.decimalPoint().size());
    }
    return text;
}

int decimalsFor(double standardError)
{
    return core::text::uncertaintyDecimals(standardError, 6);
}

std::pair<QString, QString> valueAndErrorTexts(double value, double standardError)
{
    const int decimals = decimalsFor(standardError);
    return {fixedText(value, decimals), fixedText(standardError, decimals)};
}

QString valueWithErrorText(double value, double standardError)
{
    const auto [v, e] = valueAndErrorTexts(value, standardError);
    return v + QStringLiteral(" ± ") + e;
}

int sharedDecimals(const std::vector<double>& standardErrors, int fallback)
{
    std::optional<int> coarsest;
    for (const double error : standardErrors)
        if (std::isfinite(error) && error > 0.0) coarsest = std::min(coarsest.value_or(9), decimalsFor(error));
    return coarsest.value_or(fallback);
}

QString rangeText(double low, double high, int decimals)
{
    const QString from = fixedText(low, decimals);
    const QString to = fixedText(high, decimals);
    return from == to ? from : from + QStringLiteral(" – ") + to;
}

QString countText(long long n, const QString& one, const QString& many)
{
    return QLocale().toString(n) + u' ' + (n == 1 ? one : many);
}

}  // namespace tactiscope::ui
