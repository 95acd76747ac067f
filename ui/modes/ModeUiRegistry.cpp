// ModeUiRegistry: the one list of the modes' ui entries.
#include "ui/modes/ModeUi.h"

#include <map>

namespace tactiscope::ui {
namespace {

std::map<core::Mode, ModeUi>& entries()
{
    static std::map<core::Mode, ModeUi> modes{
        {core::Mode::PanelScan, panelScanUi()},
        {core::Mode::Palpation, palpationUi()},
        {core::Mode::Capacitive, capacitiveUi()},
    };
    return modes;
}

}  // namespace

const ModeUi& modeUi(core::Mode mode)
{
    auto& known = entries();
    const auto found = known.find(mode);
    if (found != known.end()) return found->second;
    // A mode with no parts of its own: an entry that says so, kept for the next ask.
    return known.emplace(mode, ModeUi{mode}).first->second;
}

void registerModeUi(const ModeUi& entry)
{
    entries().insert_or_assign(entry.mode, entry);
}

void unregisterModeUi(core::Mode mode)
{
    entries().erase(mode);
}

}  // namespace tactiscope::ui
