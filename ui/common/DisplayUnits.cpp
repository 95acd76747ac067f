// Display scaling per channel kind.
#include "ui/common/DisplayUnits.h"

#include "ui/common/NumberText.h"

#include "ui/modes/ModeUi.h"

#include <algorithm>

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
    case ChannelKind::Decision:
        break;
    }
    return {1.0, QString::fromStdString(channel.unit), QStringLiteral("Value")};
}

DisplayUnit laneUnit(const core::ChannelDescriptor& lane, core::Mode mode)
{
    // The mode's derived quantities in its users' units (ui/modes/ModeUi.h).
    if (const auto derived = modeUi(mode).laneUnit)
        if (auto unit = derived(lane.name)) return *unit;
    DisplayUnit unit = displayUnitFor(lane);
    unit.quantity = QString::fromStdString(lane.name);
    return unit;
}

DisplayUnit watchedUnit(const std::vector<core::ChannelDescriptor>& watchable, const std::string& name, core::Mode mode)
{
    const auto found = std::ranges::find(watchable, name, &core::ChannelDescriptor::name);
    return found != watchable.end() ? laneUnit(*found, mode) : DisplayUnit();
}

QString watchedText(double si, const DisplayUnit& unit)
{
    const QString number = typedText(si * unit.scale);
    return unit.symbol.isEmpty() ? number : QStringLiteral("%1 %2").arg(number, unit.symbol);
}

QString laneLabel(const DisplayUnit& unit)
{
    return unit.symbol.isEmpty() ? unit.quantity : QStringLiteral("%1\n(%2)").arg(unit.quantity, unit.symbol);
}

}  // namespace tactiscope::ui
