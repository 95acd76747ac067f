// A channel's signal health in words, as the report's "Signal quality"
// table and the live Signal health panel both show it: the mains hum's
// amplitude and frequency, the noise floor per √Hz, the drift per hour
// with its ± and the clipped samples (and a beam's creep), each in the unit the channel is
// read in (µε, pF, mN), so the two never disagree on how a figure reads.
#pragma once

#include "core/report/SignalQuality.h"

#include <QStringList>

namespace tactiscope::ui {

// The column titles after the channel's: hum, noise floor, drift, clipped.
QStringList healthHeaders();
// The cells under them for one channel.
QStringList healthCells(const core::report::ChannelQuality& quality);
// A capacitive beam's creep after its load steps, or why there is none.
QString healthCreepText(const std::optional<core::dsp::StepCreep>& creep);

}  // namespace tactiscope::ui
