// The review window's account of a capacitive session (seed 002): the
// calibration its force and deflection are read through (C0, sensitivity,
// who calibrated when), and the choice of another record of the same beam
// from the store to read the session through instead: a re-analysis that
// redraws the plot and leaves what was recorded as it was.
#pragma once

#include "core/calibration/CalibrationRecord.h"
#include "ui/review/ReviewAccount.h"

#include <optional>
#include <vector>

class QLabel;

namespace tactiscope::ui {

class CapacitiveBasisBox : public ReviewAccount {
    Q_OBJECT

public:
    CapacitiveBasisBox(const ReviewAccountContext& context, QWidget* parent);

    // Reads the session through `record`, or (none) the recorded one;
    // returns an error, or empty (and the basis shown is the new one).
    QString readThrough(const std::optional<core::calibration::CalibrationRecord>& record);

private:
    core::storage::SessionSource& m_store;
    const core::storage::SessionSummary& m_session;
    std::function<QString(const std::function<void(core::derived::LaneOptions&)>&)> m_changeLanes;
    QLabel* m_basis = nullptr;
    std::vector<core::calibration::CalibrationRecord> m_records;  // the choices after "as recorded"
};

}  // namespace tactiscope::ui
