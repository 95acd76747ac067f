// How a channel's SI values are shown to a person: strain in µε, capacitance
// in pF, position in mm. The core stores SI; this is the UI edge where the
// conversion happens.
#pragma once

#include "core/ChannelDescriptor.h"

#include <QString>

namespace tactiscope::ui {

struct DisplayUnit {
    double scale = 1.0;  // displayed value = SI value × scale
    QString symbol;      // unit symbol shown on axes and readouts
    QString quantity;    // "Strain", "Capacitance", ...

    // Axis title such as "Strain (µε)".
    QString axisTitle() const;
    friend bool operator==(const DisplayUnit&, const DisplayUnit&) = default;
};

DisplayUnit displayUnitFor(const core::ChannelDescriptor& channel);

}  // namespace tactiscope::ui
