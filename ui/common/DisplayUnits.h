// How a channel's SI values are shown to a person: strain in µε, capacitance
// in pF, position in mm. The core stores SI; this is the UI edge where the
// conversion happens.
#pragma once

#include "core/ChannelDescriptor.h"
#include "core/Vocabulary.h"

#include <QString>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tactiscope::ui {

struct DisplayUnit {
    DisplayUnit() = default;
    DisplayUnit(double scale_, QString symbol_, QString quantity_, std::vector<std::pair<double, QString>> levels_ = {})
        : scale(scale_),
          symbol(std::move(symbol_)),
          quantity(std::move(quantity_)),
          levels(std::move(levels_))
    {
    }

    double scale = 1.0;  // displayed value = SI value × scale
    QString symbol;      // unit symbol shown on axes and readouts
    QString quantity;    // "Strain", "Capacitance", ...
    // A quantity that takes a few values only (the detector's decision):
    // each value's name, shown on its axis in place of numbers.
    std::vector<std::pair<double, QString>> levels;
    // A readout's decimals when fixed (a correlation's 3: "Best R 0.001",
    // not "0.0013789"); none: as many as its magnitude needs.
    std::optional<int> decimals;

    // Axis title such as "Strain (µε)".
    QString axisTitle() const;
    friend bool operator==(const DisplayUnit&, const DisplayUnit&) = default;
};

DisplayUnit displayUnitFor(const core::ChannelDescriptor& channel);

// How a lane of a session's review or report plot is titled and scaled:
// the mode's derived quantities (core/derived) by their names, in the
// units of their users — a palpation force in mN, a capacitive beam's in
// µN (its scale, seed 002), ΔC/C₀ in % — and a stored channel by its name,
// in its kind's unit. `quantity` is the lane's title: short, as a lane is
// low; the readout and the report name the quantity in full.
DisplayUnit laneUnit(const core::ChannelDescriptor& lane, core::Mode mode);
// What a trigger or limit watches (a device channel or a mode's quantity,
// among `watchable`) in its lane's unit; a name not there: SI as it is.
DisplayUnit watchedUnit(const std::vector<core::ChannelDescriptor>& watchable, const std::string& name,
                        core::Mode mode);
// A value in that unit: "597 µN", "20 µε", "0.3" (typed digits, no padding).
QString watchedText(double si, const DisplayUnit& unit);

// The colour a threshold line is drawn in on every plot (live, review,
// report): teal, apart from the red playhead and the events' colours.
inline constexpr unsigned kThresholdRgb = 0x00897b;

// The lane's axis label: the title over the unit, two short lines.
QString laneLabel(const DisplayUnit& unit);

}  // namespace tactiscope::ui
