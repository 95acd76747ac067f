// `sessions export --math`: math channels added to a session's CSV export
// over its channels as the recording showed them: a channel it filtered is
// read filtered, as its own math channels read it live. In a session of
// several devices each is over one device's part, given as
// DEVICE/NAME[UNIT]=EXPR (the devices' clocks differ).
#pragma once

#include "core/storage/SessionExport.h"
#include "core/storage/SessionSource.h"

#include <QString>
#include <QStringList>

#include <cstdint>
#include <memory>
#include <optional>

namespace tactiscope::cli {

// Adds the math of `definitions` after `computed` (a session of one
// device) or after each part's `partColumns` (of several). The reason, for
// definitions that cannot be; nothing is changed then.
std::optional<QString> addExportMath(core::storage::SessionSource& store, std::int64_t session,
                                     const QStringList& definitions,
                                     std::unique_ptr<core::storage::ComputedColumns>& computed,
                                     core::storage::PartColumns& partColumns);

}  // namespace tactiscope::cli
