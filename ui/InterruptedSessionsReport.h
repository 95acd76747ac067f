// After a crash or a power cut: the sessions the store found cut short
// (still marked "recording" with no recorder alive) are reported once, in a
// message that does not block, with what each kept and an offer to export
// them (CSV plus metadata) or to open them in the review view.
#pragma once

#include <QString>

#include <cstdint>
#include <functional>
#include <vector>

class QWidget;

namespace tactiscope::ui {

// Marks the store's crashed sessions interrupted and returns the ids of the
// interrupted sessions newer than `afterId`. Nothing when the store does not
// exist or cannot be opened (the recording path reports that).
std::vector<std::int64_t> interruptedSessionsAfter(const QString& storePath, std::int64_t afterId);

// Shows the report for `sessions` of the store, non-modal, owned by
// `parent`; its Review button calls `review` with them.
void showInterruptedSessionsReport(QWidget* parent, const QString& storePath, const std::vector<std::int64_t>& sessions,
                                   const std::function<void(const std::vector<std::int64_t>&)>& review);

}  // namespace tactiscope::ui
