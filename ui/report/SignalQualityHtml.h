// The report's "Signal quality" section (issue 57): a row per channel with
// its mains hum, noise floor, drift per hour with its ±, and clipped
// samples, each in the unit the channel is read in (µε, pF, mN, mm); the
// filters and math channels the session was recorded with; and for a
// capacitive beam the detection limit from the noise floor beside the
// calibration's.
#pragma once

#include "core/report/SignalQuality.h"

#include <QString>

namespace tactiscope::ui {

QString signalQualitySection(const core::report::SignalQuality& quality);

}  // namespace tactiscope::ui
