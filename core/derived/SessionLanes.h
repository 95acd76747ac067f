// Which lanes a session is plotted in, for the review window and the
// report alike: a mode's physical quantities by default, as its definition
// makes them (core/modes: e.g. palpation's F_H, F_L, Q and k_o before the
// stored channels the forces did not come from; a panel scan's best R and
// decision after the strains), or every stored channel as it is (`raw`,
// and the general mode). A session of several devices has each part's, by
// its own mode, named DEVICE/NAME and placed by its device's clock.
#pragma once

#include "core/Vocabulary.h"
#include "core/calibration/CalibrationRecord.h"
#include "core/derived/ModeLanes.h"
#include "core/signal/ReviewFilterLane.h"
#include "core/storage/SessionExport.h"
#include "core/storage/SessionStore.h"
#include "core/storage/TraceWindow.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tactiscope::core::derived {

struct SessionLanes {
    std::vector<std::unique_ptr<storage::LaneSource>> lanes;
    // Each lane's mode, whose units it is shown in, and its device: the
    // session's mode and no device, or in a session of several devices its
    // part's mode and device (its name's DEVICE/).
    std::vector<Mode> modes;
    std::vector<std::string> devices;
    std::string basis;    // what the derived lanes were computed with; empty without them
    std::string problem;  // why a mode's quantities could not be derived, if so
    bool derived = false;
};

struct LaneOptions {
    bool raw = false;  // every stored channel as it is
    // A capacitive session read through another calibration record (a
    // re-analysis); none: the one recorded with it.
    std::optional<calibration::CalibrationRecord> capacitiveCalibration;
    // Filters set in review, each a lane of its own after the others
    // (core/signal/ReviewFilterLane.h); the stored samples are not changed.
    std::vector<signal::ReviewFilter> reviewFilters;
};

// Throws storage::StorageError when the store cannot be read.
SessionLanes sessionLanes(storage::SessionSource& store, const storage::SessionSummary& session,
                          const LaneOptions& options = {});

// The mode's physical quantities as export columns. Throws
// std::invalid_argument saying why a session has none (e.g. a palpation
// session without a profile).
std::unique_ptr<storage::ComputedColumns> computedColumns(storage::SessionSource& store,
                                                          const storage::SessionSummary& session);

}  // namespace tactiscope::core::derived
