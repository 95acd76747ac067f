// Display scaling per channel kind.
#include "ui/DisplayUnits.h"

#include <QObject>

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

QString laneLabel(const DisplayUnit& unit)
{
    return unit.symbol.isEmpty() ? unit.quantity : QStringLiteral("%1\n(%2)").arg(unit.quantity, unit.symbol);
}

}  // namespace tactiscope::ui
