// Display scaling per channel kind.
#include "ui/DisplayUnits.h"

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

}  // namespace tactiscope::ui
