// After a crash or a power cut: the sessions the store found cut short
// (still marked "recording" with no recorder alive) are reported once, in a
// message that does not block, with what each kept and an offer to export
// them (CSV plus metadata) or to open them in the review view.
#pragma once

#include "core/storage/SessionStore.h"

#include <QString>

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

class QWidget;

namespace tactiscope::core::storage {
class StoreWorker;
}

namespace tactiscope::ui {

// The interrupted sessions newer than `afterId`, oldest first: a job for the
// store's worker, whose read-write open has marked crashed recordings
// interrupted.
std::vector<core::storage::SessionSummary> interruptedSessionsAfter(core::storage::SessionSource& store,
                                                                    std::int64_t afterId);

// Shows the report for `sessions`, non-modal, owned by `parent`; its Review
// button calls `review` with them, its export runs on `store`'s worker.
void showInterruptedSessionsReport(QWidget* parent, std::shared_ptr<core::storage::StoreWorker> store,
                                   const std::vector<core::storage::SessionSummary>& sessions,
                                   const std::function<void(const std::vector<std::int64_t>&)>& review);

}  // namespace tactiscope::ui
