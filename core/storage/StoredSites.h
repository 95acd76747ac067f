// A stored panel scan's defect sites: its defect events grouped as
// core/detector/DefectSites.h groups them, each crossing placed by the
// session's position channel when it recorded one (an encoder's channel
// with the role `position`, or of the kind position), by its phase in its
// stroke otherwise. The one way `sessions show`, the review and the
// report find a session's sites.
#pragma once

#include "core/detector/DefectSites.h"
#include "core/storage/SessionSource.h"

#include <optional>
#include <span>

namespace tactiscope::core::storage {

// The probe's place along the stroke at a time, read from the session's
// position channel around it (each call reads two samples); none for a
// session without one, or of several devices. Reads `store`, which must
// outlive it.
std::optional<detector::PositionAt> storedPositionAt(SessionSource& store, std::int64_t session);

// The sites of `defects`, stored defect events of `session`.
detector::SiteGrouping storedSites(SessionSource& store, std::int64_t session,
                                   std::span<const detector::DefectEvent> defects);

}  // namespace tactiscope::core::storage
