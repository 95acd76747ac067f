// NumberRange's words.
#include "core/NumberRanges.h"

#include "core/text/NumberFormat.h"

namespace tactiscope::core {

std::string NumberRange::text() const
{
    std::string said = "from " + text::formatShortest(least) + " to " + text::formatShortest(most);
    if (*unit) said += std::string(" ") + unit;
    return said;
}

}  // namespace tactiscope::core
