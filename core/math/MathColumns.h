// Math channels as columns of a session's CSV export (`sessions export
// --math`): each definition over the session's stored channels (and the
// mode's derived ones when those are exported too), in its declared unit,
// read in the export's windows.
#pragma once

#include "core/math/MathChannels.h"
#include "core/storage/SessionExport.h"

#include <map>
#include <memory>
#include <optional>
#include <string>

namespace tactiscope::core::math {

class MathColumns final : public storage::ComputedColumns {
public:
    // `derived` (may be null) is written first and its columns may be
    // named too. `readAs` maps a stored channel's name to a column of
    // `derived` read in its place (its filtered series, as the recording's
    // math channels read it). Throws MathError for a definition that
    // cannot be made.
    MathColumns(storage::SessionSource& store, std::int64_t session, std::vector<MathDefinition> definitions,
                std::unique_ptr<storage::ComputedColumns> derived = nullptr,
                const std::map<std::string, std::string>& readAs = {});

    std::vector<ChannelDescriptor> channels() const override;
    std::string basis() const override;
    std::vector<std::vector<double>> read(std::uint64_t first, std::uint64_t count) override;

private:
    storage::SessionSource& m_store;
    std::int64_t m_session;
    std::unique_ptr<storage::ComputedColumns> m_derived;
    std::size_t m_storedChannels = 0;
    // SI units per unit of each computed column (a recorded math channel in
    // µε: 1e-6), read once: the expressions read SI.
    std::vector<double> m_derivedToSi;
    // Per stored channel, the column of `derived` read in its place; none: itself.
    std::vector<std::optional<std::size_t>> m_readAs;
    std::unique_ptr<MathChannels> m_math;
};

}  // namespace tactiscope::core::math
