// The general mode: any device, any channels, stored, reviewed and
// exported as they came, with no analysis and no zero.
#include "core/modes/ModeDefinition.h"

namespace tactiscope::core {

const ModeDefinition& generalMode()
{
    static const ModeDefinition definition{
        .mode = Mode::General,
        .name = "general",
        .title = "General recording",
        .needs = "any channels",
        .roles = {},
        .profile = ProfileType::None,
        .detectsDefects = false,
        .readings = std::nullopt,
        .noZero = "general recording has no zero to take: it stores the channels as they come",
        .lanes = nullptr,
        .computedColumns = nullptr,
    };
    return definition;
}

}  // namespace tactiscope::core
