// Display scaling per channel kind.
#include "ui/DisplayUnits.h"

#include "core/text/UncertaintyFormat.h"

#include <QLocale>
#include <QObject>

#include <algorithm>
#include <cmath>

namespace tactiscope::ui {

QString DisplayUnit::axisTitle() const
{
    return symbol.isEmpty() ? quantity : QStringLiteral("%1 (%2)").arg(quantity, symbol);
}

DisplayUnit displayUnitFor(const core::ChannelDescriptor& channel)
{
    using core::ChannelKind;
    switch (channel.kind) {
    case ChannelKind::Strain:
        return {1e6, QStringLiteral("µε"), QStringLiteral("Strain")};
    case ChannelKind::Capacitance:
        return {1e12, QStringLiteral("pF"), QStringLiteral("Capacitance")};
    case ChannelKind::Force:
        return {1e3, QStringLiteral("mN"), QStringLiteral("Force")};
    case ChannelKind::Position:
        return {1e3, QStringLiteral("mm"), QStringLiteral("Position")};
    case ChannelKind::Other:
        break;
    }
    return {1.0, QString::fromStdString(channel.unit), QStringLiteral("Value")};
}

DisplayUnit laneUnit(const core::ChannelDescriptor& lane, core::Mode mode)
{
    struct Derived {
        core::Mode mode;
        const char* name;
        DisplayUnit unit;
    };
    using core::Mode;
    static const Derived derived[] = {
        {Mode::Palpation, "force_high", {1e3, QStringLiteral("mN"), QObject::tr("F stiff")}},
        {Mode::Palpation, "force_low", {1e3, QStringLiteral("mN"), QObject::tr("F soft")}},
        {Mode::Palpation, "Q", {1.0, {}, QObject::tr("Q")}},
        {Mode::Palpation, "stiffness", {1.0, QStringLiteral("N/m"), QObject::tr("kₒ")}},
        {Mode::Capacitive, "delta_c", {1e12, QStringLiteral("pF"), QObject::tr("ΔC")}},
        {Mode::Capacitive, "relative_change", {1e2, QStringLiteral("%"), QObject::tr("ΔC/C₀")}},
        {Mode::Capacitive, "force", {1e6, QStringLiteral("µN"), QObject::tr("Force")}},
        {Mode::Capacitive, "deflection", {1e3, QStringLiteral("mm"), QObject::tr("Deflection")}},
        {Mode::PanelScan, "best_r", {1.0, {}, QObject::tr("Best R")}},
        {Mode::PanelScan,
         "decision",
         {1.0,
          {},
          QObject::tr("Decision"),
          {{-1.0, QObject::tr("B→A")}, {0.0, QObject::tr("none")}, {1.0, QObject::tr("A→B")}}}},
    };
    for (const Derived& d : derived)
        if (d.mode == mode && lane.name == d.name) return d.unit;
    DisplayUnit unit = displayUnitFor(lane);
    unit.quantity = QString::fromStdString(lane.name);
    return unit;
}

QString fixedText(double value, int decimals)
{
    // "-0.000": a tiny negative rounded away; the sign would claim what the digits do not.
    if (std::abs(value) * std::pow(10.0, decimals) < 0.5) value = 0.0;
    return QLocale().toString(value, 'f', decimals);
}

int decimalsForMagnitude(double magnitude, int significant)
{
    if (!(std::abs(magnitude) > 0.0) || !std::isfinite(magnitude)) return std::max(0, significant - 1);
    return std::clamp(significant - 1 - static_cast<int>(std::floor(std::log10(std::abs(magnitude)))), 0, 9);
}

int decimalsFor(double standardError)
{
    return core::text::uncertaintyDecimals(standardError, 6);
}

std::pair<QString, QString> valueAndErrorTexts(double value, double standardError)
{
    const int decimals = decimalsFor(standardError);
    const QLocale locale;
    return {fixedText(value, decimals), fixedText(standardError, decimals)};
}

QString laneLabel(const DisplayUnit& unit)
{
    return unit.symbol.isEmpty() ? unit.quantity : QStringLiteral("%1\n(%2)").arg(unit.quantity, unit.symbol);
}

}  // namespace tactiscope::ui
